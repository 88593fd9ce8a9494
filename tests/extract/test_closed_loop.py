"""Closed loop: scenarios run in the preview, recorded, extracted, and run again.

The extraction must show the same maneuvers per actor in the same order and the same waits
(condition kind and actors, before the same maneuver) as the original (`closedloop.signature`
says what a run shows), and its replay must stay within 1 m of the recording; a speed that
jumps (DriveDistance) is extracted at the actor kind's acceleration limit, which costs up to
(speed change)² / (8 × limit) while it ramps.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from conftest import EXAMPLES, REPO

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.extract import Extraction, extract
from sceml.extract.closedloop import allowed_error, recording_of, replays_closely, signature
from sceml.levels.apply import FlatTemplate
from sceml.levels.sampling import design, plan_for
from sceml.levels.space import parameter_space
from sceml.maps import RoadMap, load_map
from sceml.model.loading import load_scenario
from sceml.model.saving import save
from sceml.simulate import Run, simulate
from sceml.validation import validate

MAP_REFERENCE = "../maps/intersection.xodr"


@cache
def road_map() -> RoadMap:
    return load_map(REPO / "maps" / "intersection.xodr")


def original(path: Path) -> tuple[scm.Scenario, Run]:
    scenario = load_scenario(path).root
    return scenario, simulate(scenario, path, road_map=road_map())


def extracted(run: Run, *, noise: float = 0.0, every: int = 1, seed: int = 0) -> Extraction:
    recording = recording_of(run, noise=noise, every=every, seed=seed)
    return extract(recording, road_map(), map_reference=MAP_REFERENCE)


def assert_replays_closely(found: Extraction) -> None:
    assert found.replay is not None
    for fit in found.replay.actors:
        assert fit.largest < allowed_error(found, fit.name), (fit, found.notes)


@pytest.mark.parametrize("name", ["uis1-concrete.xmi", "uis2-concrete.xmi"])
def test_each_intersection_example_comes_back_with_its_maneuvers_and_waits(name: str) -> None:
    scenario, run = original(EXAMPLES / name)
    found = extracted(run)
    assert signature(found.scenario, found.replay.run) == signature(scenario, run)  # type: ignore[union-attr]
    assert_replays_closely(found)


def test_uis1_gives_back_the_trigger_radius_and_a_clean_scenario(tmp_path: Path) -> None:
    _, run = original(EXAMPLES / "uis1-concrete.xmi")
    found = extracted(run)
    (why,) = found.inferred
    assert (why.actor, why.explanation.kind, why.explanation.target) == (
        "bike",
        "InVehicleRadius",
        "ego",
    )
    assert why.explanation.parameters == {"radius": 12.0}  # examples/build_examples.py: 12 m
    (tmp_path / "maps").mkdir()
    (tmp_path / "maps" / "intersection.xodr").write_bytes(
        (REPO / "maps" / "intersection.xodr").read_bytes()
    )
    saved = save(found.scenario, tmp_path / "out" / "uis1.xmi")
    document = load_scenario(saved, allow=[tmp_path / "maps"])
    problems = [
        d for d in validate(document.root, document=document) if d.severity >= Severity.WARNING
    ]
    assert problems == [], [str(p) for p in problems]


def test_overtaking_comes_back_with_its_lane_changes() -> None:
    # Its waits are a time to collision and a time; a recording shows an approach instead, so
    # only the maneuvers are compared (docs/extract.md, "What a recording cannot tell").
    scenario, run = original(EXAMPLES / "overtaking-concrete.xmi")
    found = extracted(run)
    assert (
        signature(found.scenario, found.replay.run).maneuvers == signature(scenario, run).maneuvers
    )  # type: ignore[union-attr]
    assert_replays_closely(found)


def samples(name: str, n: int, seed: int) -> Iterator[tuple[int, scm.Scenario, Run]]:
    """Each sample with its run; the template is filled in place, so use one before the next."""
    path = EXAMPLES / name
    logical = load_scenario(path).root
    space = parameter_space(logical)
    template = FlatTemplate(logical, space.paths)
    for index, row in enumerate(design(space, plan_for(space, "random", n, seed))):
        scenario = template.fill(list(row))
        yield index, scenario, simulate(scenario, path, road_map=road_map())


@pytest.mark.parametrize(("name", "n"), [("uis1-logical.xmi", 16), ("uis2-logical.xmi", 8)])
def test_sampled_scenarios_come_back_with_their_maneuvers_and_waits(name: str, n: int) -> None:
    for index, scenario, run in samples(name, n, seed=7):
        expected = signature(scenario, run)
        found = extracted(run)
        assert signature(found.scenario, found.replay.run) == expected, index  # type: ignore[union-attr]
        assert_replays_closely(found)


def noisy_runs(run: Run, seeds: int) -> Iterator[Extraction]:
    """Extractions of a run recorded at 10 Hz with 0.1 m of Gaussian position noise."""
    for seed in range(seeds):
        yield extracted(run, noise=0.1, every=2, seed=seed)


def noisy_outcome(scenario: scm.Scenario, found: Extraction, run: Run) -> str:
    """What a noisy extraction came back as: "whole" (the same maneuvers and waits, and a
    replay within 1 m), else what went wrong first ("maneuvers", "waits", "replay").
    Speed changes below 1 m/s may be seen or missed by chance under noise: not compared."""
    expected = signature(scenario, run, min_change=1.0)
    shown = signature(found.scenario, found.replay.run, min_change=1.0)  # type: ignore[union-attr]
    if shown.maneuvers != expected.maneuvers:
        return "maneuvers"
    if shown != expected:
        return "waits"
    return "whole" if replays_closely(found) else "replay"


@pytest.mark.parametrize("name", ["uis1-concrete.xmi", "uis2-concrete.xmi"])
def test_noisy_recordings_of_the_intersection_examples_come_back_whole(name: str) -> None:
    # 8 fixed seeds, each asserted. The code before issue 30's noise round: UIS1 8 of 8,
    # UIS2 5 of 8 (seeds 3, 4 and 7 replayed 1.10, 1.05 and 1.57 m off).
    scenario, run = original(EXAMPLES / name)
    outcomes = [noisy_outcome(scenario, found, run) for found in noisy_runs(run, 8)]
    assert outcomes == ["whole"] * 8


#: The outcome of each of the first 12 samples of the logical scenarios (seed 7, as the
#: benchmark), each recorded at 10 Hz with 0.1 m of noise (seed: the sample's index).
#: Looked into by hand, before this round: UIS2's 5 and 10 were pedestrians whose short ramp
#: (0 to 1.9 m/s in 1 s), fitted along the smoothed path, came out gentler than walked, so
#: their crossing started a few tenths late (1.04 m); now it is fitted in the plane, the bend
#: pinning its end (`setoff`). Sample 10's crossing had also been ended 0.9 m short, at a
#: "bend" of the smoothing's last window. UIS2's 7 was the car, whose step follows the ego
#: reaching a place: the ego's start was put 0.25 m ahead (the filter's edge) and the car's
#: step fitted 0.04 s early, so it set off a step early (1.22 m); now the start is fitted by
#: the distance driven and the step in the plane.
NOISY_SAMPLES = {
    "uis1-logical.xmi": ["whole"] * 12,
    "uis2-logical.xmi": ["whole"] * 12,
}


@pytest.mark.parametrize("name", sorted(NOISY_SAMPLES))
def test_noisy_recordings_of_sampled_scenarios_come_back_as_each_did(name: str) -> None:
    # Two rounds ago (the same samples and seeds): UIS1 whole in 7 of 12 (samples 5 and 11
    # with a wait the scenario did not have, 0, 2 and 9 replayed 1.01-1.06 m off), UIS2 in 9
    # of 12 (samples 6, 7 and 10 replayed 1.10-1.31 m off); last round UIS1 12 and UIS2 9
    # (samples 5, 7 and 10 replayed 1.04-1.22 m off).
    outcomes = [
        noisy_outcome(scenario, extracted(run, noise=0.1, every=2, seed=index), run)
        for index, scenario, run in samples(name, 12, seed=7)
    ]
    assert outcomes == NOISY_SAMPLES[name]


def test_noisy_recordings_keep_the_maneuvers_of_overtaking() -> None:
    scenario, run = original(EXAMPLES / "overtaking-concrete.xmi")
    expected = signature(scenario, run, min_change=1.0).maneuvers
    same = [
        signature(found.scenario, found.replay.run, min_change=1.0).maneuvers == expected  # type: ignore[union-attr]
        for found in noisy_runs(run, 8)
    ]
    assert sum(same) >= 6, same


def benchmark_sample(name: str, index: int) -> tuple[scm.Scenario, Run]:
    """Sample `index` of the benchmark's 100 (benchmarks/extract_closed_loop.py, seed 7)."""
    path = EXAMPLES / name
    logical = load_scenario(path).root
    space = parameter_space(logical)
    row = design(space, plan_for(space, "random", 100, 7))[index]
    scenario = FlatTemplate(logical, space.paths).fill(list(row))
    return scenario, simulate(scenario, path, road_map=road_map())


def first_speed_change(found: Extraction, actor: str) -> tuple[str, float, float, float]:
    """The kind, start (s), speed before and target (m/s) of an actor's first speed change."""
    (extracted_actor,) = [a for a in found.actors if a.name == actor]
    event = next(e for e in extracted_actor.maneuvers if e.longitudinal)
    target = event.parameters.get("targetSpeed", event.parameters.get("speed"))
    return event.kind, event.start, event.from_speed or 0.0, float(str(target))


#: Each cause of a miss found this round (benchmark, 100 noisy samples each, sample index =
#: noise seed), with a sample it made miss: the scenario, the sample, and what went wrong.
#: Each now comes back whole; `test_each_cause_of_a_noisy_miss_is_gone` checks the cause too.
CAUSES = {
    # A change already under way at the start, 1.1 to 1.4 m/s over 0.55 to 0.7 s: within the
    # noise of a steady speed for the free fit (missed in 7 UIS2 and 2 UIS1 samples).
    "start change missed": ("uis2-logical.xmi", 62),
    "start change missed, UIS1": ("uis1-logical.xmi", 16),
    # A change from the start fitted late, the anchored fit's end held near the free fit's:
    # a timed wait the scenario did not have (2 UIS2, 2 UIS1), or the change found twice.
    "start change fitted late": ("uis2-logical.xmi", 42),
    "start change split in two": ("uis2-logical.xmi", 44),
    # A bike that set off with the recording: its first half window's distance, from the
    # extrapolated cubic, came out 0.5 m short; its set-off from 1.2 m/s at 0.8 s, a wait.
    "set-off at the start, from the edge's distance": ("uis1-logical.xmi", 72),
    # ... and the set-off anchored at the start from 0.3 m/s, replayed from 0 (1.08 m off).
    "set-off at the start, from a creep": ("uis1-logical.xmi", 9),
    # A bike that set off at once, with no sure heading before its crossing: missed (2.9 m).
    "crossing after a set-off at the start": ("uis1-logical.xmi", 81),
    # A crossing seen during the set-off (bike) or before a walker's step: crossed first.
    "crossing during the set-off": ("uis1-logical.xmi", 14),
    "crossing before a walker's step": ("uis2-logical.xmi", 56),
}


@pytest.mark.parametrize("cause", sorted(CAUSES))
def test_each_cause_of_a_noisy_miss_is_gone(cause: str) -> None:
    name, index = CAUSES[cause]
    scenario, run = benchmark_sample(name, index)
    found = extracted(run, noise=0.1, every=2, seed=index)
    assert noisy_outcome(scenario, found, run) == "whole", cause
    if cause.startswith("start change"):
        # The ego's first speed change starts with the recording, to the run's speed at 3 s
        # (after the change) within 0.2 m/s, from its speed at 0 s within 0.4 m/s: the noise
        # pins the change times its length, not each (sample 44: 6.36 for 6.0 m/s).
        kind, start, before, target = first_speed_change(found, "ego")
        ego = run.actor_index("ego")
        speeds = run.states[ego, :, 3]
        truth = (float(speeds[0]), float(np.interp(3.0, run.times, speeds)))
        assert (kind, start) == ("Accelerate", 0.0)
        assert before == pytest.approx(truth[0], abs=0.4)
        assert target == pytest.approx(truth[1], abs=0.2)
        assert sum(e.longitudinal and e.start < 1.0 for e in found.actors[0].maneuvers) == 1
    if cause.startswith("set-off at the start"):
        kind, start, before, _ = first_speed_change(found, "bike")
        assert (kind, start, before) == ("Accelerate", 0.0, 0.0)
    if cause.startswith("crossing"):
        actor = "bike" if name.startswith("uis1") else "pedestrian"
        (events,) = [a.maneuvers for a in found.actors if a.name == actor]
        assert [e.kind for e in events] == ["Accelerate", "Cross"]
        assert events[1].start >= events[0].end - 1e-9

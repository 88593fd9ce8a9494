"""The closed-loop check: a scenario run in the preview, recorded, extracted, and compared.

Two scenarios agree when their runs show the same things: per actor, the same maneuvers in the
same order, and before each, the same kind of condition about the same actors where the actor
had to wait. Only what a recording can show is compared:

- a speed change is Accelerate, Decelerate or Stop by what the speed did (an Accelerate to
  the speed the actor already has shows nothing; a DriveDistance from standing is a speed
  change); KeepVelocity shows nothing either;
- a condition counts only where it made its actor wait (it finished after it was activated):
  one that already held when activated leaves no trace in a recording.

tests/extract and benchmarks/extract_closed_loop.py use it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

import scemlmodel as scm

from ..graph import actors as scenario_actors
from ..modules import flatten
from ..params import concrete
from ..simulate import Run
from .events import LONGITUDINAL
from .pipeline import Extraction
from .recording import Recording, Track
from .thresholds import Thresholds

_SPEED_KINDS = LONGITUDINAL
_QUIET = ("KeepVelocity",)
_CONDITIONS = (
    "InVehicleRadius",
    "InLocationRadius",
    "SpeedCondition",
    "TimeElapsed",
    "TimeToCollision",
)


@dataclass(frozen=True)
class Signature:
    """What a run of a scenario shows: each actor's maneuvers in order, and the waits before
    them as (actor, maneuver index, condition kind, its reference actor, its target actor)."""

    maneuvers: dict[str, tuple[str, ...]]
    waits: frozenset[tuple[str, int, str, str, str | None]]


def recording_of(run: Run, *, noise: float = 0.0, every: int = 1, seed: int = 0) -> Recording:
    """A run as a recording: every `every`-th sample, positions with Gaussian noise (m, sd)."""
    rng = np.random.default_rng(seed)
    times = run.times[::every]
    tracks = []
    for index, info in enumerate(run.actors):
        states = run.states[index, ::every]
        x = states[:, 0] + rng.normal(0.0, noise, len(times)) if noise else states[:, 0]
        y = states[:, 1] + rng.normal(0.0, noise, len(times)) if noise else states[:, 1]
        tracks.append(Track(info.name, times, x, y, states[:, 2], kind=info.kind, ego=info.ego))
    return Recording(tuple(tracks), run.scenario, "preview run")


def signature(
    scenario: scm.Scenario,
    run: Run,
    thresholds: Thresholds | None = None,
    *,
    min_change: float | None = None,
) -> Signature:
    """What the run of `scenario` shows (module uses are flattened as the preview does).

    A speed change smaller than `min_change` (m/s; by default the extraction's threshold)
    shows nothing: a comparison under noise sets it higher, where changes near the threshold
    are seen or missed by chance.
    """
    thresholds = thresholds or Thresholds()
    if min_change is not None:
        thresholds = replace(thresholds, min_speed_change=min_change)
    flat = (
        flatten(scenario) if any(isinstance(n, scm.ModuleUse) for n in scenario.nodes) else scenario
    )
    by_name = {str(n.name): n for n in flat.nodes}
    maneuvers: dict[str, list[str]] = {str(a.name): [] for a in scenario_actors(flat)}
    waits: set[tuple[str, int, str, str, str | None]] = set()
    records = sorted(
        (r for r in run.timeline if r.started is not None and r.name in by_name),
        key=lambda r: (r.started, r.name),
    )
    for record in records:
        node = by_name[record.name]
        if not isinstance(node, scm.Maneuver) or node.referenceActor is None:
            continue
        actor = str(node.referenceActor.name)
        shown = _shown_kind(node, run, actor, float(record.started or 0.0), thresholds)
        if shown is None:
            continue
        index = len(maneuvers[actor])
        maneuvers[actor].append(shown)
        for condition in _waited_for(node, run):
            target = condition.targetActor
            waits.add(
                (
                    actor,
                    index,
                    "TimeElapsed"
                    if isinstance(condition, scm.KeepVelocity)
                    else condition.eClass.name,
                    str(condition.referenceActor.name),
                    str(target.name) if target is not None else None,
                )
            )
    return Signature({k: tuple(v) for k, v in maneuvers.items()}, frozenset(waits))


def _shown_kind(
    node: scm.Maneuver, run: Run, actor: str, started: float, thresholds: Thresholds
) -> str | None:
    kind = str(node.eClass.name)
    if kind in _QUIET:
        return None
    if kind == "LaneChange":
        side = str(node.direction.name) if node.direction is not None else "left"
        return f"LaneChange {side}"
    if kind not in _SPEED_KINDS:
        return kind
    index = run.actor_index(actor)
    # The sample before the start: a step change shows in the sample of the start itself.
    before = float(np.interp(started - run.step, run.times, run.states[index, :, 3]))
    target = (
        0.0
        if kind == "Stop"
        else concrete(node, "speed" if kind == "DriveDistance" else "targetSpeed")
    )
    if abs(target - before) < thresholds.min_speed_change:
        return None
    if target < thresholds.standing_speed:
        return "Stop"
    return "Accelerate" if target > before else "Decelerate"


def _waited_for(node: scm.GraphElement, run: Run) -> list[scm.ActionNode]:
    """The conditions (and timed waits) right before a node that made it wait."""
    found = []
    for flow in node.incoming:
        source = flow.source
        if isinstance(source, scm.JoiningPolicy):
            found += _waited_for(source, run)
            continue
        waited = isinstance(source, scm.KeepVelocity) or source.eClass.name in _CONDITIONS
        if not waited:
            continue
        try:
            record = run.node(str(source.name))
        except KeyError:
            continue
        started, finished = record.started, record.finished
        if started is not None and finished is not None and finished > started + run.step / 2:
            found.append(source)
    return found


def allowed_error(found: Extraction, actor: str, within: float = 1.0) -> float:
    """How far (m) the replay of `actor` may stray: `within`, or for a speed change of the
    actor that was recorded steeper than its kind allows and extracted at the limit (a stop
    that jumps to standing; a step up is a DriveDistance, which replays it as it was) the most
    a ramp at the limit with the same midpoint can differ from a jump, (speed change)² /
    (8 × limit), plus what one sample step of the jump's timing moves it (speed change ×
    step) and 0.2 m."""
    step = found.replay.run.step if found.replay is not None else 0.0
    bounds = [
        change**2 / (8 * float(str(e.parameters["rate"]))) + change * step + 0.2
        for a in found.actors
        if a.name == actor
        for e in a.maneuvers
        if e.limited
        for change in [
            abs(float(str(e.parameters.get("targetSpeed", 0.0))) - (e.from_speed or 0.0))
        ]
    ]
    return max([within, *bounds])


def replays_closely(found: Extraction, within: float = 1.0) -> bool:
    """Whether every actor's replay stays within its `allowed_error`."""
    assert found.replay is not None
    return all(f.largest < allowed_error(found, f.name, within) for f in found.replay.actors)

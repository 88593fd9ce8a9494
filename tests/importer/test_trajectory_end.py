"""An imported trajectory finishes when players end it (issue 24, `parking_demo`):
files/walk-to-end.xosc walks a walker at 2 m/s along 10.03 m of polyline and stops it when the
walk action ends.

Worked by hand: the walker moves 0.1 m a step (0.05 s) from t = 0. esmini ends a trajectory in
the step that leaves less than a step's travel of it: after step k, 10.03 - 0.1 k m are left,
under 0.1 m first at k = 100 (0.03 m), so the walk ends at 5.00 s and Halt starts in the next
step, 5.05 s (esmini 3.6: both, in the original and in this re-export). Finished within the
default 2 m instead, the walk ended at step 81 (1.93 m left), 4.05 s, and Halt came 19 steps
early, as `parking_demo`'s ManStopEvent came 13 steps early."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.simulate import simulate
from sceml.xosc import schema

FILE = Path(__file__).parent / "files" / "walk-to-end.xosc"


def test_the_walk_finishes_within_a_steps_travel() -> None:
    imported = import_file(FILE)
    walk = next(n for n in imported.scenario.nodes if n.name == "Walk")
    assert isinstance(walk, scm.FollowTrajectory)
    assert walk.tolerance.value == pytest.approx(0.1)  # 2 m/s x 0.05 s
    guessed = [e.message for e in imported.report.entries if e.section == "guessed"]
    assert any(m.startswith("Walk: finished within 0.1 m of the last point") for m in guessed)


def test_the_preview_stops_the_walker_when_the_player_does() -> None:
    scenario = import_file(FILE).scenario
    run = simulate(scenario, FILE)
    assert round(run.node("Halt").started / 0.05) == 101
    walk = next(n for n in scenario.nodes if n.name == "Walk")
    walk.tolerance.value = 2.0  # the default the import used to leave
    assert round(simulate(scenario, FILE).node("Halt").started / 0.05) == 82


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.3"))
def test_the_tolerance_goes_back_in_the_arrival(version: str, tmp_path: Path) -> None:
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version=version, source_path=FILE)
    assert schema.validate_file(exported, version) == []
    document = etree.parse(str(exported)).getroot()
    # Running or complete (two groups); ReachPosition where the version has it, else Distance.
    marker = document.find(".//Event[@name='Walk__arrived']/StartTrigger")
    assert marker is not None
    reach = [(t.get("tolerance"), None) for t in marker.iter("ReachPositionCondition")]
    near = [(t.get("value"), t.get("rule")) for t in marker.iter("DistanceCondition")]
    assert sorted(reach + near, key=str) in ([("0.1", None)] * 2, [("0.1", "lessThan")] * 2)
    again = import_file(exported, allow=[FILE.parent]).scenario
    walk = next(n for n in again.nodes if n.name == "Walk")
    assert walk.tolerance.value == pytest.approx(0.1)

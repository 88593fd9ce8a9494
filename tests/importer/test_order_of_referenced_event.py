"""An actor's maneuvers are kept one at a time in file order, also where a trigger names a
later event first (issue 24, `parking_demo`: Target5's unparking never started, waiting for
its slow-down). files/order-of-referenced-event.xosc: Blink's trigger names Cruise, so Cruise
is read before Leave; Leave (a lane change at 2 s) still comes first, and Cruise (the lane
change back) waits for it.

Worked by hand from the file: the car drives at 10 m/s from s = 50; Leave takes 40 m, 4 s
(the preview ends it a step later, at 6.05 s); the car is closer than 5 m to s = 120 in its
new lane once past s = 115, from 6.5 s on: first at 6.55 s."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.simulate import simulate
from sceml.xosc import schema

FILE = Path(__file__).parent / "files" / "order-of-referenced-event.xosc"


def sources(node: scm.GraphElement) -> list[str]:
    return sorted(str(flow.source.name) for flow in node.incoming)


def test_the_later_event_waits_for_the_earlier_one() -> None:
    nodes = {str(n.name): n for n in import_file(FILE).scenario.nodes}
    # Leave waits for its clock alone; Cruise for its condition and for Leave (one lateral
    # maneuver of an actor at a time), not the other way round.
    assert sources(nodes["Leave"]) == ["after_2s"]
    (join,) = nodes["Cruise"].incoming
    assert isinstance(join.source, scm.JoinAllFinished)
    assert sources(join.source) == ["Leave", "PastMark"]


def test_the_preview_leaves_then_comes_back() -> None:
    run = simulate(import_file(FILE).scenario, FILE)
    leave, mark, cruise = run.node("Leave"), run.node("PastMark"), run.node("Cruise")
    assert (leave.started, leave.finished) == pytest.approx((2.0, 6.05))
    assert mark.finished == pytest.approx(6.55)
    # PastMark is a marker event (Blink's wait needs it too): Cruise a step after it.
    assert cruise.started == pytest.approx(6.6)


def test_the_export_imports_back_as_the_same_scenario(
    tmp_path: Path, same: Callable[[scm.Scenario, scm.Scenario], None]
) -> None:
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version="1.2", source_path=FILE)
    assert schema.validate_file(exported, "1.2") == []
    first.nodes[0].environment = scm.Environment()  # the export's default environment
    same(first, import_file(exported, allow=[FILE.parent]).scenario)

"""An actor's maneuvers that may overlap interrupt each other (release 1.5), also where a
trigger names a later event first (issue 24, `parking_demo`: Target5's unparking never started
when it waited for its slow-down, made first). files/order-of-referenced-event.xosc: Blink's
trigger names Cruise, so Cruise is read before Leave; Leave (a lane change at 2 s) and Cruise
(the lane change back, on a position) each start on their own condition, as in the file.

Worked by hand from the file: the car drives at 10 m/s from s = 50; Leave takes 40 m, 4 s
(the preview ends it a step later, at 6.05 s); the car is closer than 5 m to s = 120 in its
new lane once past s = 115, from 6.5 s on: first at 6.55 s, when Cruise starts (esmini starts an
event in the step its condition holds)."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.simulate import simulate
from sceml.xosc import schema

from .conftest import readable_form

FILE = Path(__file__).parent / "files" / "order-of-referenced-event.xosc"


def sources(node: scm.GraphElement) -> list[str]:
    return sorted(str(flow.source.name) for flow in node.incoming)


def test_each_event_starts_on_its_own_condition_and_interrupts() -> None:
    nodes = {str(n.name): n for n in import_file(FILE).scenario.nodes}
    # Neither waits for the other: the flows do not order them, so either may end the other
    # (Maneuver.interrupts), as a player ends the running lateral action.
    assert sources(nodes["Leave"]) == ["after_2s"]
    assert sources(nodes["Cruise"]) == ["PastMark"]
    assert nodes["Leave"].interrupts and nodes["Cruise"].interrupts


def test_the_preview_leaves_then_comes_back() -> None:
    run = simulate(import_file(FILE).scenario, FILE)
    leave, mark, cruise = run.node("Leave"), run.node("PastMark"), run.node("Cruise")
    assert (leave.started, leave.finished) == pytest.approx((2.0, 6.05))
    assert mark.finished == pytest.approx(6.55)
    assert cruise.started == pytest.approx(6.55)


def test_the_export_imports_back_as_the_same_scenario(tmp_path: Path) -> None:
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version="1.2", source_path=FILE)
    assert schema.validate_file(exported, "1.2") == []
    first.nodes[0].environment = scm.Environment()  # the export's default environment
    again = import_file(exported, allow=[FILE.parent]).scenario
    # PastMark, which Cruise and Blink's delay both wait for, is written into each trigger and
    # read back as two conditions of the same content (a position condition holds for both at
    # once): the same nodes with the same waits, PastMark once more.
    assert set(readable_form(again)) == set(readable_form(first))
    kinds = [n.eClass.name for n in again.nodes]
    assert kinds.count("InLocationRadius") == 2

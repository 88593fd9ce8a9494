"""An event of controller changes only keeps its maximumExecutionCount (issue 24, `acc-toggle`:
"assign the ACC and activate it, up to 10,000 times"): each controller node repeats on the
event's trigger, as the event's actions do, since controller changes complete at once.

`files/controller-repeats.xosc` is written by hand; every expectation is read off it."""

from __future__ import annotations

import shutil
from pathlib import Path

from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc, export_to_file
from sceml.importer import import_file
from sceml.model import graph

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "controller-repeats.xosc"


def test_each_controller_change_of_the_event_repeats_as_often() -> None:
    imported = import_file(SOURCE)
    assert imported.report.section("not represented") == []
    changes = [n for n in imported.scenario.nodes if isinstance(n, scm.ControllerManeuver)]
    assert sorted((n.eClass.name, n.maxRuns) for n in changes) == [
        ("ActivateController", 5),
        ("AssignController", 5),
    ]
    # Both wait for the same rising clock, so they run together each time.
    (first,), (second,) = (graph.predecessors(n) for n in changes)
    assert first is second


def test_the_export_writes_each_with_the_events_count(tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    document = build_xosc(first, version="1.1", source_path=SOURCE).tree.getroot()
    counts = sorted(
        (e.find(".//ControllerAction/*").tag, e.get("maximumExecutionCount"))
        for e in document.iter("Event")
        if e.find(".//ControllerAction") is not None
    )
    assert counts == [("ActivateControllerAction", "5"), ("AssignControllerAction", "5")]
    exported = tmp_path / SOURCE.name
    export_to_file(first, exported, version="1.1", source_path=SOURCE)
    first.nodes[0].environment = scm.Environment()
    same(first, import_file(exported, allow=[FILES]).scenario)


def test_an_event_of_a_controller_change_and_a_maneuver_is_not_repeated(tmp_path: Path) -> None:
    # A speed change takes time; repeated apart from the assignment it would run out of step.
    document = etree.parse(str(SOURCE))
    activate = document.find(".//Action[@name='ActivateAcc']")
    activate.clear()
    activate.set("name", "SlowDown")
    activate.append(
        etree.fromstring(
            "<PrivateAction><LongitudinalAction><SpeedAction>"
            '<SpeedActionDynamics dynamicsShape="linear" value="1" dynamicsDimension="rate"/>'
            '<SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget>'
            "</SpeedAction></LongitudinalAction></PrivateAction>"
        )
    )
    changed = tmp_path / SOURCE.name
    document.write(str(changed))
    shutil.copy(FILES / "highway.xodr", tmp_path)
    imported = import_file(changed)
    assert all(getattr(n, "maxRuns", 1) == 1 for n in imported.scenario.nodes)
    assert any("may run 5 times" in e.message for e in imported.report.section("not represented"))

"""A StopTrigger's condition stops the re-export in the same step (issue 24, "same run"): it
is written back into the StopTrigger, not as a marker event whose completion the StopTrigger
would see a step later (`pedestrian_traj_synch` ended at 10.8 s instead of 10.7 s).

`files/stop-in-step.xosc` is written by hand; every expectation below is read off it (played
by hand in esmini 3.6: the original and the re-export stop at 10.45 s, the re-export with a
marker event at 10.50 s)."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.importer import import_file
from sceml.model import graph

SOURCE = Path(__file__).parent / "files" / "stop-in-step.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


@pytest.fixture(scope="module")
def exported(imported: scm.Scenario) -> etree._Element:
    return build_xosc(imported, version="1.1", source_path=SOURCE).tree.getroot()


def test_the_condition_stands_in_the_stop_trigger(exported: etree._Element) -> None:
    assert exported.find(".//Event[@name='Close']") is None
    stop = exported.find("Storyboard/StopTrigger")
    assert stop is not None
    reach = [c for c in stop.iter("Condition") if c.find(".//ReachPositionCondition") is not None]
    assert [c.get("name") for c in reach] == ["Close"]
    assert reach[0].get("conditionEdge") == "rising"
    position = reach[0].find(".//ReachPositionCondition/Position/LanePosition")
    assert position is not None and float(position.get("s")) == 150.0
    # Its group: the start (the root's finish, `>= 0`) and the condition; the other: 60 s.
    # No event's completion: the branch of Slow, which the import joins with Close, is left
    # out (the run has stopped by the time it could add anything).
    groups = sorted(
        sorted(
            (inner.tag, inner.get("rule"), inner.get("value"))
            for inner in group.iterfind("Condition/*/*")
            if inner.tag != "TriggeringEntities"
        )
        for group in stop.iterfind("ConditionGroup")
    )
    assert groups == [
        [("EntityCondition", None, None), ("SimulationTimeCondition", "greaterOrEqual", "0.0")],
        [("SimulationTimeCondition", "greaterThan", "60.0")],
    ]


def test_the_stop_survives_export_then_import(
    exported: etree._Element, tmp_path: Path, same
) -> None:
    path = tmp_path / "stop-in-step.xosc"
    path.write_bytes(etree.tostring(exported))
    (tmp_path / "highway.xodr").write_bytes((SOURCE.parent / "highway.xodr").read_bytes())
    first, again = import_file(SOURCE).scenario, import_file(path).scenario
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first, again):
        graph.root_node(scenario).environment = None
    same(first, again)

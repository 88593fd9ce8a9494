"""A repeated event keeps a condition node of its own (issue 24, `lane_change_simple`):
files/repeat-on-shared-condition.xosc starts Count (maximumExecutionCount 2) and Cruise on the
same rising-edge condition, and Cruise may overlap the Init speed change. One shared
condition node would become a marker event where Cruise needs a join (before release 1.5,
when it waited for the speed change), and Count, waiting for
that marker's lasting completion, would run both its runs at once (esmini 3.6 played the
re-export's Count at 9.30 s and 9.35 s; the original's once, at 9.25 s, as this re-export's).

Every expectation below is read off the file."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "repeat-on-shared-condition.xosc"


def sources(node: scm.GraphElement) -> list[scm.GraphElement]:
    return [flow.source for flow in node.incoming]


def test_the_repeated_event_has_a_condition_of_its_own() -> None:
    nodes = {str(n.name): n for n in import_file(SOURCE).scenario.nodes}
    count, cruise = nodes["Count"], nodes["Cruise"]
    assert (count.eClass.name, count.maxRuns) == ("SetParameter", 2)
    ((mark,),) = [sources(count)]
    assert isinstance(mark, scm.InLocationRadius) and mark.edge.name == "rising"
    assert [flow.target for flow in mark.outgoing] == [count]
    # Cruise has a copy of its own too. Since release 1.5 it no longer waits for the Init speed
    # change: the two may overlap, so each interrupts the other (Maneuver.interrupts), as a
    # player ends the running speed action; before, a join made Cruise's copy wait for it.
    ((other,),) = [sources(cruise)]
    assert isinstance(other, scm.InLocationRadius) and other is not mark
    assert [type(n) for n in sources(other)] == [scm.RootNode]
    assert cruise.interrupts and nodes["Init_Ego_speed"].interrupts


@pytest.mark.parametrize("version", ("1.1", "1.3"))
def test_the_repeated_event_is_written_with_its_condition(
    version: str, tmp_path: Path, same: Callable[[scm.Scenario, scm.Scenario], None]
) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / "passes.xosc"
    export_to_file(first, exported, version=version, source_path=SOURCE)
    assert schema.validate_file(exported, version) == []
    document = etree.parse(str(exported)).getroot()
    events = {str(e.get("name")): e for e in document.iter("Event")}
    assert "AtMark" not in events  # no marker event: its completion would last
    count = events["Count"]
    assert count.get("maximumExecutionCount") == "2"
    edges = [c.get("conditionEdge") for c in count.iterfind("StartTrigger//Condition")]
    assert edges.count("rising") == 1
    refs = list(count.iter("StoryboardElementStateCondition"))
    assert refs == []  # Count waits for its condition alone (and the start)
    first.nodes[0].environment = scm.Environment()  # the export's default environment
    same(first, import_file(exported, allow=[FILES]).scenario)

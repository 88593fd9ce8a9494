"""Repeated events through import and export (ActionNode.maxRuns): an event of one action
keeps its maximumExecutionCount as its node's maxRuns and is written back with it at every
version, XSD-valid; an event of two actions is reported, its nodes run once.

`files/repeats.xosc` is written by hand; every expectation below is read off it."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
REPEATS = FILES / "repeats.xosc"


def test_an_event_of_one_action_keeps_its_count_as_max_runs() -> None:
    imported = import_file(REPEATS)
    runs = {str(n.name): n.maxRuns for n in imported.scenario.nodes if hasattr(n, "maxRuns")}
    assert runs["Weave"] == 3
    # Pulse's two actions are two nodes: each runs once, and the count is reported.
    assert [runs[name] for name in sorted(runs) if name.startswith("Pulse")] == [1, 1]
    lost = [e.message for e in imported.report.section("not represented")]
    assert any("'Pulse' may run 2 times" in message for message in lost)
    mapped = [e.message for e in imported.report.section("mapped")]
    assert "Weave: maximumExecutionCount 3 -> maxRuns" in mapped


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_max_runs_is_written_as_the_events_count(version: str, tmp_path: Path, same) -> None:
    first = import_file(REPEATS)
    exported = tmp_path / "repeats.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=REPEATS)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    counts = {
        e.get("name"): e.get("maximumExecutionCount")
        for e in etree.parse(str(exported)).iter("Event")
    }
    assert counts["Weave"] == "3"
    assert {n for n, c in counts.items() if c != "1"} == {"Weave"}
    again = import_file(exported, allow=[FILES]).scenario
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)

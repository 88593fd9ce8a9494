"""Traffic signal states and conditions (no actor performs them) import as TrafficSignalState and
TrafficSignalCondition, the Init state too, export back at every version as the same elements
(XSD-valid) and import again to the same scenario; the preview says it has no signal model."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from sceml import graph, io, schema
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.simulate import simulate

SIGNALS = Path(__file__).parent / "files" / "traffic-signals.xosc"


def signal_elements(path: Path) -> list[tuple[str, str, str]]:
    """Each TrafficSignalStateAction and TrafficSignalCondition: (tag, name, state), sorted."""
    tags = ("TrafficSignalStateAction", "TrafficSignalCondition")
    return sorted(
        (str(e.tag), str(e.get("name")), str(e.get("state")))
        for e in etree.parse(str(path)).iter(*tags)
    )


def test_signal_states_and_conditions_import_as_global_nodes() -> None:
    imported = import_file(SIGNALS)
    assert imported.report.counts()["opaque"] == 0
    found = {
        n.name: (n.eClass.name, n.signalId, n.state, n.referenceActor)
        for n in imported.scenario.nodes
        if "Signal" in n.eClass.name
    }
    assert sorted(found.values()) == [
        ("TrafficSignalCondition", "1", "on;off;off", None),
        ("TrafficSignalState", "1", "off;off;on", None),
        ("TrafficSignalState", "1", "on;off;off", None),
    ]
    # The Init state is set at the start: a node right after the root.
    init = next(n for n in imported.scenario.nodes if n.name.startswith("Init_"))
    assert [p.eClass.name for p in graph.predecessors(init)] == ["RootNode"]


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_signal_nodes_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    model = tmp_path / "signals.xmi"
    import_to_file(SIGNALS, model)
    exported = tmp_path / "signals.xosc"
    export_to_file(io.load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    assert signal_elements(exported) == signal_elements(SIGNALS)
    first, again = import_file(SIGNALS), import_file(exported)
    assert again.report.counts()["opaque"] == 0
    for scenario in (first.scenario, again.scenario):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first.scenario, again.scenario)


def test_the_preview_says_it_has_no_signals() -> None:
    run = simulate(import_file(SIGNALS).scenario, SIGNALS)
    switch, red = run.node("SwitchToRed"), run.node("ShowsRed")
    # The wait of 2 s runs from 0.05 s (root) to 2.05 s; a wait is written into its
    # successor's trigger, so its flow costs no step more (players.flows).
    assert switch.finished == switch.started == 2.05
    assert "no traffic signals" in switch.note
    assert red.finished is None and "no traffic signals" in red.note

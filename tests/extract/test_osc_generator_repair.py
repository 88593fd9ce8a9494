"""The repair of OSC-Generator's output (benchmarks/osc_generator_repair.py) gives a file the
OpenSCENARIO 1.0 XSD accepts and that says what the original says: the same actors, start
positions, speeds, actions and start times. The original is OSC-Generator 0.2.0's output for
the preview's recording of examples/overtaking-concrete.xmi (benchmarks/extract_vs_osc_generator.py)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from conftest import REPO
from lxml import etree

from sceml.schema import validate_tree

ORIGINAL = Path(__file__).resolve().parent / "data" / "overtaking-osc-generator.xosc"


def _repair_module():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location(
        "osc_generator_repair", REPO / "benchmarks" / "osc_generator_repair.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_original_fails_the_xsd_and_the_repair_passes_it() -> None:
    original = etree.parse(str(ORIGINAL))
    assert validate_tree(original, "1.0")  # the pre-1.0 draft's names
    repaired = _repair_module().repair(original, 20.0)
    assert validate_tree(repaired, "1.0") == []


def test_the_repair_keeps_actors_positions_speeds_and_times() -> None:
    original = etree.parse(str(ORIGINAL))
    repaired = _repair_module().repair(original, 20.0)
    assert [o.get("name") for o in original.iter("Object")] == ["EGO", "Player1", "Player2"]
    assert [o.get("name") for o in repaired.iter("ScenarioObject")] == ["EGO", "Player1", "Player2"]
    worlds = [dict(w.attrib) for w in original.iter("World")]
    assert worlds == [dict(w.attrib) for w in repaired.iter("WorldPosition")]
    speeds = [(d.get("shape"), d.get("rate")) for d in original.iter("Dynamics") if d.get("rate")]
    assert len(speeds) == 20
    assert speeds == [
        (d.get("dynamicsShape"), d.get("value")) for d in repaired.iter("SpeedActionDynamics")
    ]
    targets = [a.get("value") for a in original.iter("Absolute")]
    assert targets == [a.get("value") for a in repaired.iter("AbsoluteTargetSpeed")]
    times = [t.get("value") for t in original.iter("SimulationTime")]
    # Every start time kept in order; the one condition added is the stop at the given end.
    assert [*times, "20"] == [t.get("value") for t in repaired.iter("SimulationTimeCondition")]
    change = next(repaired.iter("LaneChangeAction"))
    assert next(change.iter("RelativeTargetLane")).attrib == {"entityRef": "EGO", "value": "1"}
    assert next(change.iter("LaneChangeActionDynamics")).get("value") == "6.2"

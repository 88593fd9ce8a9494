"""The committed examples are exactly what the public-API script builds, and say what SPEC §9 says."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.model.graph import actors, predecessors, root_node
from sceml.model.loading import load

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def build_module():
    spec = importlib.util.spec_from_file_location("build_examples", EXAMPLES / "build_examples.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_committed_examples_equal_the_script_output(tmp_path: Path) -> None:
    written = build_module().build_all(tmp_path)
    assert len(written) == 10
    for path in written:
        relative = path.relative_to(tmp_path)
        assert path.read_bytes() == (EXAMPLES / relative).read_bytes(), f"{relative} is stale"


@pytest.mark.parametrize("level", ["functional", "logical", "concrete"])
def test_levels_are_declared(level: str) -> None:
    for name in ("uis1", "uis2", "overtaking"):
        root = root_node(load(EXAMPLES / f"{name}-{level}.xmi").root)
        assert root.level.name == level


def test_uis1_structure() -> None:
    scenario = load(EXAMPLES / "uis1-concrete.xmi").root
    assert [(a.name, a.eClass.name, a.isEgo) for a in actors(scenario)] == [
        ("ego", "Car", True),
        ("bike", "Bicycle", False),
    ]
    by_name = {node.name: node for node in scenario.nodes}
    # Sync 2: the ego comes close to the bike, which then starts.
    sync2 = by_name["InVehicleRadius_1"]
    assert (sync2.referenceActor.name, sync2.targetActor.name) == ("bike", "ego")
    assert predecessors(by_name["Accelerate_2"]) == [sync2]
    # Sync 1 and 3 both end at the end node, which joins all.
    end = by_name["End"]
    assert {n.name for n in predecessors(end)} == {"InLocationRadius_1", "InLocationRadius_2"}
    assert end.policy.name == "joinAll"


def test_uis2_uses_crossing_maneuver_with_pedestrian_and_car() -> None:
    scenario = load(EXAMPLES / "uis2-concrete.xmi").root
    assert {a.name: a.eClass.name for a in actors(scenario)} == {
        "ego": "Car",
        "car": "Car",
        "pedestrian": "Pedestrian",
    }
    use = next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse))
    assert use.definition.name == "CrossingManeuver"
    assert {b.role: b.actor.name for b in use.bindings} == {
        "crosser": "pedestrian",
        "trigger": "car",
    }
    by_name = {node.name: node for node in scenario.nodes}
    # Sync 2: the ego reaching the junction starts the car's DriveDistance.
    assert predecessors(by_name["DriveDistance_1"]) == [by_name["InLocationRadius_2"]]


def test_functional_examples_hold_no_parameters() -> None:
    scenario = load(EXAMPLES / "uis1-functional.xmi").root
    values = [o for o in scenario.eAllContents() if isinstance(o, scm.ParameterValue)]
    assert values == []


def test_logical_examples_hold_ranges_and_distributions() -> None:
    scenario = load(EXAMPLES / "uis2-logical.xmi").root
    kinds = {type(o).__name__ for o in scenario.eAllContents() if isinstance(o, scm.ParameterValue)}
    assert {"Range", "NormalDistribution", "UniformDistribution", "DiscreteDistribution"} <= kinds


def test_overtaking_uses_a_module_three_deep() -> None:
    scenario = load(EXAMPLES / "overtaking-concrete.xmi").root
    use = next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse))
    assert use.definition.name == "Overtaking"
    assert {b.role: b.actor.name for b in use.bindings} == {
        "overtaker": "ego",
        "overtaken": "truck",
        "oncoming": "oncoming",
    }
    chain = []
    definition = use.definition
    while definition is not None:
        chain.append(definition.name)
        inner = [n for n in definition.nodes if isinstance(n, scm.ModuleUse)]
        definition = inner[0].definition if inner else None
    assert chain == ["Overtaking", "PassVehicle", "ChangeLaneLeft"]


def test_overtaking_starts_on_the_lanes_of_one_straight_arm() -> None:
    # East arm, road 2: outbound lane -1 runs along s, inbound lane 1 is the oncoming lane.
    scenario = load(EXAMPLES / "overtaking-concrete.xmi").root
    starts = {
        a.name: (a.startPosition.roadId, a.startPosition.laneId, a.startPosition.s.value)
        for a in actors(scenario)
    }
    assert starts == {"ego": ("2", -1, 2.0), "truck": ("2", -1, 22.0), "oncoming": ("2", 1, 95.0)}

"""Refusals: wrong level, invalid model, inexpressible kinds and profile limits; nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.export import (
    ExportError,
    InvalidOutputError,
    export,
    export_to_file,
    unsupported_reason,
    writer,
)
from sceml.model.build import ScenarioBuilder, lane, world
from sceml.model.loading import load_scenario
from sceml.model.locating import uri_fragment

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def small(kind: str = "Accelerate", **parameters: object) -> scm.Scenario:
    """A concrete one-node scenario of the ego and a second car."""
    b = ScenarioBuilder("Small", map="map.xodr", level="concrete", date="2026-01-01T00:00:00")
    ego = b.actor("Car", "ego", ego=True, start=lane("3", 1, 30.0), speed=5.0)
    other = b.actor("Car", "other", start=lane("1", 1, 30.0), speed=5.0)
    needs_target = kind in ("Follow", "Approach", "InVehicleRadius", "TimeToCollision", "Overtake")
    node = b.add(kind, ego, target=other if needs_target else None, **parameters)
    b.chain(b.root, node, b.end)
    return b.scenario


def codes(error: ExportError) -> set[str]:
    return {diagnostic.code for diagnostic in error.diagnostics}


@pytest.mark.parametrize("level", ["functional", "logical"])
def test_functional_and_logical_examples_are_refused_naming_the_level(level: str) -> None:
    scenario = load_scenario(EXAMPLES / f"uis1-{level}.xmi").root
    with pytest.raises(ExportError, match=f"a {level} scenario cannot be exported") as caught:
        export(scenario)
    assert codes(caught.value) == {"SCEML-X001"}


def test_invalid_model_is_refused_with_validation_diagnostics() -> None:
    scenario = small("Accelerate", targetSpeed=8.0, rate=30.0)  # above any car's acceleration
    with pytest.raises(ExportError) as caught:
        export(scenario)
    assert any(code.startswith("SCEML-L") for code in codes(caught.value))


def test_a_refused_node_of_a_module_is_placed_at_the_use_in_the_input() -> None:
    document = load_scenario(EXAMPLES / "overtaking-concrete.xmi")
    plain, use = document.root.nodes[2], document.root.nodes[3]
    with pytest.raises(ExportError) as caught:
        export(document.root, version="1.0", profile="carla", town="Town03")
    placed = {d.path: d for d in caught.value.diagnostics}
    inner = placed["Overtaking_1.PassVehicle_1.ChangeLaneRight_1.TimeElapsed_1"]
    assert inner.code == "SCEML-E003"
    assert inner.element is use and inner.fragment == uri_fragment(use)
    assert placed["KeepVelocity_1"].element is plain
    assert placed["KeepVelocity_1"].fragment == uri_fragment(plain)


@pytest.mark.parametrize("kind", ["TimeElapsed", "KeepVelocity"])
def test_carla_refuses_delays_it_cannot_start_at_activation(kind: str) -> None:
    parameters = {"duration": 2.0}
    scenario = small(kind, **parameters)
    with pytest.raises(ExportError, match=f"{kind} is not supported by the carla") as caught:
        export(scenario, version="1.0", profile="carla", town="Town03")
    # The validation rule `sceml validate --profile carla` reports, placed at the node.
    assert codes(caught.value) == {"SCEML-E003"}
    assert "OpenSCENARIO 1.0 (carla profile)" in caught.value.diagnostics[0].message
    assert caught.value.diagnostics[0].path == f"{kind}_1"
    export(scenario, version="1.0")  # the generic profile can express it


@pytest.mark.parametrize("version", ["1.1", "1.2", "1.3"])
def test_carla_refuses_versions_other_than_1_0(version: str) -> None:
    with pytest.raises(ExportError, match="carla profile writes OpenSCENARIO 1.0 only"):
        export(small(targetSpeed=8.0), version=version, profile="carla", town="Town03")


def test_carla_takes_the_scenarios_own_map_or_a_town() -> None:
    # scenario_runner loads a LogicFile ending in .xodr as a standalone OpenDRIVE world.
    tree = export(small(targetSpeed=8.0), version="1.0", profile="carla")
    assert tree.find("RoadNetwork/LogicFile").get("filepath") == "map.xodr"
    tree = export(small(targetSpeed=8.0), version="1.0", profile="carla", town="Town03")
    assert tree.find("RoadNetwork/LogicFile").get("filepath") == "Town03"


def test_unknown_version_is_refused() -> None:
    with pytest.raises(ExportError, match="OpenSCENARIO 2.0 is not supported"):
        export(small(targetSpeed=8.0), version="2.0")


def test_missing_destination_is_refused_naming_the_node() -> None:
    scenario = small("TurnRight")
    with pytest.raises(ExportError, match="TurnRight_1.destination is missing") as caught:
        export(scenario, check_model=False)
    assert codes(caught.value) == {"SCEML-P002"}  # the validation rule, not a copy of it


def test_export_checks_are_the_registrys_rules() -> None:
    from sceml.export import checks
    from sceml.validation import REGISTRY

    rules = checks.export_rules().rules()
    # The rules registered with export=True: a reference actor, a target actor where one is
    # needed, a map, start positions, node kinds and settings the version can express, and
    # every value without a language default set.
    assert [rule.code for rule in rules] == [
        "SCEML-A001",
        "SCEML-A003",
        "SCEML-E001",
        "SCEML-E002",
        "SCEML-E003",
        "SCEML-E008",
        "SCEML-P002",
    ]
    assert all(rule is REGISTRY.rule(rule.code) for rule in rules)


def test_every_kind_maps_in_every_version_of_the_generic_profile() -> None:
    from sceml.model import catalog

    # Variables came with OpenSCENARIO 1.2; a LightStateAction the 1.2 schema accepts with 1.3;
    # TrailerAction with 1.3.
    since = {
        "VariableCondition": "1.2",
        "SetVariable": "1.2",
        "LightState": "1.3",
        "ConnectTrailer": "1.3",
        "DisconnectTrailer": "1.3",
    }
    for cls in catalog.action_node_kinds():
        for version in ("1.0", "1.1", "1.2", "1.3"):
            if (cls.__name__, version) == ("OverrideController", "1.0"):
                continue  # below
            reason = unsupported_reason(cls.__name__, version)
            first = since.get(cls.__name__, "1.0")
            if version < first:
                assert reason is not None and f"needs OpenSCENARIO {first}" in reason
            else:
                assert reason is None, (cls.__name__, version)
    # 1.0 allows an OverrideControllerValueAction only beside an assignment, all six inputs given.
    assert unsupported_reason("OverrideController", "1.0") == (
        "OverrideController needs OpenSCENARIO 1.1 or later"
    )
    assert unsupported_reason("Teleport", "1.3") == "Teleport has no OpenSCENARIO mapping"


def test_refused_export_keeps_the_existing_file(tmp_path: Path) -> None:
    target = tmp_path / "out.xosc"
    target.write_text("good", encoding="utf-8")
    logical = load_scenario(EXAMPLES / "uis2-logical.xmi").root
    with pytest.raises(ExportError):
        export_to_file(logical, target)
    assert target.read_text(encoding="utf-8") == "good"


def test_schema_invalid_output_is_an_internal_error_and_not_written(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = writer.render_tree

    def broken(view: object) -> object:
        tree = real(view)  # type: ignore[arg-type]
        tree.getroot().remove(tree.getroot().find("Storyboard"))  # required by every XSD
        return tree

    monkeypatch.setattr(writer, "render_tree", broken)
    target = tmp_path / "out.xosc"
    with pytest.raises(InvalidOutputError, match="fails its XSD"):
        export_to_file(small(targetSpeed=8.0), target)
    assert not target.exists()
    assert list(tmp_path.iterdir()) == []


def test_world_positions_and_every_maneuver_export(tmp_path: Path) -> None:
    b = ScenarioBuilder("All", map="map.xodr", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(1.75, -39.0, h=1.570796), speed=5.0)
    car = b.actor("Car", "car", start=lane("1", 1, 30.0))
    walker = b.actor("Pedestrian", "walker", start=world(-10.0, -4.5, h=1.570796))
    chain = [
        b.add("Follow", ego, target=car),
        b.add("Overtake", ego, target=car, speed=12.0),
        b.add("LaneChange", ego, direction="right"),
        b.add("FollowTrajectory", ego, waypoints=[world(30, -1.75), world(34, -1.75)]),
        b.add("Approach", ego, target=car),
        b.add("SpeedCondition", ego, speed=3.0, rule="lessThan"),
        b.add("TimeToCollision", ego, target=walker),
        b.add("Stop", ego),
    ]
    b.chain(b.root, *chain, b.end)
    for version in ("1.0", "1.3"):
        tree = export(b.scenario, version=version)
        names = [event.get("name") for event in tree.iter("Event")]
        assert "Overtake_1__back" in names and "Follow_1__gap_reached" in names


def test_controller_settings_a_version_cannot_say_are_refused_naming_the_holder() -> None:
    from sceml.model.build import activation, controller

    b = ScenarioBuilder("Ctl", map="map.xodr", level="concrete", date="2026-01-01T00:00:00")
    ego = b.actor(
        "Car",
        "ego",
        ego=True,
        start=lane("3", 1, 30.0),
        controller=controller("ALKS", "movement"),
        activation=activation(lighting=True),
    )
    assign = b.add(
        "AssignController",
        ego,
        name="takeOver",
        controller=controller("ACC"),
        activation=activation(longitudinal=True),
    )
    b.chain(b.root, assign, b.end)
    with pytest.raises(ExportError) as caught:
        export(b.scenario, version="1.1")
    refused = {(d.element.name, d.code) for d in caught.value.diagnostics}
    # controllerType and the lighting domain came with 1.2; an assignment that activates, 1.1.
    assert refused == {("ego", "SCEML-E008")}
    assert "controllerType needs OpenSCENARIO 1.2" in str(caught.value)
    with pytest.raises(ExportError) as caught:
        export(b.scenario, version="1.0")
    refused = {(d.element.name, d.code) for d in caught.value.diagnostics}
    assert refused == {("ego", "SCEML-E008"), ("takeOver", "SCEML-E008")}
    messages = " ".join(d.message for d in caught.value.diagnostics)
    assert "an assignment that also activates needs OpenSCENARIO 1.1" in messages
    ego.controller.controllerType = None
    ego.controllerActivation = None
    assert export(b.scenario, version="1.1") is not None


def test_the_kinds_support_lists_are_exactly_those_with_a_planner() -> None:
    # Validation reads MAPPED_KINDS without loading the exporter; the planners must agree.
    from sceml.export.actions import PLANNERS
    from sceml.xosc.support import MAPPED_KINDS

    assert set(PLANNERS) == MAPPED_KINDS

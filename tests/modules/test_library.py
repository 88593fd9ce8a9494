"""Listing, showing and instantiating the definitions of a module library."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.errors import BuildError
from sceml.model.build import ScenarioBuilder
from sceml.model.loading import load_library
from sceml.modules import UnknownModuleError, definition_named, instantiate, list_definitions, show

LIBRARY = Path(__file__).resolve().parents[2] / "examples" / "library" / "sceml-library.xmi"


def library() -> scm.Library:
    return load_library(LIBRARY).root


def test_list_gives_roles_parameters_and_size_of_every_definition() -> None:
    summaries = {s.name: s for s in list_definitions(library())}
    assert list(summaries) == [
        "CrossingManeuver",
        "ChangeLaneLeft",
        "ChangeLaneRight",
        "PassVehicle",
        "Overtaking",
    ]
    crossing = summaries["CrossingManeuver"]
    assert [(r.name, r.kinds) for r in crossing.roles] == [
        ("crosser", ["TwoWheeler", "Pedestrian"]),
        ("trigger", ["FourWheeler"]),
    ]
    assert [(p.name, p.unit, p.default) for p in crossing.parameters][:3] == [
        ("triggerRadius", "m", "10 m"),
        ("crossingSpeed", "m/s", "1.5 m/s"),
        ("destinationX", "m", None),
    ]
    sizes = {name: vars(s.size) for name, s in summaries.items()}
    assert sizes["CrossingManeuver"] == {
        "nodes": 4, "flows": 5, "uses": 0, "depth": 1, "problem": None
    }  # fmt: skip
    assert sizes["PassVehicle"] == {"nodes": 3, "flows": 4, "uses": 2, "depth": 2, "problem": None}
    assert sizes["Overtaking"] == {"nodes": 4, "flows": 6, "uses": 1, "depth": 3, "problem": None}


def test_show_lists_nodes_in_flow_order_with_roles_and_parameters() -> None:
    detail = show(library(), "CrossingManeuver")
    assert [n.name for n in detail.nodes] == [
        "In",
        "InVehicleRadius_1",
        "Accelerate_1",
        "Cross_1",
        "InLocationRadius_1",
        "Out",
    ]
    wait = detail.nodes[1]
    assert (wait.kind, wait.category, wait.actor, wait.target) == (
        "InVehicleRadius",
        "condition",
        "crosser",
        "trigger",
    )
    assert wait.parameters == {"radius": "$triggerRadius"}
    assert detail.nodes[3].parameters == {
        "destination": "WorldPosition(x=$destinationX, y=$destinationY, z=0 m, "
        "h=$destinationHeading)"
    }
    assert detail.flows[0] == ("In", "InVehicleRadius_1")
    assert len(detail.flows) == 5
    assert detail.uses == []


def test_show_reports_sub_module_uses_with_bindings_and_overrides() -> None:
    detail = show(library(), "PassVehicle")
    assert [(u.name, u.definition) for u in detail.uses] == [
        ("ChangeLaneLeft_1", "ChangeLaneLeft"),
        ("ChangeLaneRight_1", "ChangeLaneRight"),
    ]
    right = detail.uses[1]
    assert right.bindings == {"driver": "overtaker"}
    assert right.overrides == {"holdTime": "$passingTime"}
    assert right.file == str(LIBRARY)


def test_unknown_name_lists_the_names_and_exits_2() -> None:
    with pytest.raises(UnknownModuleError, match="no module 'Nope' .it has: CrossingManeuver, Ch"):
        definition_named(library(), "Nope")
    with pytest.raises(UnknownModuleError) as caught:
        show(library(), "Nope")
    assert caught.value.exit_code == 2
    assert caught.value.file == str(LIBRARY)


def test_instantiate_binds_roles_overrides_and_numbers_uses() -> None:
    crossing = definition_named(library(), "CrossingManeuver")
    b = ScenarioBuilder("S")
    walker, car = b.actor("Pedestrian", "walker"), b.actor("Car", "ego", ego=True)
    first = instantiate(
        b.scenario, crossing, {"crosser": walker, "trigger": car}, {"triggerRadius": 12}
    )
    second = instantiate(b.scenario, crossing, {"crosser": walker, "trigger": car})
    assert (first.name, second.name) == ("CrossingManeuver_1", "CrossingManeuver_2")
    assert {b.role: b.actor for b in first.bindings} == {"crosser": walker, "trigger": car}
    assert [(o.parameter, o.value.value) for o in first.overrides] == [("triggerRadius", 12.0)]
    assert first.definition is crossing


def test_instantiate_refuses_unknown_and_missing_names() -> None:
    crossing = definition_named(library(), "CrossingManeuver")
    b = ScenarioBuilder("S")
    walker = b.actor("Pedestrian", "walker")
    with pytest.raises(BuildError) as caught:
        instantiate(b.scenario, crossing, {"crosser": walker, "driver": walker}, {"speed": 1})
    assert str(caught.value) == (
        "cannot use module 'CrossingManeuver': unknown role 'driver'; "
        "role 'trigger' is not bound; unknown parameter 'speed'"
    )
    assert not any(isinstance(n, scm.ModuleUse) for n in b.scenario.nodes)

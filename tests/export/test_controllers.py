"""Controllers in every OpenSCENARIO version: the actor's controller as its ObjectController,
its start activation in Init, the controller nodes as one event each that is its own finish;
the version differences (1.0's unwrapped activation and released inputs, 1.2's controllerType)
as the XSD of each version wants them (the export checks every document against it)."""

from __future__ import annotations

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.build import ScenarioBuilder, activation, controller, lane, override
from sceml.export import export


def _scenario(*, overrides: bool = True, typed: bool = False) -> scm.Scenario:
    b = ScenarioBuilder("Ctl", map="map.xodr", level="concrete", date="2026-01-01T00:00:00")
    ego = b.actor(
        "Car",
        "ego",
        ego=True,
        start=lane("3", 1, 30.0),
        speed=5.0,
        controller=controller(
            "ACCController", "longitudinal" if typed else None, {"timeGap": "1.5"}
        ),
        activation=activation(longitudinal=True, lateral=False),
    )
    nodes = [
        b.add("ActivateController", ego, name="off", longitudinal=False),
        b.add("AssignController", ego, name="takeOver", controller=controller("ALKS")),
    ]
    if overrides:
        nodes.append(
            b.add(
                "OverrideController",
                ego,
                name="brake",
                overrides=[override("gear", 2), override("brake", 0.5)],
            )
        )
    b.chain(b.root, *nodes, b.end)
    return b.scenario


def _event_actions(tree: etree._ElementTree, name: str) -> etree._Element:
    (event,) = tree.getroot().iterfind(f".//Event[@name='{name}']")
    (private,) = event.iterfind("Action/PrivateAction")
    return private


@pytest.mark.parametrize("version", ["1.1", "1.2", "1.3"])
def test_controllers_from_1_1_are_wrapped_in_controller_actions(version: str) -> None:
    tree = export(_scenario(typed=version != "1.1"), version=version)
    (held,) = tree.getroot().iterfind(".//ScenarioObject[@name='ego']/ObjectController/Controller")
    assert held.get("name") == "ACCController"
    assert held.get("controllerType") == (None if version == "1.1" else "longitudinal")
    assert [(p.get("name"), p.get("value")) for p in held.iterfind("Properties/Property")] == [
        ("timeGap", "1.5")
    ]
    (init,) = tree.getroot().iterfind(".//Init//Private[@entityRef='ego']")
    (start,) = init.iterfind("PrivateAction/ControllerAction/ActivateControllerAction")
    assert dict(start.attrib) == {"lateral": "false", "longitudinal": "true"}
    off = _event_actions(tree, "off").find("ControllerAction/ActivateControllerAction")
    assert dict(off.attrib) == {"longitudinal": "false"}
    assign = _event_actions(tree, "takeOver").find("ControllerAction")
    assert [child.tag for child in assign] == ["AssignControllerAction"]
    assert assign.find("AssignControllerAction/Controller").get("name") == "ALKS"
    brake = _event_actions(tree, "brake").find("ControllerAction/OverrideControllerValueAction")
    # In the schema's order (Brake before Gear), whatever the model's order.
    assert [(c.tag, dict(c.attrib)) for c in brake] == [
        ("Brake", {"active": "true", "value": "0.5"}),
        ("Gear", {"active": "true", "number": "2.0"}),
    ]


def test_controller_nodes_finish_with_their_own_event() -> None:
    tree = export(_scenario(), version="1.3")
    (after,) = tree.getroot().iterfind(
        ".//Event[@name='takeOver']/StartTrigger//StoryboardElementStateCondition"
    )
    assert (after.get("storyboardElementRef"), after.get("state")) == ("off", "completeState")


def test_openscenario_1_0_activates_directly_and_releases_every_input_beside_an_assignment() -> (
    None
):
    tree = export(_scenario(overrides=False), version="1.0")
    (init,) = tree.getroot().iterfind(".//Init//Private[@entityRef='ego']")
    assert init.find("PrivateAction/ActivateControllerAction") is not None
    assert (
        _event_actions(tree, "off").find("ActivateControllerAction").get("longitudinal") == "false"
    )
    group = _event_actions(tree, "takeOver").find("ControllerAction")
    assert [c.tag for c in group] == ["AssignControllerAction", "OverrideControllerValueAction"]
    inputs = group.find("OverrideControllerValueAction")
    assert [c.tag for c in inputs] == [
        "Throttle",
        "Brake",
        "Clutch",
        "ParkingBrake",
        "SteeringWheel",
        "Gear",
    ]
    assert {c.get("active") for c in inputs} == {"false"}

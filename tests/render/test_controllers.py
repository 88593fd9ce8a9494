"""Controller changes are drawn in their own category colour with what they change: the
controller assigned (name, type, properties), the domains switched, the inputs overridden; the
root lists the controller each actor starts with."""

from __future__ import annotations

import scemlmodel as scm
from sceml.build import ScenarioBuilder, activation, controller, override, world
from sceml.render import diagram, to_bytes

from .svgtools import fills, groups, parse, text_of


def _scenario() -> scm.Scenario:
    b = ScenarioBuilder("Ctl", level="concrete")
    ego = b.actor(
        "Car", "ego", ego=True, start=world(0.0, 0.0), controller=controller("ACCController")
    )
    assign = b.add(
        "AssignController",
        ego,
        name="takeOver",
        controller=controller("ALKS", "movement", {"mode": "override"}),
        activation=activation(lateral=True, longitudinal=False),
    )
    brake = b.add(
        "OverrideController",
        ego,
        name="brake",
        overrides=[override("brake", 0.5), override("steeringWheel", 0.1, active=False)],
    )
    light = b.add("ActivateController", ego, name="lights", lighting=True)
    b.chain(b.root, assign, brake, light, b.end)
    return b.scenario


def _node_text(svg, title: str) -> str:
    """A node's label text with its spacing (indents are no-break spaces) made single."""
    (found,) = [g for g in groups(svg, "sceml-controller") if title in text_of(g)]
    return " ".join(text_of(found).split())


def test_controller_nodes_show_what_they_change_in_their_colour() -> None:
    svg = parse(to_bytes(diagram(_scenario()), "svg"))
    drawn = groups(svg, "sceml-controller")
    assert len(drawn) == 3
    assert all(fills(g) == {"#8e7cc3"} for g in drawn)
    assert "controller: ALKS (movement) mode = override" in _node_text(svg, "takeOver")
    assert "domains: lateral on, longitudinal off" in _node_text(svg, "takeOver")
    assert "brake = 0.5 steeringWheel released" in _node_text(svg, "OverrideController")
    assert "domains: lighting on" in _node_text(svg, "lights")


def test_the_root_names_each_actors_controller() -> None:
    svg = parse(to_bytes(diagram(_scenario()), "svg"))
    (root,) = groups(svg, "sceml-root")
    assert "ego: Car, ego, ACCController" in text_of(root)

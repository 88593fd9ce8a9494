"""Controllers in the editor: the palette offers the controller kinds in their own group and
look; their fields (domains, the assigned controller) and an actor's controller come from the
metamodel and are set like any field, with undo."""

from __future__ import annotations

from editor.helpers import actor_id, saved_bytes

import scemlmodel as scm
from sceml.editor import EditorSession


def _node(view: dict, identifier: str) -> dict:
    return next(n for n in view["nodes"] if n["id"] == identifier)


def _field(entry: dict, name: str) -> dict:
    return next(f for f in entry["fields"] if f["name"] == name)


def _model_node(session: EditorSession, name: str) -> scm.GraphElement:
    assert session.document is not None
    return next(n for n in session.document.root.nodes if n.name == name)


def test_the_palette_has_a_controller_group_with_its_look(uis1: EditorSession) -> None:
    view = uis1.view()
    (group,) = [g for g in view["palette"] if g["group"] == "controller"]
    assert [item["kind"] for item in group["items"]] == [
        "ActivateController",
        "AssignController",
        "OverrideController",
    ]
    assert group["label"] == "Controller changes"
    assert view["style"]["looks"]["controller"]["fill"] == "#8e7cc3"


def test_a_controller_node_is_added_and_its_fields_set(uis1: EditorSession) -> None:
    view = uis1.apply([{"op": "add_node", "kind": "AssignController", "actor": "ego"}])
    (made,) = view["created"]
    node = _node(view, made)
    assert node["look"] == "controller"
    # Unset domains are null, not false: unset leaves a domain as the player has it.
    assert _field(node, "activation.lateral") == {
        "name": "activation.lateral",
        "label": "Activation lateral",
        "type": "bool",
        "value": None,
    }
    assert _field(node, "controller.name")["value"] is None
    # Labelled apart from the node's own name.
    assert _field(node, "controller.name")["label"] == "Controller name"
    assert _field(node, "controller.controllerType")["label"] == "Controller type"
    before = saved_bytes(uis1)
    view = uis1.apply(
        [
            {"op": "set", "node": made, "field": "controller.name", "value": "ACCController"},
            {"op": "set", "node": made, "field": "activation.longitudinal", "value": True},
        ]
    )
    assign = _model_node(uis1, node["name"])
    assert assign.controller.name == "ACCController"
    assert (assign.activation.longitudinal, assign.activation.lateral) == (True, None)
    assert _field(_node(view, made), "controller.name")["value"] == "ACCController"
    uis1.undo()
    assert saved_bytes(uis1) == before


def test_an_actors_controller_is_set_and_removed_by_emptying_its_name(uis1: EditorSession) -> None:
    view = uis1.view()
    ego = actor_id(view, "ego")
    view = uis1.apply(
        [
            {"op": "set_actor", "actor": ego, "field": "controller.name", "value": "ALKS"},
            {
                "op": "set_actor",
                "actor": ego,
                "field": "controllerActivation.lateral",
                "value": True,
            },
        ]
    )
    entry = next(a for a in view["actors"] if a["id"] == ego)
    assert _field(entry, "controller.name")["value"] == "ALKS"
    assert _field(entry, "controllerActivation.lateral")["value"] is True
    actor = next(a for a in uis1.document.root.nodes[0].actors if a.name == "ego")
    assert actor.controller.name == "ALKS"
    uis1.apply([{"op": "set_actor", "actor": ego, "field": "controller.name", "value": ""}])
    assert actor.controller is None
    assert actor.controllerActivation.lateral is True

"""The global kinds in the editor: offered by the palette (SetParameter and SetVariable in their
own group, the conditions with the conditions), added without an actor, edited without one."""

from __future__ import annotations

from editor.helpers import node_id
from editor.test_operations import field, node, roundtrip

from sceml.editor import EditorSession
from sceml.editor.palette import node_groups


def test_the_palette_offers_the_global_kinds() -> None:
    groups = {group["group"]: [item["kind"] for item in group["items"]] for group in node_groups()}
    assert groups["global"] == ["SetParameter", "SetVariable", "TrafficSignalState"]
    conditions = {"ParameterCondition", "VariableCondition", "TrafficSignalCondition"}
    assert conditions <= set(groups["condition"])
    assert "LaneOffset" in groups["lateral"]


def test_a_global_node_is_added_and_edited_without_an_actor(uis1: EditorSession) -> None:
    view = roundtrip(uis1, [{"op": "add_node", "kind": "SetParameter", "actor": "ego"}])
    (made,) = (node(view, i) for i in view["created"])
    names = [f["name"] for f in made["fields"]]
    assert "referenceActor" not in names and "targetActor" not in names
    # How many times it runs (maxRuns) is the one field every action node has.
    assert names[1:] == ["parameter", "value", "modify", "maxRuns"]
    assert field(made, "modify") == {
        "name": "modify",
        "label": "Modify",
        "type": "enum",
        "options": ["set", "add", "multiply"],
        "value": "set",
    }
    setter = node_id(view, made["name"])
    after = roundtrip(
        uis1,
        [
            {"op": "set", "node": setter, "field": "parameter", "value": "Counter"},
            {"op": "set", "node": setter, "field": "modify", "value": "add"},
        ],
    )
    edited = node(after, setter)
    assert (field(edited, "parameter")["value"], field(edited, "modify")["value"]) == (
        "Counter",
        "add",
    )
    # A node nobody performs is no SCEML-A001 error; an actor's node without one is.
    unperformed = uis1.apply([{"op": "add_node", "kind": "Accelerate"}])
    accelerate = unperformed["created"][0]

    def codes(of: str) -> set[str]:
        return {d["code"] for d in unperformed["diagnostics"] if d["node"] == of}

    assert "SCEML-A001" in codes(accelerate)
    assert "SCEML-A001" not in codes(setter)

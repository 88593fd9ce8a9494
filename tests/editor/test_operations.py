"""Every operation of the protocol: what it changes, and that undo and redo give the same bytes."""

from __future__ import annotations

from typing import Any

import pytest
from editor.helpers import actor_id, node_id, saved_bytes

import scemlmodel as scm
from sceml.editor import EditorSession, OperationError


def roundtrip(session: EditorSession, ops: list[dict[str, Any]]) -> dict:
    """Apply ops; check undo gives the bytes before and redo the bytes after; the view after."""
    before, was_dirty = saved_bytes(session), session.stack.dirty
    answer = session.apply(ops)
    after = saved_bytes(session)
    assert after != before, "the operation changed nothing"
    assert session.undo()["dirty"] is was_dirty
    assert saved_bytes(session) == before
    redone = session.redo()
    assert saved_bytes(session) == after
    assert redone["dirty"] is True
    return answer


def node(view: dict, identifier: str) -> dict:
    return next(n for n in view["nodes"] if n["id"] == identifier)


def field(entry: dict, name: str) -> dict:
    return next(f for f in entry["fields"] if f["name"] == name)


def test_add_node_is_named_by_kind_and_placed(uis1: EditorSession) -> None:
    view = roundtrip(
        uis1,
        [
            {"op": "add_node", "kind": "Accelerate", "position": {"x": 5, "y": 6}, "actor": "ego"},
            {"op": "add_node", "kind": "JoinOneFinished"},
        ],
    )
    first, second = (node(view, i) for i in view["created"])
    assert first["name"] == "Accelerate_3"  # UIS1 has Accelerate_1 and _2
    assert first["position"] == {"x": 5.0, "y": 6.0}
    assert field(first, "referenceActor")["value"] == "ego"
    assert second["name"] == "JoinOneFinished_1" and second["look"] == "joinOne"


def test_add_node_refuses_unknown_kinds_and_actors(uis1: EditorSession) -> None:
    with pytest.raises(OperationError, match="kind"):
        uis1.apply([{"op": "add_node", "kind": "RootNode"}])
    with pytest.raises(OperationError, match="no actor named 'nobody'"):
        uis1.apply([{"op": "add_node", "kind": "Stop", "actor": "nobody"}])
    assert uis1.view()["undo"] is None


def test_delete_takes_the_flows_and_keeps_root_and_end(uis1: EditorSession) -> None:
    view = uis1.view()
    turn, root, end = (node_id(view, n) for n in ("TurnRight_1", "Root", "End"))
    after = roundtrip(uis1, [{"op": "delete", "nodes": [turn, root, end]}])
    names = {n["name"] for n in after["nodes"]}
    assert "TurnRight_1" not in names and {"Root", "End"} <= names
    assert all(turn not in (e["source"], e["target"]) for e in after["edges"])
    assert len(after["edges"]) == len(view["edges"]) - 2
    # graph.flows and the nodes' own lists agree: nothing dangles in the model.
    flows = list(uis1.graph.flows)
    assert all(f.source is not None and f.target is not None for f in flows)
    assert all(f in f.source.outgoing and f in f.target.incoming for f in flows)
    assert sum(len(n.incoming) for n in uis1.graph.nodes) == len(flows)


def test_delete_an_edge(uis1: EditorSession) -> None:
    edge = uis1.view()["edges"][0]["id"]
    after = roundtrip(uis1, [{"op": "delete", "edges": [edge]}])
    assert edge not in {e["id"] for e in after["edges"]}


def test_connect_and_its_refusals(uis1: EditorSession) -> None:
    view = uis1.view()
    root, end = node_id(view, "Root"), node_id(view, "End")
    turn, cross = node_id(view, "TurnRight_1"), node_id(view, "Cross_1")
    after = roundtrip(uis1, [{"op": "connect", "source": turn, "target": cross}])
    assert any(e["source"] == turn and e["target"] == cross for e in after["edges"])
    for source, target, message in [
        (turn, turn, "itself"),
        (turn, cross, "already"),
        (turn, root, "start"),
        (end, turn, "end"),
    ]:
        with pytest.raises(OperationError, match=message):
            uis1.apply([{"op": "connect", "source": source, "target": target}])


def test_move_sets_and_keeps_diagram_positions(uis1: EditorSession) -> None:
    turn = node_id(uis1.view(), "TurnRight_1")
    roundtrip(uis1, [{"op": "move", "positions": {turn: {"x": 1, "y": 2}}}])
    after = roundtrip(uis1, [{"op": "move", "positions": {turn: {"x": 3.5, "y": -4}}}])
    assert node(after, turn)["position"] == {"x": 3.5, "y": -4.0}
    with pytest.raises(OperationError, match="number"):
        uis1.apply([{"op": "move", "positions": {turn: {"x": "a", "y": 1}}}])


def test_set_text_enum_bool_and_actor_fields(uis1: EditorSession) -> None:
    view = uis1.view()
    root, end = node_id(view, "Root"), node_id(view, "End")
    turn = node_id(view, "TurnRight_1")
    after = roundtrip(
        uis1,
        [
            {"op": "set", "node": turn, "field": "name", "value": "Turn"},
            {"op": "set", "node": turn, "field": "referenceActor", "value": "bike"},
            {"op": "set", "node": end, "field": "policy", "value": "joinOne"},
            {"op": "set", "node": root, "field": "level", "value": "logical"},
            {"op": "set", "node": root, "field": "environment.cloudState", "value": "rainy"},
        ],
    )
    assert node(after, turn)["name"] == "Turn"
    assert field(node(after, turn), "referenceActor")["value"] == "bike"
    assert node(after, end)["look"] == "endOne"
    assert after["level"] == "logical" and "range" in after["valueTypes"]
    assert field(node(after, root), "environment.cloudState")["value"] == "rainy"


@pytest.mark.parametrize(
    ("field_name", "value", "message"),
    [
        ("name", "Accelerate_1", "already named"),
        ("name", "", "needs a name"),
        ("policy", "x", "no field"),
        ("referenceActor", "nobody", "no actor"),
        ("targetSpeed", 3, "not set with"),
    ],
)
def test_set_refusals(uis1: EditorSession, field_name: str, value: object, message: str) -> None:
    turn = node_id(uis1.view(), "Accelerate_2")
    with pytest.raises(OperationError, match=message):
        uis1.apply([{"op": "set", "node": turn, "field": field_name, "value": value}])


@pytest.mark.parametrize(
    "value",
    [
        {"type": "value", "value": 9.0},
        {"type": "range", "min": 5.0, "max": 10.0, "step": None},
        {"type": "uniform", "min": 5.0, "max": 10.0},
        {"type": "normal", "mean": 8.0, "sd": 1.0, "min": 6.0, "max": None},
        {"type": "discrete", "values": [5.0, 8.0], "weights": [1.0, 2.0]},
        None,
    ],
)
def test_set_parameter_every_value_type(uis1: EditorSession, value: dict | None) -> None:
    accelerate = node_id(uis1.view(), "Accelerate_1")
    op = {"op": "set_parameter", "node": accelerate, "field": "targetSpeed", "value": value}
    after = roundtrip(uis1, [op])
    shown = field(node(after, accelerate), "targetSpeed")
    assert shown["value"] == value
    assert shown["unit"] == "m/s" and shown["kmh"] is True and shown["required"] is True


def test_set_parameter_refusals(uis1: EditorSession) -> None:
    accelerate = node_id(uis1.view(), "Accelerate_1")
    for value, message in [
        ({"type": "range", "min": 9, "max": 1}, "min"),
        ({"type": "value", "value": "fast"}, "number"),
        ({"type": "ref", "parameter": "x"}, "only inside a module"),
        ({"type": "spline"}, "unknown parameter value type"),
    ]:
        with pytest.raises(OperationError, match=message):
            op = {"op": "set_parameter", "node": accelerate, "field": "targetSpeed", "value": value}
            uis1.apply([op])
    with pytest.raises(OperationError, match="no parameter"):
        uis1.apply([{"op": "set_parameter", "node": accelerate, "field": "radius", "value": None}])


def test_set_environment_parameter_creates_nothing_needless(uis1: EditorSession) -> None:
    root = node_id(uis1.view(), "Root")
    op = {"op": "set_parameter", "node": root, "field": "environment.fogVisualRange"}
    after = roundtrip(uis1, [{**op, "value": {"type": "value", "value": 500.0}}])
    assert field(node(after, root), "environment.fogVisualRange")["value"]["value"] == 500.0


def test_set_a_road_position(uis1: EditorSession) -> None:
    cross = node_id(uis1.view(), "Cross_1")
    road = {
        "type": "road",
        "roadId": "3",
        "s": {"type": "value", "value": 12.0},
        "t": {"type": "value", "value": -1.75},
        "h": None,
    }
    after = roundtrip(
        uis1, [{"op": "set_position", "node": cross, "field": "destination", "value": road}]
    )
    assert field(node(after, cross), "destination")["value"] == road
    with pytest.raises(OperationError, match="needs 's'"):
        uis1.apply(
            [
                {
                    "op": "set_position",
                    "node": cross,
                    "field": "destination",
                    "value": {**road, "s": None},
                }
            ]
        )


def test_set_a_relative_position_naming_an_actor(uis1: EditorSession) -> None:
    cross = node_id(uis1.view(), "Cross_1")
    ahead = {
        "type": "relativeLane",
        "entity": "ego",
        "dLane": 1,
        "ds": {"type": "value", "value": 20.0},
        "offset": None,
    }
    after = roundtrip(
        uis1, [{"op": "set_position", "node": cross, "field": "destination", "value": ahead}]
    )
    assert field(node(after, cross), "destination")["value"] == ahead
    with pytest.raises(OperationError, match="'nobody' is none of"):
        uis1.apply(
            [
                {
                    "op": "set_position",
                    "node": cross,
                    "field": "destination",
                    "value": {**ahead, "entity": "nobody"},
                }
            ]
        )


def test_set_position_and_waypoints(uis1: EditorSession) -> None:
    view = uis1.view()
    cross = node_id(view, "Cross_1")
    lane = {
        "type": "lane",
        "roadId": "3",
        "laneId": -1,
        "s": {"type": "value", "value": 12.0},
        "offset": None,
        "h": None,
    }
    after = roundtrip(
        uis1, [{"op": "set_position", "node": cross, "field": "destination", "value": lane}]
    )
    assert field(node(after, cross), "destination")["value"] == lane
    made = uis1.apply([{"op": "add_node", "kind": "FollowTrajectory", "actor": "ego"}])
    trajectory = made["created"][0]
    world = {
        "type": "world",
        "x": {"type": "value", "value": 1.0},
        "y": {"type": "value", "value": 2.0},
        "z": None,
        "h": None,
    }
    after = roundtrip(uis1, [{"op": "set_waypoints", "node": trajectory, "value": [world, lane]}])
    assert field(node(after, trajectory), "waypoints")["value"] == [world, lane]
    with pytest.raises(OperationError, match="needs 'x'"):
        uis1.apply(
            [
                {
                    "op": "set_position",
                    "node": cross,
                    "field": "destination",
                    "value": {"type": "world"},
                }
            ]
        )


def test_a_start_moved_onto_the_sidewalk_is_flagged_on_the_actor_and_undo_clears_it(
    uis1: EditorSession,
) -> None:
    ego = actor_id(uis1.view(), "ego")
    sidewalk = {
        "type": "lane",
        "roadId": "3",
        "laneId": 2,
        "s": {"type": "value", "value": 30.0},
        "offset": None,
    }
    after = uis1.apply([{"op": "set_actor_position", "actor": ego, "value": sidewalk}])
    flagged = [d for d in after["diagnostics"] if d["code"] == "SCEML-R004"]
    assert len(flagged) == 1 and "sidewalk" in flagged[0]["message"], flagged
    assert flagged[0]["actor"] == ego
    undone = uis1.undo()
    assert not [d for d in undone["diagnostics"] if d["code"].startswith("SCEML-R")]


def test_actor_operations(uis1: EditorSession) -> None:
    after = roundtrip(uis1, [{"op": "add_actor", "kind": "Truck"}])
    assert [a["name"] for a in after["actors"]] == ["ego", "bike", "truck_1"]
    truck = actor_id(after, "truck_1")
    after = roundtrip(
        uis1,
        [
            {"op": "set_actor", "actor": truck, "field": "name", "value": "lorry"},
            {"op": "set_actor", "actor": truck, "field": "isEgo", "value": False},
            {"op": "set_actor", "actor": truck, "field": "model", "value": "vehicle.t"},
            {"op": "set_actor", "actor": truck, "field": "catalogEntry", "value": "truck_yellow"},
            {
                "op": "set_actor_parameter",
                "actor": truck,
                "field": "initialSpeed",
                "value": {"type": "value", "value": 3.0},
            },
            {
                "op": "set_actor_position",
                "actor": truck,
                "value": {
                    "type": "lane",
                    "roadId": "1",
                    "laneId": 1,
                    "s": {"type": "value", "value": 5.0},
                    "offset": None,
                },
            },
        ],
    )
    lorry = next(a for a in after["actors"] if a["id"] == truck)
    assert lorry["name"] == "lorry"
    assert field(lorry, "catalogEntry")["value"] == "truck_yellow"  # release 1.5, a text field
    assert field(lorry, "initialSpeed")["value"] == {"type": "value", "value": 3.0}
    assert field(lorry, "length")["default"] > 5  # a truck's bounding box
    with pytest.raises(OperationError, match="already named"):
        uis1.apply([{"op": "set_actor", "actor": truck, "field": "name", "value": "ego"}])


def test_changing_an_actor_kind_keeps_every_reference(uis1: EditorSession) -> None:
    view = uis1.view()
    bike = actor_id(view, "bike")
    after = roundtrip(
        uis1, [{"op": "set_actor", "actor": bike, "field": "kind", "value": "Pedestrian"}]
    )
    walker = next(a for a in after["actors"] if a["name"] == "bike")
    assert walker["kind"] == "Pedestrian"
    assert field(walker, "startPosition")["value"] is not None
    performed = [n for n in uis1.graph.nodes if isinstance(n, scm.ActionNode)]
    on_bike = [
        n for n in performed if n.referenceActor is not None and n.referenceActor.name == "bike"
    ]
    assert len(on_bike) == 4 and all(isinstance(n.referenceActor, scm.Pedestrian) for n in on_bike)


def test_an_actor_keeps_its_id_through_a_change_of_kind_and_its_undo(uis1: EditorSession) -> None:
    # The browser keys the actor's panel by id: a new id would re-create it under the cursor.
    bike = actor_id(uis1.view(), "bike")
    changed = uis1.apply([{"op": "set_actor", "actor": bike, "field": "kind", "value": "Van"}])
    assert actor_id(changed, "bike") == bike
    renamed = uis1.apply([{"op": "set_actor", "actor": bike, "field": "name", "value": "van"}])
    assert actor_id(renamed, "van") == bike
    uis1.undo()
    undone = uis1.undo()
    assert actor_id(undone, "bike") == bike
    assert next(a for a in undone["actors"] if a["id"] == bike)["kind"] == "Bicycle"
    again = uis1.apply([{"op": "set_actor", "actor": bike, "field": "name", "value": "rider"}])
    assert next(a for a in again["actors"] if a["id"] == bike)["kind"] == "Bicycle"


def test_remove_actor_clears_references(uis1: EditorSession) -> None:
    ego = actor_id(uis1.view(), "ego")
    after = roundtrip(uis1, [{"op": "remove_actor", "actor": ego}])
    assert [a["name"] for a in after["actors"]] == ["bike"]
    radius = node(after, node_id(after, "InVehicleRadius_1"))
    assert field(radius, "targetActor")["value"] is None
    assert any(d["code"] for d in after["diagnostics"])


def test_module_use_operations(uis2: EditorSession) -> None:
    op = {
        "op": "add_module_use",
        "library": "library/sceml-library.xmi",
        "module": "CrossingManeuver",
        "position": {"x": 0, "y": 0},
        "bindings": {"crosser": "pedestrian"},
        "overrides": {"crossingSpeed": {"type": "value", "value": 2.0}},
    }
    after = roundtrip(uis2, [op])
    use = node(after, after["created"][0])
    assert use["name"] == "CrossingManeuver_2" and use["look"] == "module"
    module = use["module"]
    assert module["library"] == "library/sceml-library.xmi" and module["resolved"]
    assert {b["role"]: b["actor"] for b in module["bindings"]} == {
        "crosser": "pedestrian",
        "trigger": None,
    }
    use_id = use["id"]
    after = roundtrip(
        uis2,
        [
            {"op": "bind_role", "node": use_id, "role": "trigger", "actor": "car"},
            {"op": "set_override", "node": use_id, "parameter": "crossingSpeed", "value": None},
            {
                "op": "set_override",
                "node": use_id,
                "parameter": "triggerRadius",
                "value": {"type": "value", "value": 7.0},
            },
        ],
    )
    module = node(after, use_id)["module"]
    assert {b["role"]: b["actor"] for b in module["bindings"]}["trigger"] == "car"
    overrides = {p["name"]: p["override"] for p in module["parameters"]}
    assert overrides["crossingSpeed"] is None
    assert overrides["triggerRadius"] == {"type": "value", "value": 7.0}
    with pytest.raises(OperationError, match="no role"):
        uis2.apply([{"op": "bind_role", "node": use_id, "role": "x", "actor": "car"}])
    with pytest.raises(OperationError, match="no module"):
        uis2.apply([{**op, "module": "Nothing"}])


def test_module_internals_are_read_only(uis2: EditorSession) -> None:
    inner = next(n for n in uis2.view()["nodes"] if n["parent"] is not None)
    assert inner["readOnly"]
    with pytest.raises(OperationError, match="inside a module use"):
        uis2.apply([{"op": "delete", "nodes": [inner["id"]]}])


def test_paste_copies_nodes_and_the_flows_among_them(uis1: EditorSession) -> None:
    view = uis1.view()
    chosen = [node_id(view, n) for n in ("Accelerate_2", "Cross_1")]
    uis1.apply([{"op": "move", "positions": {chosen[0]: {"x": 10, "y": 10}}}])
    assert uis1.copy([*chosen, node_id(view, "Root")]) == 2
    after = roundtrip(uis1, [{"op": "paste", "offset": {"x": 40, "y": 40}}])
    pasted = [node(after, i) for i in after["created"]]
    assert [n["name"] for n in pasted] == ["Accelerate_3", "Cross_2"]
    assert pasted[0]["position"] == {"x": 50.0, "y": 50.0}
    ids = set(after["created"])
    assert sum(e["source"] in ids and e["target"] in ids for e in after["edges"]) == 1
    assert field(pasted[0], "referenceActor")["value"] == "bike"


def test_unknown_operation_and_node(uis1: EditorSession) -> None:
    with pytest.raises(OperationError, match="unknown operation"):
        uis1.apply([{"op": "explode"}])
    with pytest.raises(OperationError, match="unknown node"):
        uis1.apply([{"op": "delete", "nodes": ["n999"]}])


def test_a_condition_edge_and_a_box_centre_are_fields(uis1: EditorSession) -> None:
    # Release 1.3: Condition.edge (an enum, none by default) and Actor.boxCenterX (a number).
    view = uis1.view()
    radius = node_id(view, "InVehicleRadius_1")
    edge = field(node(view, radius), "edge")
    assert edge["value"] == "none"
    assert edge["options"] == ["none", "rising", "falling", "risingOrFalling"]
    ego = actor_id(view, "ego")
    after = roundtrip(
        uis1,
        [
            {"op": "set", "node": radius, "field": "edge", "value": "rising"},
            {
                "op": "set_actor_parameter",
                "actor": ego,
                "field": "boxCenterX",
                "value": {"type": "value", "value": 1.25},
            },
        ],
    )
    assert field(node(after, radius), "edge")["value"] == "rising"
    ego_view = next(a for a in after["actors"] if a["id"] == ego)
    centre = field(ego_view, "boxCenterX")
    assert centre["label"] == "Box centre x"
    assert centre["value"]["value"] == 1.25


def test_a_trailer_and_its_hitch_and_coupler_are_fields(uis1: EditorSession) -> None:
    # Release 1.4: Actor.trailer (the actor towed, chosen by name) and hitchX/couplerX.
    view = uis1.view()
    ego, bike = actor_id(view, "ego"), actor_id(view, "bike")
    ego_view = next(a for a in view["actors"] if a["id"] == ego)
    tows = field(ego_view, "trailer")
    assert (tows["label"], tows["type"], tows["value"], tows["required"]) == (
        "Tows",
        "actor",
        None,
        False,
    )
    after = roundtrip(
        uis1,
        [
            {"op": "set_actor", "actor": ego, "field": "trailer", "value": "bike"},
            {
                "op": "set_actor_parameter",
                "actor": ego,
                "field": "hitchX",
                "value": {"type": "value", "value": -1.2},
            },
            {
                "op": "set_actor_parameter",
                "actor": bike,
                "field": "couplerX",
                "value": {"type": "value", "value": 3.25},
            },
        ],
    )
    ego_view = next(a for a in after["actors"] if a["id"] == ego)
    bike_view = next(a for a in after["actors"] if a["id"] == bike)
    assert field(ego_view, "trailer")["value"] == "bike"
    assert field(ego_view, "hitchX")["label"] == "Hitch x"
    assert field(ego_view, "hitchX")["value"]["value"] == -1.2
    assert field(bike_view, "couplerX")["value"]["value"] == 3.25
    with pytest.raises(OperationError, match="no actor is named 'truck'"):
        uis1.apply([{"op": "set_actor", "actor": ego, "field": "trailer", "value": "truck"}])
    with pytest.raises(OperationError, match="cannot tow itself"):
        uis1.apply([{"op": "set_actor", "actor": ego, "field": "trailer", "value": "ego"}])


def test_an_actors_own_performance_is_a_field_unset_by_default(uis1: EditorSession) -> None:
    # Release 1.4: Actor.maxSpeed, maxAcceleration, maxDeceleration (a Vehicle's Performance).
    view = uis1.view()
    ego = actor_id(view, "ego")
    ego_view = next(a for a in view["actors"] if a["id"] == ego)
    top = field(ego_view, "maxSpeed")
    assert (top["label"], top["value"]) == ("Top speed", None)
    after = roundtrip(
        uis1,
        [
            {
                "op": "set_actor_parameter",
                "actor": ego,
                "field": "maxAcceleration",
                "value": {"type": "value", "value": 5.0},
            },
        ],
    )
    ego_view = next(a for a in after["actors"] if a["id"] == ego)
    assert field(ego_view, "maxAcceleration")["label"] == "Max acceleration"
    assert field(ego_view, "maxAcceleration")["value"]["value"] == 5.0
    assert field(ego_view, "maxDeceleration")["value"] is None

"""The view: labels as `sceml render` writes them, module internals, mapped diagnostics, palette."""

from __future__ import annotations

import pytest
from editor.helpers import node_id

from sceml.editor import EditorSession
from sceml.editor.palette import value_types
from sceml.render.style import CATEGORY_FILLS


def test_uis1_nodes_edges_and_actors(uis1: EditorSession) -> None:
    view = uis1.view()
    assert (
        view["document"]["kind"] == "scenario" and view["document"]["name"] == "uis1-concrete.xmi"
    )
    assert view["level"] == "concrete" and view["valueTypes"] == ["value"]
    assert len(view["nodes"]) == 9 and len(view["edges"]) == 9
    assert view["summary"] == {"errors": 0, "warnings": 0, "infos": 0}
    root = next(n for n in view["nodes"] if n["kind"] == "RootNode")
    assert root["title"] == "UIS1" and "level: concrete" in root["lines"]
    accelerate = next(n for n in view["nodes"] if n["name"] == "Accelerate_1")
    assert accelerate["look"] == "longitudinal" and accelerate["title"] == "Accelerate"
    assert accelerate["lines"][0] == "ego"
    assert any("28.8 km/h" in line for line in accelerate["lines"])
    assert [a["name"] for a in view["actors"]] == ["ego", "bike"]
    assert view["actors"][0]["isEgo"] and view["actors"][1]["kind"] == "Bicycle"
    names = [f["name"] for f in view["actors"][0]["fields"]]
    assert names[:3] == ["name", "kind", "isEgo"] and "startPosition" in names


def test_uis2_lists_the_module_use_and_its_internals(uis2: EditorSession) -> None:
    view = uis2.view()
    use = next(n for n in view["nodes"] if n["kind"] == "ModuleUse")
    assert use["look"] == "module" and use["title"] == "CrossingManeuver"
    assert use["module"]["library"] == "library/sceml-library.xmi"
    inner = [n for n in view["nodes"] if n["parent"] == use["id"]]
    assert {n["id"] for n in inner} >= {f"{use['id']}/in", f"{use['id']}/out"}
    assert all(n["readOnly"] for n in inner)
    kinds = [n["kind"] for n in inner if n["kind"] not in ("InPort", "OutPort")]
    assert kinds == ["InVehicleRadius", "Accelerate", "Cross", "InLocationRadius"]
    # Roles are shown with the actors bound to them, as in `sceml render --modules expanded`.
    assert next(n for n in inner if n["kind"] == "Accelerate")["lines"][0] == "pedestrian (crosser)"
    edges = [e for e in view["edges"] if e["id"].startswith(use["id"] + "/")]
    assert len(edges) == 5 and edges[0]["source"] == f"{use['id']}/in"


def test_a_deleted_flow_puts_the_diagnostic_on_the_node_that_lost_its_input(
    uis1: EditorSession,
) -> None:
    view = uis1.view()
    radius = node_id(view, "InVehicleRadius_1")
    flow = next(e for e in view["edges"] if e["target"] == radius)
    after = uis1.apply([{"op": "delete", "edges": [flow["id"]]}])
    mine = [d for d in after["diagnostics"] if d["node"] == radius]
    assert mine and all(d["code"].startswith("SCEML-") for d in mine)
    entry = next(n for n in after["nodes"] if n["id"] == radius)
    assert entry["severity"] == "error" and entry["problems"] == len(mine)
    cleared = uis1.undo()
    assert not [d for d in cleared["diagnostics"] if d["node"] == radius]
    assert next(n for n in cleared["nodes"] if n["id"] == radius)["severity"] is None


def test_diagnostics_on_actors_point_at_the_actor(uis1: EditorSession) -> None:
    view = uis1.view()
    bike = next(a for a in view["actors"] if a["name"] == "bike")
    after = uis1.apply([{"op": "set_actor_position", "actor": bike["id"], "value": None}])
    assert any(d["actor"] == bike["id"] for d in after["diagnostics"])


def test_a_problem_in_a_module_use_marks_the_use(uis2: EditorSession) -> None:
    view = uis2.view()
    use = next(n for n in view["nodes"] if n["kind"] == "ModuleUse")
    after = uis2.apply([{"op": "bind_role", "node": use["id"], "role": "trigger", "actor": None}])
    marked = next(n for n in after["nodes"] if n["id"] == use["id"])
    assert marked["severity"] == "error"
    unbound = next(d for d in after["diagnostics"] if d["code"] == "SCEML-M015")
    assert unbound["node"] == use["id"]


def test_palette_groups_and_libraries(uis2: EditorSession) -> None:
    palette = uis2.view()["palette"]
    groups = [g["group"] for g in palette]
    assert groups[:9] == [
        "longitudinal",
        "lateral",
        "composite",
        "controller",
        "appearance",
        "coupling",
        "condition",
        "global",
        "join",
    ]
    assert groups[9] == "library:library/sceml-library.xmi"
    assert [g["label"] for g in palette[:8]] == [
        "Longitudinal maneuvers",
        "Lateral maneuvers",
        "Composite maneuvers",
        "Controller changes",
        "Appearance (lights)",
        "Trailer couplings",
        "Conditions",
        "Global (no actor)",
    ]
    longitudinal = [i["kind"] for i in palette[0]["items"]]
    assert "Accelerate" in longitudinal and "TurnLeft" not in longitudinal
    modules = [i["module"] for i in palette[9]["items"]]
    assert "CrossingManeuver" in modules and palette[9]["items"][0]["kind"] == "ModuleUse"
    crossing = next(i for i in palette[9]["items"] if i["module"] == "CrossingManeuver")
    # UIS2's actors: ego and car are Cars (FourWheelers), pedestrian a Pedestrian.
    assert crossing["roles"] == [
        {"role": "crosser", "allowedKinds": ["TwoWheeler", "Pedestrian"], "actors": ["pedestrian"]},
        {"role": "trigger", "allowedKinds": ["FourWheeler"], "actors": ["ego", "car"]},
    ]


def test_style_is_the_render_notation(uis1: EditorSession) -> None:
    view = uis1.view()
    looks = view["style"]["looks"]
    assert looks["longitudinal"]["fill"] == CATEGORY_FILLS["longitudinal"]
    used = {n["look"] for n in view["nodes"]}
    assert used <= set(looks)
    assert view["style"]["symbols"]["joinAll"] == "⇉"
    assert view["choices"]["actorKinds"][0] == "Pedestrian"
    assert view["choices"]["oscVersions"][-1] == "1.3"


def test_fields_follow_the_catalog(uis1: EditorSession) -> None:
    view = uis1.view()
    turn = next(n for n in view["nodes"] if n["kind"] == "TurnRight")
    by_name = {f["name"]: f for f in turn["fields"]}
    assert by_name["destination"]["type"] == "position" and by_name["destination"]["required"]
    assert by_name["tolerance"]["default"] == 2.0 and by_name["tolerance"]["unit"] == "m"
    assert "targetActor" not in by_name
    radius = next(n for n in view["nodes"] if n["kind"] == "InVehicleRadius")
    assert {f["name"] for f in radius["fields"]} >= {"targetActor", "radius"}
    stop = uis1.apply([{"op": "add_node", "kind": "LaneChange"}])
    change = next(n for n in stop["nodes"] if n["id"] == stop["created"][0])
    direction = next(f for f in change["fields"] if f["name"] == "direction")
    assert direction["options"] == ["left", "right"]


def test_new_scenario_from_a_missing_file(tmp_path) -> None:
    from sceml.editor import SessionOptions

    session = EditorSession(SessionOptions(level="logical"))
    view = session.open(tmp_path / "cut-in.xmi")
    assert [n["kind"] for n in view["nodes"]] == ["RootNode", "EndNode"]
    assert view["nodes"][0]["title"] == "cut-in" and view["level"] == "logical"
    assert not view["dirty"]


@pytest.mark.parametrize(
    ("level", "in_module", "expected"),
    [
        ("functional", False, ["value", "range", "uniform", "normal", "discrete"]),
        ("logical", False, ["value", "range", "uniform", "normal", "discrete"]),
        ("concrete", False, ["value"]),
        ("concrete", True, ["value", "range", "uniform", "normal", "discrete", "ref"]),
    ],
)
def test_value_types_are_what_the_parameter_rules_accept(
    level: str, in_module: bool, expected: list[str]
) -> None:
    # Read from SCEML-P001's and P008's kinds: no spread in a concrete scenario, refs in modules.
    assert value_types(level, in_module) == expected

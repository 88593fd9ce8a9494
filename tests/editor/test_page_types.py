"""The page's types.ts says what the server sends: the view as the app answers it, each of its
parts, and each ParamValue, Position and Field kind, with the fields editor/app.py, view.py,
fields.py and values.py write (a change on one side fails here until the other follows).

Only the names of fields are compared, and whether each may be left out; their types are the
page's type check's business."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from starlette.testclient import TestClient

import scemlmodel as scm
from sceml.editor import EditorSession
from sceml.editor.app import create_app
from sceml.editor.fields import node_fields
from sceml.editor.values import RELATIVE_TYPES, VALUE_TYPES, position_to_json, value_to_json

TYPES = Path(__file__).resolve().parents[2] / "web" / "src" / "types.ts"


def source() -> str:
    """types.ts without its comments (they may hold words followed by colons)."""
    text = TYPES.read_text(encoding="utf-8")
    return re.sub(r"//[^\n]*", "", re.sub(r"/\*.*?\*/", "", text, flags=re.S))


#: Stands for an index signature (`[key: string]: unknown`): any other field is allowed.
ANY = "[index]"


def declared(body: str) -> dict[str, bool]:
    """The fields of an object type's body, each with whether it may be left out (`name?:`);
    only the body's own fields, not those of object types nested in it."""
    parts, depth, start = [], 0, 0
    for index, char in enumerate(body):
        depth += char in "{([<"
        depth -= char in "})]>"
        if char == ";" and depth == 0:
            parts.append(body[start:index])
            start = index + 1
    parts.append(body[start:])
    fields = {}
    for part in (part.strip() for part in parts):
        if part.startswith("["):
            fields[ANY] = True
        elif part:
            named = re.match(r"(\w+)(\?)?:", part)
            assert named, f"types.ts: cannot read the field {part!r}"
            fields[named.group(1)] = bool(named.group(2))
    return fields


def optional_members(name: str) -> dict[str, dict[str, bool]]:
    """The members of `export type NAME = | { type: "x"; a: ...; b?: ... } | ...` by their tag."""
    found = re.search(rf"export type {name} =(.*?);\n\n", source(), re.S)
    assert found, f"types.ts has no union {name}"
    members = {}
    for body in re.findall(r"\{([^{}]*)\}", found.group(1)):
        tag = re.search(r'type: "(\w+)"', body)
        assert tag, body
        members[tag.group(1)] = {k: v for k, v in declared(body).items() if k != "type"}
    return members


def union(name: str) -> dict[str, set[str]]:
    """The members of a union by their tag, each with its field names."""
    return {tag: set(fields) for tag, fields in optional_members(name).items()}


def interface(name: str) -> dict[str, bool]:
    """The fields of `interface NAME { ... }`, each with whether it may be left out."""
    text = source()
    found = re.search(rf"interface {name} \{{", text)
    assert found, f"types.ts has no interface {name}"
    depth, start = 1, found.end()
    for index in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[index], 0)
        if depth == 0:
            return declared(text[start:index])
    raise AssertionError(f"types.ts: interface {name} is not closed")


def fits(sent: dict[str, Any], fields: dict[str, bool]) -> None:
    """The server sends every field the page's type requires, and none it does not know."""
    if ANY not in fields:
        assert set(sent) <= set(fields), f"types.ts lacks {sorted(set(sent) - set(fields))}"
    required = {name for name, optional in fields.items() if not optional}
    assert required <= set(sent), f"the server does not send {sorted(required - set(sent))}"


def keys(sent: dict[str, Any] | None) -> tuple[str, set[str]]:
    assert sent is not None
    return sent["type"], set(sent) - {"type"}


def test_the_value_kinds_are_the_servers() -> None:
    assert list(union("ParamValue")) == list(VALUE_TYPES)


@pytest.mark.parametrize(
    "value",
    [
        scm.Value(value=1.0),
        scm.Range(min=1.0, max=2.0),
        scm.UniformDistribution(min=1.0, max=2.0),
        scm.NormalDistribution(mean=1.0, standardDeviation=0.5),
        scm.DiscreteDistribution(),
        scm.ParameterRef(),
    ],
    ids=lambda value: value.eClass.name,
)
def test_each_value_kind_has_the_fields_the_server_sends(value: scm.ParameterValue) -> None:
    kind, sent = keys(value_to_json(value))
    assert union("ParamValue")[kind] == sent


@pytest.mark.parametrize(
    "name", ["WorldPosition", "LanePosition", "RoadPosition", "RoutePosition", *RELATIVE_TYPES]
)
def test_each_position_kind_has_the_fields_the_server_sends(name: str) -> None:
    kind, sent = keys(position_to_json(getattr(scm, name)()))
    assert union("Position")[kind] == sent


def sent_fields() -> dict[str, list[dict[str, Any]]]:
    """Every Field the examples' views hold, by type, and those of a FollowTrajectory."""
    found: dict[str, list[dict[str, Any]]] = {}
    root = Path(__file__).resolve().parents[2] / "examples"
    for name in ("uis1-logical.xmi", "overtaking-concrete.xmi"):
        session = EditorSession()
        session.open(root / name)
        view = session.view()
        lists = [node["fields"] for node in view["nodes"]]
        lists += [actor.get("fields", []) for actor in view["actors"]]
        for field in (field for fields in lists for field in fields):
            found.setdefault(field["type"], []).append(field)
    for field in node_fields(scm.FollowTrajectory(name="Follow_1")):
        found.setdefault(field["type"], []).append(field)
    return found


def test_each_field_kind_has_the_fields_the_server_sends() -> None:
    page = optional_members("Field")
    base = interface("FieldBase")
    sent = sent_fields()
    assert set(sent) == set(page)
    for kind, fields in sent.items():
        for field in fields:
            fits({k: v for k, v in field.items() if k != "type"}, {**base, **page[kind]})


def test_a_module_parameter_has_the_fields_the_server_sends(uis2: EditorSession) -> None:
    uses = [node["module"] for node in uis2.view()["nodes"] if "module" in node]
    parameters = [parameter for use in uses for parameter in use["parameters"]]
    assert parameters, "uis2 uses a module with parameters"
    for parameter in parameters:
        fits(parameter, interface("ModuleParameter"))


def test_the_view_the_app_sends_fits_the_pages_types(examples_copy: Path) -> None:
    session = EditorSession()
    session.open(examples_copy / "uis2-logical.xmi")
    client = TestClient(create_app(session), base_url="http://127.0.0.1:8765")
    # A node without its actor: the answer names what was created and has a problem to show.
    answer = client.post("/api/ops", json={"ops": [{"op": "add_node", "kind": "Accelerate"}]})
    view = answer.json()
    assert view["created"] and view["diagnostics"]
    fits(view, interface("View"))
    fits(view["document"], interface("DocumentInfo"))
    fits(view["style"], interface("Style"))
    for look in view["style"]["looks"].values():
        fits(look, interface("LookStyle"))
    parts = {"ViewNode": "nodes", "ViewEdge": "edges", "Actor": "actors"}
    parts |= {"Diagnostic": "diagnostics", "PaletteGroup": "palette"}
    for name, key in parts.items():
        for part in view[key]:
            fits(part, interface(name))
    for item in (item for group in view["palette"] for item in group["items"]):
        fits(item, interface("PaletteItem"))
    modules = [node["module"] for node in view["nodes"] if "module" in node]
    assert modules, "uis2 uses a module"
    for module in modules:
        fits(module, interface("ModuleInfo"))
        for binding in module["bindings"]:
            fits(binding, interface("Binding"))

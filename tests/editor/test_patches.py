"""Answers as patches: a page that names the revision it holds gets only what changed."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
from editor.helpers import node_id
from starlette.testclient import TestClient

from sceml.editor import EditorSession, SessionOptions
from sceml.editor.app import create_app
from sceml.editor.patches import diff

SHARED = ("actors", "diagnostics", "palette", "style", "choices", "valueTypes", "comparison")


def applied(view: dict[str, Any], answer: dict[str, Any]) -> dict[str, Any]:
    """What the page makes of `answer` while it holds `view` (docs/editor-protocol.md)."""
    patch = answer.get("patch")
    if patch is None:
        return answer
    assert patch["base"] == view["revision"]
    result = {key: value for key, value in view.items() if key not in ("undo", "redo", "created")}
    result.update({key: value for key, value in answer.items() if key != "patch"})
    for key in ("nodes", "edges"):
        part = patch.get(key)
        if part is None:
            continue
        changed = {entry["id"]: entry for entry in part["changed"]}
        kept = [e for e in view[key] if e["id"] not in set(part["removed"])]
        known = {e["id"] for e in kept}
        merged = {e["id"]: changed.get(e["id"], e) for e in kept} | changed
        order = part.get("order") or [e["id"] for e in kept] + [
            i for i in changed if i not in known
        ]
        result[key] = [merged[i] for i in order]
    for key in SHARED:
        if key in patch:
            result[key] = patch[key]
    if result.get("comparison") is None:
        result.pop("comparison", None)
    return result


@pytest.fixture
def client(examples_copy: Path) -> TestClient:
    session = EditorSession(SessionOptions())
    session.open(examples_copy / "uis1-concrete.xmi")
    return TestClient(create_app(session), base_url="http://127.0.0.1:8765")


def without(view: dict[str, Any], *keys: str) -> dict[str, Any]:
    return {key: value for key, value in view.items() if key not in keys}


def full(client: TestClient, tab: str = "a") -> dict[str, Any]:
    return dict(client.get("/api/view", headers={"x-sceml-tab": tab}).json())


def post(client: TestClient, route: str, body: dict[str, Any], revision: int) -> dict[str, Any]:
    headers = {"x-sceml-tab": "a", "x-sceml-revision": str(revision)}
    answer = client.post(route, json=body, headers=headers)
    assert answer.status_code == 200, answer.text
    return dict(answer.json())


def test_a_parameter_edit_sends_that_node_only(client: TestClient) -> None:
    view = full(client)
    target = node_id(view, "Accelerate_1")
    value = {"type": "value", "value": 17.0}
    op = {"op": "set_parameter", "node": target, "field": "targetSpeed", "value": value}
    answer = post(client, "/api/ops", {"ops": [op]}, view["revision"])
    patch = answer["patch"]
    assert "nodes" not in answer and "diagnostics" not in patch
    assert [n["id"] for n in patch["nodes"]["changed"]] == [target]
    assert patch["nodes"]["removed"] == [] and "order" not in patch["nodes"]
    assert "edges" not in patch and "palette" not in patch and "style" not in patch
    assert "targetSpeed: 17 m/s = 61.2 km/h" in patch["nodes"]["changed"][0]["lines"]
    assert answer["revision"] == view["revision"] + 1 and answer["undo"] is not None
    assert without(applied(view, answer), "created") == full(client)


def test_patches_follow_adds_deletes_undo_and_save(client: TestClient) -> None:
    view = full(client)
    steps: list[tuple[str, dict[str, Any]]] = [
        ("/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]}),
        ("/api/ops", {"ops": [{"op": "delete", "nodes": [node_id(view, "TurnRight_1")]}]}),
        ("/api/undo", {}),
        ("/api/save", {}),
        ("/api/redo", {}),
    ]
    for route, body in steps:
        answer = post(client, route, body, view["revision"])
        assert "patch" in answer, route
        view = without(applied(view, answer), "created")
        assert view == full(client), route
    assert "TurnRight_1" not in {n["name"] for n in view["nodes"]}
    assert view["dirty"] is True


def test_a_delete_names_the_removed_node_and_its_flows(client: TestClient) -> None:
    view = full(client)
    gone = node_id(view, "TurnRight_1")
    flows = {e["id"] for e in view["edges"] if gone in (e["source"], e["target"])}
    answer = post(
        client, "/api/ops", {"ops": [{"op": "delete", "nodes": [gone]}]}, view["revision"]
    )
    assert answer["patch"]["nodes"]["removed"] == [gone]
    assert set(answer["patch"]["edges"]["removed"]) == flows


def test_a_page_that_missed_a_change_gets_the_whole_view(client: TestClient) -> None:
    view = full(client)
    post(client, "/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]}, view["revision"])
    missed = post(client, "/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]}, 0)
    assert "patch" not in missed and len(missed["nodes"]) == len(view["nodes"]) + 2
    stale = post(client, "/api/ops", {"ops": []}, view["revision"])
    assert "patch" not in stale and "nodes" in stale


def test_a_page_that_holds_the_newest_revision_gets_the_small_fields(client: TestClient) -> None:
    view = full(client)
    again = client.get("/api/view", headers={"x-sceml-revision": str(view["revision"])}).json()
    assert again["patch"] == {"base": view["revision"]} and "nodes" not in again
    assert again["revision"] == view["revision"]


def test_a_bad_revision_header_is_400(client: TestClient) -> None:
    answer = client.get("/api/view", headers={"x-sceml-revision": "soon"})
    assert answer.status_code == 400 and "x-sceml-revision" in answer.json()["error"]


def test_other_pages_get_the_patch_in_the_change_event(examples_copy: Path) -> None:
    session = EditorSession(SessionOptions())
    session.open(examples_copy / "uis1-concrete.xmi")
    app = create_app(session)
    published: list[dict[str, Any]] = []
    app.state.api.live.publish = published.append
    client = TestClient(app, base_url="http://127.0.0.1:8765")
    other = full(client, tab="b")
    post(client, "/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]}, 0)
    (event,) = published
    assert event["tab"] == "a" and "undo" not in event and "redo" not in event
    assert [n["name"] for n in event["patch"]["nodes"]["changed"]] == ["Stop_1"]
    expected = full(client, tab="b")
    assert without(applied(other, event), "undo", "redo", "tab") == without(
        expected, "undo", "redo"
    )


def test_diff_sends_an_order_only_when_the_ids_move() -> None:
    before: dict[str, Any] = {
        "nodes": [{"id": "a"}, {"id": "b"}, {"id": "c"}],
        "edges": [{"id": "f", "source": "a", "target": "b"}],
    }
    added = copy.deepcopy(before)
    added["nodes"] = [{"id": "a"}, {"id": "c"}, {"id": "d"}]
    patch = diff(before, added)
    assert patch == {"nodes": {"changed": [{"id": "d"}], "removed": ["b"]}}
    moved = copy.deepcopy(before)
    moved["nodes"] = [{"id": "b"}, {"id": "a"}, {"id": "c"}]
    assert diff(before, moved) == {
        "nodes": {"changed": [], "removed": [], "order": ["b", "a", "c"]}
    }
    assert diff(before, copy.deepcopy(before)) is None

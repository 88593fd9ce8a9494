"""Several tabs on one server: each undoes its own edits, conflicts are named, all hear changes."""

from __future__ import annotations

from pathlib import Path

import pytest
from editor.helpers import node_id
from starlette.testclient import TestClient

from sceml.editor import EditorSession, OperationError, SessionOptions
from sceml.editor.app import create_app
from sceml.editor.errors import ConflictError


def add(session: EditorSession, kind: str, tab: str) -> str:
    view = session.apply([{"op": "add_node", "kind": kind}], tab=tab)
    return str(view["created"][0])


def names(view: dict) -> set[str]:
    return {n["name"] for n in view["nodes"] if n["parent"] is None}


def test_each_tab_undoes_its_own_step(uis1: EditorSession) -> None:
    add(uis1, "Stop", "A")
    add(uis1, "Accelerate", "B")
    view = uis1.undo("A")
    assert "Stop_1" not in names(view) and "Accelerate_1" in names(view)
    assert view["undo"] is None and view["redo"] == "Add Stop"
    assert uis1.view(tab="B")["undo"] == "Add Accelerate"
    view = uis1.redo("A")
    assert {"Stop_1", "Accelerate_1"} <= names(view)


def test_undo_over_another_tabs_change_of_the_same_thing_is_refused(
    uis1: EditorSession,
) -> None:
    stop = add(uis1, "Stop", "A")
    rename = {"op": "set", "node": stop, "field": "name", "value": "Halt"}
    uis1.apply([rename], label="Rename", tab="B")
    with pytest.raises(ConflictError, match=r"'Add Stop' cannot be undone here.*'Rename'"):
        uis1.undo("A")
    assert "Halt" in names(uis1.view())
    uis1.undo("B")
    assert "Stop_1" not in names(uis1.undo("A"))


def test_editing_what_another_tab_deleted_names_it(uis1: EditorSession) -> None:
    target = node_id(uis1.view(tab="A"), "TurnRight_1")
    uis1.apply([{"op": "delete", "nodes": [target]}], tab="B")
    rename = {"op": "set", "node": target, "field": "name", "value": "x"}
    with pytest.raises(OperationError, match="^'TurnRight_1' was deleted in another tab$"):
        uis1.apply([rename], tab="A")
    with pytest.raises(OperationError, match="^'TurnRight_1' was deleted by 'Delete'$"):
        uis1.apply([rename], tab="B")


def test_saved_state_is_the_same_for_every_tab(uis1: EditorSession) -> None:
    add(uis1, "Stop", "A")
    assert uis1.view(tab="B")["dirty"] is True
    uis1.save()
    assert uis1.view(tab="A")["dirty"] is False and uis1.view(tab="B")["dirty"] is False
    uis1.undo("A")
    assert uis1.view(tab="B")["dirty"] is True


def test_the_tab_header_reaches_the_session(examples_copy: Path) -> None:
    session = EditorSession(SessionOptions())
    session.open(examples_copy / "uis1-concrete.xmi")
    client = TestClient(create_app(session), base_url="http://127.0.0.1:8765")
    a, b = {"x-sceml-tab": "tab-a"}, {"x-sceml-tab": "tab-b"}
    client.post("/api/ops", json={"ops": [{"op": "add_node", "kind": "Stop"}]}, headers=a)
    assert client.get("/api/view", headers=b).json()["undo"] is None
    assert client.post("/api/undo", headers=b).json()["undo"] is None
    assert "Stop_1" in names(client.get("/api/view").json())
    assert client.post("/api/undo", headers=a).json()["redo"] == "Add Stop"
    bad = client.post("/api/undo", headers={"x-sceml-tab": "no spaces"})
    assert bad.status_code == 400 and "x-sceml-tab" in bad.json()["error"]


def test_the_event_stream_announces_every_change(examples_copy: Path) -> None:
    session = EditorSession(SessionOptions())
    session.open(examples_copy / "uis1-concrete.xmi")
    app = create_app(session)
    live = app.state.api.live
    published: list[dict] = []
    live.publish = published.append  # what every open stream would receive
    client = TestClient(app, base_url="http://127.0.0.1:8765")
    version = client.get("/api/view").json()["version"]
    client.post(
        "/api/ops", json={"ops": [{"op": "add_node", "kind": "Stop"}]}, headers={"x-sceml-tab": "a"}
    )
    client.post("/api/ops", json={"ops": "refused"})
    client.post("/api/undo", headers={"x-sceml-tab": "b"})
    assert [(event["version"], event["tab"]) for event in published] == [
        (version + 1, "a"),
        (version + 1, "b"),
    ]
    # The patch of the added node travels with the event (tests/editor/test_patches.py).
    assert [n["name"] for n in published[0]["patch"]["nodes"]["changed"]] == ["Stop_1"]

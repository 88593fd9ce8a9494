"""Hostile and malformed requests (issue 26, item 6): a 400 or 413 with a message, never a 500;
headers that keep other pages from framing the editor; saves and exports only where reading is
allowed."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from starlette.testclient import TestClient

from sceml.editor import EditorSession, SessionOptions
from sceml.editor.app import create_app
from sceml.editor.bodies import MAX_BODY_BYTES
from sceml.model.loading import load

POST_ROUTES = [
    "/api/ops",
    "/api/undo",
    "/api/redo",
    "/api/copy",
    "/api/save",
    "/api/export",
    "/api/open",
    "/api/open-definition",
    "/api/recovery",
]


def client_for(path: Path, **options: object) -> TestClient:
    session = EditorSession(SessionOptions(**options))  # type: ignore[arg-type]
    session.open(path)
    return TestClient(create_app(session), base_url="http://127.0.0.1:8765")


@pytest.fixture
def client(examples_copy: Path) -> TestClient:
    return client_for(examples_copy / "uis1-concrete.xmi")


def first_node(client: TestClient, kind: str) -> str:
    return next(n["id"] for n in client.get("/api/view").json()["nodes"] if n["kind"] == kind)


@pytest.mark.parametrize("route", POST_ROUTES)
def test_deeply_nested_json_is_400_on_every_route(client: TestClient, route: str) -> None:
    for depth in (100, 100_000):
        body = "[" * depth + "]" * depth
        answer = client.post(route, content=body.encode())
        assert answer.status_code == 400, (route, depth, answer.text)
        assert "nested more than 32 levels" in answer.json()["error"]


def test_nesting_inside_an_object_counts_too(client: TestClient) -> None:
    value: object = 1
    for _ in range(40):
        value = {"type": value}
    answer = client.post("/api/ops", json={"ops": [{"op": "move", "positions": value}]})
    assert answer.status_code == 400 and "nested" in answer.json()["error"]


def test_a_body_over_the_limit_is_413_without_parsing(client: TestClient) -> None:
    huge = b'{"ops": [' + b" " * MAX_BODY_BYTES + b"]}"
    answer = client.post("/api/ops", content=huge)
    assert answer.status_code == 413 and "larger than 4 MiB" in answer.json()["error"]


def test_a_body_that_lies_about_its_length_is_counted_as_it_arrives(client: TestClient) -> None:
    def chunks():  # no Content-Length: the body is streamed in chunks
        yield b'{"ops": ['
        for _ in range(5):
            yield b" " * (MAX_BODY_BYTES // 4)
        yield b"]}"

    answer = client.post("/api/ops", content=chunks())
    assert answer.status_code == 413


@pytest.mark.parametrize(
    ("route", "body", "reason"),
    [
        ("/api/ops", {"ops": [1, 2]}, "an operation must be an object, not 1"),
        ("/api/ops", {"ops": [{"op": 5}]}, "unknown operation 5"),
        ("/api/ops", {"ops": [], "label": ["x"]}, "'label' must be a text"),
        ("/api/save", {"path": 5}, "'path' must name a file as text, not 5"),
        ("/api/save", {"path": "a\x00b.xmi"}, "NUL"),
        ("/api/save", {"path": "x" * 5000}, "5,000 characters long"),
        ("/api/save", {"path": "y" * 300 + ".xmi"}, "longer than 255 bytes"),
        ("/api/export", {"path": 5}, "'path' must name a file as text"),
        ("/api/export", {"version": {"v": 1}}, "'version' must be a short text"),
        ("/api/export", {"profile": 7}, "'profile' must be a short text"),
        ("/api/open", {"path": 5}, "'path' must name a file as text"),
        ("/api/open", {"path": "x.xmi", "discard": "yes"}, "'discard' must be true or false"),
        ("/api/open", {"path": "x.xmi", "module": 3}, "'module' must be the name"),
        ("/api/open-definition", {"node": [1]}, "unknown node [1]"),
        ("/api/copy", {"nodes": "n1"}, "'nodes' must be a list"),
        ("/api/copy", {"nodes": [{"id": 1}]}, "unknown node"),
        ("/api/recovery", {"restore": "yes"}, "'restore' must be true or false"),
        (
            "/api/ops",
            {"ops": [{"op": "extract_module", "nodes": 5, "name": "M", "library": "l"}]},
            "'nodes' must be a list",
        ),
    ],
)
def test_malformed_requests_are_400_with_a_message(
    client: TestClient, route: str, body: dict[str, object], reason: str
) -> None:
    answer = client.post(route, json=body)
    assert answer.status_code == 400, answer.text
    assert reason in answer.json()["error"]


def test_a_lone_surrogate_is_refused_and_the_view_still_answers(client: TestClient) -> None:
    node = first_node(client, "Accelerate")
    # json.dumps escapes the surrogate as \\ud800, as a browser's JSON.stringify would.
    op = {"op": "set", "node": node, "field": "name", "value": "a\ud800b"}
    body = json.dumps({"ops": [op]})
    assert "\\ud800" in body
    answer = client.post("/api/ops", content=body.encode())
    assert answer.status_code == 400 and "lone surrogate (U+D800)" in answer.json()["error"]
    assert client.get("/api/view").status_code == 200


def test_names_and_texts_have_a_length_limit(client: TestClient, examples_copy: Path) -> None:
    node = first_node(client, "Accelerate")
    long_name = {"op": "set", "node": node, "field": "name", "value": "N" * 201}
    answer = client.post("/api/ops", json={"ops": [long_name]})
    assert answer.status_code == 400
    assert answer.json()["error"] == "name may be at most 200 characters long, not 201"
    actor = {"op": "add_actor", "kind": "Car", "name": "c" * 1000}
    assert client.post("/api/ops", json={"ops": [actor]}).status_code == 400
    root = first_node(client, "RootNode")
    description = {"op": "set", "node": root, "field": "description", "value": "d" * 10_001}
    assert client.post("/api/ops", json={"ops": [description]}).status_code == 400
    # The longest name allowed saves a file that reads back.
    longest = {"op": "set", "node": node, "field": "name", "value": "N" * 200}
    assert client.post("/api/ops", json={"ops": [longest]}).status_code == 200
    assert client.post("/api/save", json={}).status_code == 200
    names = {n.name for n in load(examples_copy / "uis1-concrete.xmi").root.nodes}
    assert "N" * 200 in names


def test_every_answer_forbids_framing(client: TestClient) -> None:
    answers = [
        client.get("/"),
        client.get("/api/view"),
        client.post("/api/ops", json={"ops": "x"}),
        client.get("/api/nothing-here"),
        client.get("/api/view", headers={"host": "evil.example"}),
    ]
    for answer in answers:
        assert answer.headers["x-frame-options"] == "DENY", answer.url
        policy = answer.headers["content-security-policy"]
        assert "frame-ancestors 'none'" in policy and "script-src 'self'" in policy


@pytest.fixture
def outside(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder beside the test's own (whose project root holds the copied examples)."""
    return tmp_path_factory.mktemp("elsewhere")


def test_save_and_export_stay_in_the_allowed_folders(
    client: TestClient, examples_copy: Path, outside: Path
) -> None:
    for route, name in (("/api/save", "a.xmi"), ("/api/export", "a.xosc")):
        answer = client.post(route, json={"path": str(outside / name)})
        assert answer.status_code == 400
        assert "outside the folders the editor may use" in answer.json()["error"]
        assert "--allow" in answer.json()["error"]
    climbing = client.post(
        "/api/save", json={"path": os.path.relpath(outside / "b.xmi", examples_copy)}
    )
    assert climbing.status_code == 400
    assert client.post("/api/open", json={"path": "/etc/passwd"}).status_code == 400
    extract = {"op": "extract_module", "nodes": [], "name": "M", "library": "/tmp/x/lib.xmi"}
    assert client.post("/api/ops", json={"ops": [extract]}).status_code == 400
    assert list(outside.iterdir()) == []
    # A relative path means beside the edited file.
    assert client.post("/api/export", json={"path": "out/uis1.xosc"}).status_code == 200
    assert (examples_copy / "out" / "uis1.xosc").is_file()


def test_allow_opens_another_folder(examples_copy: Path, outside: Path) -> None:
    refused = client_for(examples_copy / "uis1-concrete.xmi")
    assert refused.post("/api/export", json={"path": str(outside / "a.xosc")}).status_code == 400
    client = client_for(examples_copy / "uis1-concrete.xmi", allow=[outside])
    assert client.post("/api/export", json={"path": str(outside / "a.xosc")}).status_code == 200
    assert (outside / "a.xosc").is_file()


def test_a_link_out_of_the_allowed_folders_is_refused(
    client: TestClient, examples_copy: Path, outside: Path
) -> None:
    victim = outside / "victim.txt"
    victim.write_text("keep me", encoding="utf-8")
    os.symlink(victim, examples_copy / "link.xmi")
    answer = client.post("/api/save", json={"path": "link.xmi"})
    assert answer.status_code == 400 and "outside" in answer.json()["error"]
    assert victim.read_text(encoding="utf-8") == "keep me"
    assert (examples_copy / "link.xmi").is_symlink()

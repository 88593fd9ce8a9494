"""The HTTP protocol through Starlette's test client: routes, status codes, files written."""

from __future__ import annotations

from pathlib import Path

import pytest
from starlette.testclient import TestClient

from sceml.diagnostics import Severity
from sceml.editor import EditorSession, SessionOptions
from sceml.editor import app as app_module
from sceml.editor.app import create_app
from sceml.model.compare import differences
from sceml.model.loading import load, load_library
from sceml.validation import validate
from sceml.xosc import schema


def client_for(path: Path, **options: object) -> TestClient:
    session = EditorSession(SessionOptions(**options))  # type: ignore[arg-type]
    session.open(path)
    return TestClient(create_app(session), base_url="http://127.0.0.1:8765")


@pytest.fixture
def client(examples_copy: Path) -> TestClient:
    return client_for(examples_copy / "uis1-concrete.xmi")


def test_view_ops_undo_redo(client: TestClient) -> None:
    view = client.get("/api/view").json()
    assert view["document"]["name"] == "uis1-concrete.xmi"
    answer = client.post("/api/ops", json={"ops": [{"op": "add_node", "kind": "Stop"}]})
    assert answer.status_code == 200 and answer.json()["created"]
    assert client.post("/api/undo").json()["redo"] == "Add Stop"
    assert client.post("/api/redo").json()["undo"] == "Add Stop"


@pytest.mark.parametrize(
    "body",
    [
        {"ops": [{"op": "delete", "nodes": ["n999"]}]},
        {"ops": [{"op": "set", "node": "n3", "field": "nope", "value": 1}]},
        {"ops": "not a list"},
    ],
)
def test_bad_operations_are_400(client: TestClient, body: dict) -> None:
    answer = client.post("/api/ops", json=body)
    assert answer.status_code == 400 and answer.json()["error"]


def test_a_body_that_is_not_json_is_400(client: TestClient) -> None:
    assert client.post("/api/ops", content=b"{nope").status_code == 400


def test_read_only_refuses_every_change(examples_copy: Path) -> None:
    client = client_for(examples_copy / "uis1-concrete.xmi", read_only=True)
    assert client.get("/api/view").json()["readOnly"] is True
    for path, body in [
        ("/api/ops", {"ops": [{"op": "add_node", "kind": "Stop"}]}),
        ("/api/undo", {}),
        ("/api/redo", {}),
        ("/api/save", {}),
    ]:
        answer = client.post(path, json=body)
        assert answer.status_code == 403, path


def test_save_writes_a_file_that_loads_back_equal_and_valid(
    client: TestClient, examples_copy: Path, tmp_path: Path
) -> None:
    view = client.get("/api/view").json()
    turn = next(n["id"] for n in view["nodes"] if n["name"] == "TurnRight_1")
    client.post("/api/ops", json={"ops": [{"op": "move", "positions": {turn: {"x": 7, "y": 8}}}]})
    target = examples_copy / "uis1-edited.xmi"
    saved = client.post("/api/save", json={"path": str(target)})
    assert saved.status_code == 200 and saved.json()["dirty"] is False
    assert saved.json()["document"]["name"] == "uis1-edited.xmi"
    document = load(target)
    original = load(examples_copy / "uis1-concrete.xmi")
    changes = differences(original.root, document.root)
    assert changes and all("diagramPosition" in line for line in changes)
    found = validate(document.root, document=document)
    assert not [d for d in found if d.severity is Severity.ERROR]


def test_export_writes_xsd_valid_openscenario(client: TestClient, examples_copy: Path) -> None:
    target = examples_copy / "uis1.xosc"
    answer = client.post("/api/export", json={"version": "1.2", "path": str(target)})
    assert answer.status_code == 200 and answer.json() == {"path": str(target), "version": "1.2"}
    assert schema.validate_tree(schema.parse_file(target), "1.2") == []


def test_the_view_offers_the_exporters_versions_and_profiles(client: TestClient) -> None:
    # The page types none of them: the export dialog's selects are filled from these.
    choices = client.get("/api/view").json()["choices"]
    assert choices["oscVersions"] == ["1.0", "1.1", "1.2", "1.3"]
    assert choices["profiles"] == ["generic", "carla"]


def test_export_with_an_empty_version_writes_the_profiles_default(
    client: TestClient, examples_copy: Path
) -> None:
    # What the page sends when "the profile's default" is chosen.
    target = examples_copy / "uis1-generic.xosc"
    answer = client.post("/api/export", json={"version": "", "path": str(target)})
    assert answer.status_code == 200 and answer.json() == {"path": str(target), "version": "1.3"}


def test_export_without_a_version_writes_the_profiles_default(
    client: TestClient, examples_copy: Path
) -> None:
    # The carla profile reads 1.0 only: the editor, like the CLI, must not default to 1.3 there.
    target = examples_copy / "uis1-carla.xosc"
    body = {"profile": "carla", "path": str(target)}
    answer = client.post("/api/export", json=body)
    assert answer.status_code == 200 and answer.json() == {"path": str(target), "version": "1.0"}
    assert schema.parse_file(target).getroot().find("FileHeader").get("revMinor") == "0"


def test_a_refused_export_is_422_with_diagnostics(examples_copy: Path) -> None:
    client = client_for(examples_copy / "uis1-logical.xmi")
    answer = client.post("/api/export", json={"path": str(examples_copy / "x.xosc")})
    assert answer.status_code == 422
    assert answer.json()["diagnostics"] and answer.json()["error"]
    assert not (examples_copy / "x.xosc").exists()


def test_open_with_unsaved_changes_is_409_unless_discarded(
    client: TestClient, examples_copy: Path
) -> None:
    client.post("/api/ops", json={"ops": [{"op": "add_node", "kind": "Stop"}]})
    other = str(examples_copy / "uis2-concrete.xmi")
    assert client.post("/api/open", json={"path": other}).status_code == 409
    opened = client.post("/api/open", json={"path": other, "discard": True})
    assert opened.status_code == 200 and opened.json()["document"]["name"] == "uis2-concrete.xmi"


def test_open_definition_edits_the_module_in_its_library(examples_copy: Path) -> None:
    client = client_for(examples_copy / "uis2-concrete.xmi")
    use = next(n for n in client.get("/api/view").json()["nodes"] if n["kind"] == "ModuleUse")
    view = client.post("/api/open-definition", json={"node": use["id"]}).json()
    assert view["document"] == {
        "kind": "module",
        "path": str((examples_copy / "library" / "sceml-library.xmi").resolve()),
        "name": "sceml-library.xmi",
        "module": "CrossingManeuver",
    }
    assert [a["name"] for a in view["actors"]] == ["crosser", "trigger"]
    assert "ref" in view["valueTypes"]
    accelerate = next(n for n in view["nodes"] if n["kind"] == "Accelerate")
    op = {
        "op": "set_parameter",
        "node": accelerate["id"],
        "field": "targetSpeed",
        "value": {"type": "ref", "parameter": "triggerRadius"},
    }
    assert client.post("/api/ops", json={"ops": [op]}).status_code == 200
    assert client.post("/api/save", json={}).status_code == 200
    library = load_library(examples_copy / "library" / "sceml-library.xmi").root
    crossing = next(m for m in library.modules if m.name == "CrossingManeuver")
    moved = next(n for n in crossing.nodes if n.eClass.name == "Accelerate")
    assert moved.targetSpeed.parameter.name == "triggerRadius"


def test_copy_answers_how_many(client: TestClient) -> None:
    view = client.get("/api/view").json()
    ids = [n["id"] for n in view["nodes"] if n["kind"] in ("Accelerate", "RootNode")]
    assert client.post("/api/copy", json={"nodes": ids}).json() == {"copied": 2}


def test_missing_bundle_page_says_how_to_build(
    client: TestClient, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(app_module, "static_folder", lambda: tmp_path / "nothing")
    answer = client.get("/")
    assert answer.status_code == 200 and "bash scripts/setup.sh" in answer.text


def test_the_built_page_is_served(
    client: TestClient, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "index.html").write_text("<html>editor</html>", encoding="utf-8")
    monkeypatch.setattr(app_module, "static_folder", lambda: tmp_path)
    assert client.get("/").text == "<html>editor</html>"


def test_other_sites_cannot_edit_or_save(client: TestClient, examples_copy: Path) -> None:
    target = examples_copy / "uis1-concrete.xmi"
    before = target.read_bytes()
    # A page of another site posting to the editor (no preflight for a text/plain body).
    hostile = {"origin": "http://evil.example", "content-type": "text/plain"}
    ops = '{"ops": [{"op": "add_node", "kind": "Stop"}]}'
    answer = client.post("/api/ops", content=ops, headers=hostile)
    assert answer.status_code == 403 and "another site" in answer.json()["error"]
    assert client.post("/api/save", content="{}", headers=hostile).status_code == 403
    assert target.read_bytes() == before
    assert client.get("/api/view").json()["dirty"] is False
    # DNS rebinding: a foreign host name that resolves to 127.0.0.1.
    assert client.get("/api/view", headers={"host": "evil.example"}).status_code == 400
    # The editor's own page names its own origin.
    own = {"origin": "http://127.0.0.1:8765"}
    answer = client.post("/api/ops", content=ops, headers=own)
    assert answer.status_code == 200

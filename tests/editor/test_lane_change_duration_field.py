"""The properties panel edits a lane change's `duration` (release 1.5) as a parameter in
seconds beside its distance, and live validation follows it: both set is SCEML-P010."""

from __future__ import annotations

from pathlib import Path

from editor.helpers import node_id

from sceml.editor import EditorSession, SessionOptions
from sceml.importer import import_to_file

FILES = Path(__file__).resolve().parents[1] / "importer" / "files"


def _field(view: dict, name: str, field: str) -> dict:
    node = next(n for n in view["nodes"] if n["name"] == name and n["parent"] is None)
    return next(f for f in node["fields"] if f["name"] == field)


def test_the_duration_is_a_parameter_in_seconds(tmp_path: Path) -> None:
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    import_to_file(FILES / "lane-change-time.xosc", tmp_path / "timed.xmi")
    session = EditorSession(SessionOptions())
    session.open(tmp_path / "timed.xmi")
    view = session.view()
    duration = _field(view, "CutInEvent", "duration")
    assert (duration["type"], duration["unit"], duration["required"]) == ("parameter", "s", False)
    assert (duration["value"], duration["text"]) == ({"type": "value", "value": 3.0}, "3 s")
    assert _field(view, "CutInEvent", "distance")["value"] is None
    assert "SCEML-P010" not in {d.code for d in session.diagnostics()}
    change = node_id(view, "CutInEvent")
    value = {"type": "value", "value": 40}
    session.apply([{"op": "set_parameter", "node": change, "field": "distance", "value": value}])
    assert "SCEML-P010" in {d.code for d in session.diagnostics()}
    session.apply([{"op": "set_parameter", "node": change, "field": "duration", "value": None}])
    assert "SCEML-P010" not in {d.code for d in session.diagnostics()}
    assert _field(session.view(), "CutInEvent", "duration")["value"] is None

"""The properties panel edits a maneuver's `interrupts` (release 1.5) as a checkbox, and live
validation follows it: two speed changes of one actor that may overlap pass simultaneity
(SCEML-C001) while one of them interrupts."""

from __future__ import annotations

from pathlib import Path

from editor.helpers import node_id

from sceml.editor import EditorSession, SessionOptions
from sceml.importer import import_to_file

FILES = Path(__file__).resolve().parents[1] / "importer" / "files"


def _field(view: dict, name: str, field: str) -> dict:
    node = next(n for n in view["nodes"] if n["name"] == name and n["parent"] is None)
    return next(f for f in node["fields"] if f["name"] == field)


def test_the_flag_is_a_checkbox_and_validation_follows_it(tmp_path: Path) -> None:
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    import_to_file(FILES / "interrupts.xosc", tmp_path / "interrupts.xmi")
    session = EditorSession(SessionOptions())
    session.open(tmp_path / "interrupts.xmi")
    view = session.view()
    field = _field(view, "Brake", "interrupts")
    assert (field["type"], field["value"], field["label"]) == (
        "bool",
        True,
        "Interrupts a running one",
    )
    assert "SCEML-C001" not in {d.code for d in session.diagnostics()}
    ops = [
        {"op": "set", "node": node_id(view, name), "field": "interrupts", "value": False}
        for name in ("SpeedUp", "Brake")
    ]
    session.apply(ops)
    assert _field(session.view(), "Brake", "interrupts")["value"] is False
    assert "SCEML-C001" in {d.code for d in session.diagnostics()}
    session.undo()
    assert "SCEML-C001" not in {d.code for d in session.diagnostics()}

"""extract_module: the library is written at once; undo gives back the very same nodes."""

from __future__ import annotations

from pathlib import Path

import pytest
from editor.helpers import node_id, saved_bytes

from sceml.editor import EditorSession, OperationError
from sceml.model.loading import load_library


def test_extract_writes_the_library_and_undo_restores_the_nodes(uis1: EditorSession) -> None:
    view = uis1.view()
    chosen = [node_id(view, n) for n in ("Accelerate_2", "Cross_1")]
    before = saved_bytes(uis1)
    op = {"op": "extract_module", "nodes": chosen, "name": "BikeGo", "library": "library/mine.xmi"}
    after = uis1.apply([op])
    use = next(n for n in after["nodes"] if n["id"] == after["created"][0])
    assert use["kind"] == "ModuleUse" and use["module"]["definition"] == "BikeGo"
    assert use["module"]["library"] == "library/mine.xmi"
    top = {n["name"] for n in after["nodes"] if n["parent"] is None}
    assert not top & {"Accelerate_2", "Cross_1"}
    assert after["summary"]["errors"] == 0
    library = load_library(uis1.path.parent / "library" / "mine.xmi").root
    assert [m.name for m in library.modules] == ["BikeGo"]
    undone = uis1.undo()
    assert saved_bytes(uis1) == before
    assert {n["id"] for n in undone["nodes"]} >= set(chosen)
    assert not (uis1.path.parent / "library" / "mine.xmi").exists(), "undo removes the new file"
    uis1.redo()
    assert any(n["kind"] == "ModuleUse" for n in uis1.view()["nodes"])
    library = load_library(uis1.path.parent / "library" / "mine.xmi").root
    assert [m.name for m in library.modules] == ["BikeGo"]


def test_undo_puts_an_existing_library_back_byte_for_byte(uis1: EditorSession) -> None:
    shipped = uis1.path.parent / "library" / "sceml-library.xmi"
    before = shipped.read_bytes()
    view = uis1.view()
    chosen = [node_id(view, n) for n in ("Accelerate_2", "Cross_1")]
    op = {"op": "extract_module", "nodes": chosen, "name": "BikeGo", "library": str(shipped)}
    uis1.apply([op])
    assert b"BikeGo" in shipped.read_bytes()
    uis1.undo()
    assert shipped.read_bytes() == before


def test_extract_refuses_a_selection_with_two_exits(uis1: EditorSession) -> None:
    view = uis1.view()
    chosen = [node_id(view, n) for n in ("Accelerate_1", "Accelerate_2")]
    with pytest.raises(OperationError, match="exactly one"):
        uis1.apply([{"op": "extract_module", "nodes": chosen, "name": "X", "library": "lib.xmi"}])
    assert not (uis1.path.parent / "lib.xmi").exists()


def test_a_module_cannot_use_itself(examples_copy: Path) -> None:
    session = EditorSession()
    view = session.open(examples_copy / "library" / "sceml-library.xmi", module="CrossingManeuver")
    listed = [i["module"] for g in view["palette"] for i in g["items"] if i["module"]]
    assert "CrossingManeuver" not in listed and listed, "the module itself is not offered"
    op = {
        "op": "add_module_use",
        "library": "sceml-library.xmi",
        "module": "CrossingManeuver",
        "position": {"x": 0, "y": 0},
    }
    with pytest.raises(OperationError, match="cannot be used inside its own definition"):
        session.apply([op])


def test_expanded_internals_are_named_by_their_use(uis2: EditorSession) -> None:
    inner = [n["name"] for n in uis2.view()["nodes"] if n["parent"] is not None]
    assert "CrossingManeuver_1.Accelerate_1" in inner
    top = {n["name"] for n in uis2.view()["nodes"] if n["parent"] is None}
    assert not top & set(inner), "no label is shown twice"

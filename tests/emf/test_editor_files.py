"""Files the editor saves stay files that real Eclipse EMF reads: positions, new nodes, undone edits."""

from __future__ import annotations

import shutil
from pathlib import Path

from sceml.editor import EditorSession
from sceml.model.compare import differences
from sceml.model.loading import load

from .conftest import ECORE, Harness


def _node_id(view: dict, name: str) -> str:
    return next(n["id"] for n in view["nodes"] if n["name"] == name and not n["parent"])


def test_emf_reads_what_the_editor_saved(emf: Harness, examples_copy: Path, tmp_path: Path) -> None:
    session = EditorSession()
    view = session.open(examples_copy / "uis2-concrete.xmi")
    top = [n for n in view["nodes"] if not n["parent"]]
    moves = {n["id"]: {"x": 10.0 * i, "y": 20.5} for i, n in enumerate(top)}
    view = session.apply([{"op": "move", "positions": moves}])
    view = session.apply(
        [{"op": "add_node", "kind": "Stop", "position": {"x": 5, "y": 6}, "actor": "car"}]
    )
    stop = view["created"][0]
    view = session.apply(
        [{"op": "connect", "source": _node_id(view, "DriveDistance_1"), "target": stop}]
    )
    # A value set and undone must leave no trace (pyecore would write it as xsi:nil).
    accelerate = _node_id(view, "Accelerate_1")
    session.apply([{"op": "set_parameter", "node": accelerate, "field": "rate", "value": None}])
    session.undo()
    session.save()

    saved = examples_copy / "uis2-concrete.xmi"
    assert b"diagramPosition" in saved.read_bytes() and b'name="Stop_1"' in saved.read_bytes()
    out = tmp_path / "emf"
    result = emf.run("roundtrip", ECORE, examples_copy, out, "uis2-concrete.xmi")
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    # What EMF wrote back reads in SceML equal to what the editor saved.
    shutil.copytree(examples_copy / "library", out / "library", dirs_exist_ok=True)
    from_emf = load(out / "uis2-concrete.xmi", allowed_roots=[tmp_path, examples_copy.parent])
    assert differences(load(saved).root, from_emf.root) == []

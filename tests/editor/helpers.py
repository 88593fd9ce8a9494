"""Helpers of the editor tests: the bytes a model saves to, ids by name."""

from __future__ import annotations

from sceml.editor import EditorSession
from sceml.model.saving import save


def saved_bytes(session: EditorSession) -> bytes:
    """What the session's model saves to (beside the file, so relative references stay)."""
    assert session.document is not None
    target = session.path.with_name(".snapshot.xmi")
    save(session.document.root, target)
    return target.read_bytes()


def node_id(view: dict, name: str) -> str:
    """The id of the top-level node called `name` in a view."""
    return next(n["id"] for n in view["nodes"] if n["name"] == name and n["parent"] is None)


def actor_id(view: dict, name: str) -> str:
    """The id of the actor called `name` in a view."""
    return next(a["id"] for a in view["actors"] if a["name"] == name)

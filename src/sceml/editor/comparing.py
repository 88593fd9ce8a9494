"""The editor's comparison of the open scenario with its saved file (issue 29), in the marks and
words of `sceml diff`: which boxes were added or changed since the last save, which were removed,
and every change as one line."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pyecore.ecore import EObject

from ..diff import compare_models
from ..diff.picture import node_actions
from ..diff.words import describe
from ..model.documents import Document
from ..model.loading import load
from .ids import Ids


class SavedComparison:
    """Compares a scenario with the file it was saved to; the saved model is read again only
    when the file changed on disk."""

    def __init__(self, path: Path, roots: list[Path] | None) -> None:
        self.path, self.roots = path, roots
        self._stamp: tuple[int, int] | None = None
        self._saved: Document | None = None

    def _saved_model(self) -> Document | None:
        try:
            stat = self.path.stat()
        except OSError:
            return None  # never saved: everything is new, and there is nothing to compare
        stamp = (stat.st_mtime_ns, stat.st_size)
        if stamp != self._stamp or self._saved is None:
            self._saved = load(self.path, allowed_roots=self.roots)
            self._stamp = stamp
        return self._saved

    def compare(self, scenario: EObject, ids: Ids) -> tuple[dict[str, str], dict[str, Any]]:
        """(node id -> "added" or "changed", the comparison the view reports)."""
        saved = self._saved_model()
        if saved is None:
            return {}, {"against": self.path.name, "saved": False, "changes": [], "removed": []}
        diff = compare_models(saved.root, scenario)
        marks = {}
        for name, action in node_actions(diff.changes).items():
            element = diff.new.nodes.get(name)
            if element is not None:
                marks[ids.of(element.obj, "n")] = action
        removed = [
            c.element
            for c in diff.changes
            if c.action == "removed" and c.part in ("nodes", "modules")
        ]
        report = {
            "against": self.path.name,
            "saved": True,
            "changes": [describe(change) for change in diff.changes],
            "removed": removed,
        }
        return marks, report

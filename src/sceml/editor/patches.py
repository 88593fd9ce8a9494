"""Answer a page with what changed since the view it holds, not the whole view.

At 500 nodes the whole view is about half a megabyte, and a page that receives it must compare
every node to find the one an edit changed. Each view the server answers gets a *revision*: the
same number while its shared content (nodes, edges, actors, problems, palette...) stays the
same, the next one when anything in it changed. The server remembers the last view and the patch
from the revision before it. A page names the revision it holds (the `X-SceML-Revision` header);
if that is the last one or the one before it, the answer is a patch: the view's small fields in
full, and under `patch` only the nodes and edges that changed or were added, the ids of those
removed, and any other shared part that changed, whole. Any other page (a new one, one that
missed a change) gets the whole view. docs/editor-protocol.md, "Patches", describes the format.
"""

from __future__ import annotations

import time
from typing import Any

#: Parts of the view that are lists of entries with an id: patched entry by entry.
KEYED = ("nodes", "edges")
#: Other large parts every tab shares: sent whole when they changed, left out when not.
WHOLE = ("actors", "diagnostics", "palette", "style", "choices", "valueTypes", "comparison")


def _keyed_patch(before: list[dict[str, Any]], after: list[dict[str, Any]]) -> dict[str, Any]:
    """The entries of `after` that differ from `before`'s or are new, the ids that are gone,
    and the order of the ids when the old order less the removed plus the added at the end is
    not it."""
    old = {entry["id"]: entry for entry in before}
    ids = [entry["id"] for entry in after]
    present = set(ids)
    removed = [entry["id"] for entry in before if entry["id"] not in present]
    changed = [entry for entry in after if old.get(entry["id"]) != entry]
    patch: dict[str, Any] = {"changed": changed, "removed": removed}
    kept = [entry["id"] for entry in before if entry["id"] in present]
    added = [entry["id"] for entry in after if entry["id"] not in old]
    if kept + added != ids:
        patch["order"] = ids
    return patch


def diff(before: dict[str, Any], after: dict[str, Any]) -> dict[str, Any] | None:
    """The shared changes from view `before` to view `after`, or None when there are none."""
    patch: dict[str, Any] = {}
    for key in KEYED:
        part = _keyed_patch(before[key], after[key])
        if part["changed"] or part["removed"] or "order" in part:
            patch[key] = part
    for key in WHOLE:
        if before.get(key) != after.get(key):
            patch[key] = after.get(key)
    return patch or None


def small_fields(view: dict[str, Any]) -> dict[str, Any]:
    """The view without its shared large parts: what every answer carries in full."""
    return {key: value for key, value in view.items() if key not in KEYED and key not in WHOLE}


class ViewHistory:
    """The last view answered, its revision, and the patch that led to it."""

    def __init__(self) -> None:
        # Counted from the start time (ms), so that a page still open from an earlier run of the
        # server never holds a revision this run also gives out, and gets the whole view.
        self.revision = time.time_ns() // 1_000_000
        self._last: dict[str, Any] | None = None
        #: The changes from revision `self.revision - 1` to `self.revision`.
        self._patch: dict[str, Any] = {}

    def answer(self, view: dict[str, Any], known: int | None) -> dict[str, Any]:
        """`view` with its revision, as a patch when the page holds `known` and one applies."""
        if self._last is None:
            self.revision += 1
        else:
            changes = diff(self._last, view)
            if changes is not None:
                self.revision += 1
                self._patch = changes
        self._last = view
        view["revision"] = self.revision
        if known == self.revision:
            return {**small_fields(view), "patch": {"base": known}}
        if known is not None and known == self.revision - 1 and self._patch:
            return self.latest_patch(view)
        return view

    def latest_patch(self, view: dict[str, Any]) -> dict[str, Any]:
        """The answer for a page that holds the revision before `view`'s."""
        return {**small_fields(view), "patch": {"base": self.revision - 1, **self._patch}}

    def event(self, tab: str) -> dict[str, Any]:
        """The change event for every other page: the shared small fields (no tab's undo and
        redo labels) and the patch to the newest revision."""
        if self._last is None:
            return {"tab": tab, "revision": self.revision}
        shared = {
            key: value
            for key, value in small_fields(self._last).items()
            if key not in ("undo", "redo", "created")
        }
        return {**shared, "tab": tab, "patch": {"base": self.revision - 1, **self._patch}}

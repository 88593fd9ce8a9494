"""Two versions of a scenario compared, drawn and merged in the model's own terms (SPEC §16).

diff = compare_files("uis2-old.xmi", "uis2.xmi")
for change in diff.changes: print(words.describe(change))
"""

from __future__ import annotations

from pathlib import Path

import scemlmodel as scm

from ..model.collector import collector_paused
from ..model.loading import load_scenario
from .changes import PARTS, Change, Diff, compare
from .snapshot import Snapshot, snapshot

__all__ = [
    "PARTS",
    "Change",
    "Diff",
    "Snapshot",
    "compare",
    "compare_files",
    "compare_models",
    "snapshot",
]


def compare_models(old: scm.Scenario, new: scm.Scenario) -> Diff:
    """Every change from one scenario to another."""
    # A snapshot makes a few tuples per element while both models are alive: the collector
    # would rescan them all again and again (10k nodes: seconds, for nothing to collect).
    with collector_paused():
        return compare(snapshot(old), snapshot(new))


def compare_files(old: str | Path | None, new: str | Path | None) -> Diff:
    """Load two scenario files (each in its own resource set) and compare them.

    None stands for a file that does not exist on that side (git's /dev/null): everything in
    the other one is then added, or removed.
    """
    with collector_paused():
        before = snapshot(_scenario(old)) if old is not None else None
        after = snapshot(_scenario(new)) if new is not None else None
        if before is None and after is None:
            raise ValueError("compare_files needs at least one file")
        return compare(before or _empty(after), after or _empty(before))  # type: ignore[arg-type]


def _empty(like: Snapshot) -> Snapshot:
    return Snapshot(actors={}, nodes={}, flows=[], root=like.root)


def _scenario(path: str | Path) -> scm.Scenario:
    root = load_scenario(path).root
    assert isinstance(root, scm.Scenario)
    return root

"""Metamodel releases and the migration of files saved with older ones (SPEC §15).

Files are migrated as parsed XML, before pyecore decodes them: `upgrade` rewrites the tree of a
file of an older release into the current release by the declared steps in
`metamodel/migrations/`, and returns a `Report` of every change. `check_release` is what CI runs
to refuse a breaking change to the `.ecore` that no migration covers.
"""

from __future__ import annotations

from .history import History, ReleaseCheck, check_release, installed, upgrade
from .report import Change, Report

__all__ = ["Change", "History", "ReleaseCheck", "Report", "check_release", "installed", "upgrade"]

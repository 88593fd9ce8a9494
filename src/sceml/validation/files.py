"""Validating one file as `sceml validate` does: load it, run every rule, report what it found.

A library function so that the command line and any other caller get the same report, including
a file that cannot be read (reported, not raised) and files saved with an older release.
"""

from __future__ import annotations

from pathlib import Path

from ..diagnostics import Diagnostic, Severity
from ..errors import LoadError
from ..model.documents import Document
from ..model.loading import load
from ..report import FileReport
from .engine import OLDER_RELEASE
from .engine import validate as validate_model
from .limits import Limits


def validate_file(
    path: Path,
    limits: Limits,
    osc_version: str | None,
    allow: tuple[Path, ...] = (),
    osc_profile: str | None = None,
    *,
    read_only: bool = True,
    jobs: int = 1,
) -> FileReport:
    """Load and validate one file; an unreadable one is reported, not raised.

    Validation only reads the model, so it is loaded `read_only` (lighter objects) unless told.
    With `jobs` > 1 a large scenario is checked in two processes (`sceml.validation.split`).
    """
    try:
        document = load(path, allow=allow, read_only=read_only)
    except LoadError as error:
        where = f"line {error.line}: " if error.line else ""
        return FileReport(str(path), unreadable=where + error.message)
    diagnostics = validate_model(
        document.root,
        document=document,
        limits=limits,
        osc_version=osc_version,
        osc_profile=osc_profile,
        jobs=jobs,
    )
    return FileReport(str(path), [*older_releases(document), *diagnostics])


def older_releases(document: Document) -> list[Diagnostic]:
    """A warning for each file read (the model, its libraries) saved with an older release."""
    found = []
    for report in document.migrations():
        changes = "; ".join(change.describe() for change in report.changes[:5])
        more = f"; and {len(report.changes) - 5} more" if len(report.changes) > 5 else ""
        found.append(
            Diagnostic(
                Severity.WARNING,
                OLDER_RELEASE,
                f"{report.summary()}{': ' + changes + more if changes else ''}; "
                f"`sceml migrate {report.file} --in-place` rewrites it",
                file=str(report.file),
                line=1,
            )
        )
    return found

"""Check one OpenSCENARIO file: the XSD of its declared version, its positions against the map
its LogicFile names, then ASAM's Quality Checker."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from . import schema
from .diagnostics import Severity
from .errors import SceMLError
from .qualitychecker import quality_diagnostics
from .report import FileReport
from .xosc_map import map_diagnostics


def check_file(path: Path, quality: bool = True, allow: Iterable[Path] = ()) -> FileReport:
    """Every finding on `path` as a Diagnostic; the Quality Checker runs (1.2+) on a file that
    passes its XSD and whose map could be read. A file that cannot be read at all is reported as
    unreadable, not raised. Its LogicFile is read from its folder, its project root and `allow`
    only (`sceml.safefiles.reading_roots`)."""
    try:
        tree = schema.parse_file(path)
        version = schema.declared_version(tree)
    except (SceMLError, OSError) as error:
        reason = error.message if isinstance(error, SceMLError) else str(error.strerror)
        line = getattr(error, "line", None)
        return FileReport(str(path), unreadable=(f"line {line}: " if line else "") + reason)
    diagnostics = [
        issue.diagnostic(version, str(path)) for issue in schema.validate_tree(tree, version)
    ]
    if not diagnostics:
        diagnostics.extend(map_diagnostics(tree, path, allow))
    if quality and not any(d.severity is Severity.ERROR for d in diagnostics):
        diagnostics.extend(quality_diagnostics(path, version))
    return FileReport(str(path), diagnostics)

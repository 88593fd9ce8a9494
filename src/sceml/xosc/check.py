"""Check one OpenSCENARIO file: the XSD of its declared version, its positions against the map
its LogicFile names, then ASAM's Quality Checker."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from ..diagnostics import Diagnostic, Severity
from ..errors import SceMLError
from ..report import FileReport
from . import schema
from .mapcheck import map_diagnostics
from .qualitychecker import quality_diagnostics

#: The largest file ASAM's Quality Checker is run on by default. The bundle is far slower than
#: our own checks on large files (a 20 MB file took 144 s, where the XSD and map checks took
#: 1.8 s); a scenario file is rarely above a few hundred kilobytes.
QUALITY_MAX_BYTES = 4 * 1024 * 1024
QUALITY_SKIPPED = "XOSC-QC-SKIPPED"


def check_file(
    path: Path,
    quality: bool = True,
    allow: Iterable[Path] = (),
    quality_max_bytes: int = QUALITY_MAX_BYTES,
) -> FileReport:
    """Every finding on `path` as a Diagnostic; the Quality Checker runs (1.2+) on a file that
    passes its XSD and whose map could be read, up to `quality_max_bytes` (above, an info says it
    was skipped). A file that cannot be read at all is reported as unreadable, not raised. Its
    LogicFile is read from its folder, its project root and `allow` only
    (`sceml.files.safefiles.reading_roots`)."""
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
        size = path.stat().st_size
        if size > quality_max_bytes:
            diagnostics.append(
                Diagnostic(
                    Severity.INFO,
                    QUALITY_SKIPPED,
                    f"ASAM's Quality Checker was not run: the file is {size / 2**20:.1f} MiB, "
                    f"above {quality_max_bytes / 2**20:.1f} MiB (it is slow on large files; "
                    "--quality-max-mb raises the limit)",
                    file=str(path),
                )
            )
        else:
            diagnostics.extend(quality_diagnostics(path, version))
    return FileReport(str(path), diagnostics)

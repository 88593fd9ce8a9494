"""Rewriting files of older releases as files of the current one (`sceml migrate`)."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..files.writing import write_atomically
from ..migrations.report import Report
from .loading import load
from .saving import save


@dataclass(frozen=True)
class Outcome:
    """What became of one file: the migration's report (None: already current), where it went."""

    source: Path
    written: Path | None
    report: Report | None
    backup: Path | None = None


def migrate_file(
    source: Path,
    output: Path | None = None,
    *,
    backup: bool = False,
    allow: Iterable[Path] = (),
) -> Outcome:
    """Write `source` as a file of the current release to `output` (default: over itself).

    A file already of the current release is left alone when rewritten in place. With `backup`,
    the original bytes are kept beside it as `FILE.<release>.bak` before it is replaced. The
    file is read and written through sceml.model (the same safety and atomic write as every save).
    """
    document = load(source, allow=allow)
    report = document.migration
    target = output if output is not None else source
    if report is None and output is None:
        return Outcome(source, None, None)
    kept = None
    if backup and output is None and report is not None:
        kept = source.with_name(f"{source.name}.{report.from_release}.bak")
        write_atomically(kept, source.read_bytes())
    save(document.root, target, origin=source)
    return Outcome(source, target, report, kept)

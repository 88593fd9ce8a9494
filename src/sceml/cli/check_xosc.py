"""`sceml check-xosc FILE...`: check OpenSCENARIO files against their XSD and ASAM's checker."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from ..report import exit_code, render
from ..xosc.check import QUALITY_MAX_BYTES, check_file
from .common import SceMLCommand, allow_option, emit_report, file_progress, report_options


@click.command("check-xosc", cls=SceMLCommand)
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@report_options(json_help="as `sceml validate --format json`")
@click.option(
    "--no-quality-checker",
    "skip_quality",
    is_flag=True,
    help="Check the XSD only, without ASAM's Quality Checker bundle.",
)
@click.option(
    "--quality-max-mb",
    type=click.FloatRange(min=0),
    default=QUALITY_MAX_BYTES / 2**20,
    show_default=True,
    help="Run ASAM's Quality Checker only on files up to this size (it is slow on large "
    "files); larger ones get an info that it was not run.",
)
@allow_option
def check_xosc(
    files: tuple[Path, ...],
    output_format: str,
    strict: bool,
    skip_quality: bool,
    quality_max_mb: float,
    output: Path | None,
    allow: tuple[Path, ...],
) -> None:
    """Check OpenSCENARIO FILES (.xosc) against the official XSD of their declared version and,
    for 1.2 and later, ASAM's OpenSCENARIO XML Quality Checker bundle.

    Exit status: 0 clean, 1 when a file has errors (with --strict: or warnings), 2 for usage
    errors or files that cannot be read (missing, malformed, DOCTYPE, unknown version).
    """
    with file_progress(files, "checking") as todo:
        reports = [
            check_file(
                path,
                quality=not skip_quality,
                allow=allow,
                quality_max_bytes=int(quality_max_mb * 2**20),
            )
            for path in todo
        ]
    emit_report(render(reports, output_format, strict, tool="sceml check-xosc"), output)
    sys.exit(exit_code(reports, strict))

"""`sceml check-xosc FILE...`: check OpenSCENARIO files against their XSD and ASAM's checker."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .. import schema
from ..diagnostics import Diagnostic, Severity
from ..errors import SceMLError
from ..qualitychecker import QualityCheckerError, run_quality_checker
from ..report import FileReport, exit_code, render
from .common import SceMLCommand, emit_report, file_progress, report_options

XSD_CODE = "XOSC-XSD"
SKIPPED_CODE = "XOSC-QC-SKIPPED"
_LEVELS = {"error": Severity.ERROR, "warning": Severity.WARNING, "information": Severity.INFO}


def check_file(path: Path, quality: bool = True) -> FileReport:
    """XSD of the declared version, then (1.2+) the ASAM Quality Checker; unreadable is reported."""
    try:
        tree = schema.parse_file(path)
        version = schema.declared_version(tree)
    except (SceMLError, OSError) as error:
        reason = error.message if isinstance(error, SceMLError) else str(error.strerror)
        line = getattr(error, "line", None)
        return FileReport(str(path), unreadable=(f"line {line}: " if line else "") + reason)
    diagnostics = [
        Diagnostic(
            Severity.ERROR,
            XSD_CODE,
            f"OpenSCENARIO {version} XSD: {issue.reason}",
            path=issue.path,
            file=str(path),
            line=issue.line,
        )
        for issue in schema.validate_tree(tree, version)
    ]
    if quality and not diagnostics:
        diagnostics.extend(_quality(path, version))
    return FileReport(str(path), diagnostics)


def _quality(path: Path, version: str) -> list[Diagnostic]:
    if version in ("1.0", "1.1"):
        message = (
            f"ASAM Quality Checker rules apply from OpenSCENARIO 1.2; {version} got the XSD only"
        )
        return [Diagnostic(Severity.INFO, SKIPPED_CODE, message, file=str(path))]
    try:
        report = run_quality_checker(path)
    except QualityCheckerError as error:
        return [
            Diagnostic(
                Severity.ERROR,
                "XOSC-QC",
                f"Quality Checker failed: {error.message}",
                file=str(path),
            )
        ]
    return [
        Diagnostic(
            _LEVELS.get(issue.level, Severity.ERROR),
            issue.rule_uid,
            issue.message,
            path=issue.xpath,
            file=str(path),
            line=issue.line,
        )
        for issue in report.issues
    ]


@click.command("check-xosc", cls=SceMLCommand)
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@report_options(json_help="as `sceml validate --format json`")
@click.option(
    "--no-quality-checker",
    "skip_quality",
    is_flag=True,
    help="Check the XSD only, without ASAM's Quality Checker bundle.",
)
def check_xosc(
    files: tuple[Path, ...],
    output_format: str,
    strict: bool,
    skip_quality: bool,
    output: Path | None,
) -> None:
    """Check OpenSCENARIO FILES (.xosc) against the official XSD of their declared version and,
    for 1.2 and later, ASAM's OpenSCENARIO XML Quality Checker bundle.

    Exit status: 0 clean, 1 when a file has errors (with --strict: or warnings), 2 for usage
    errors or files that cannot be read (missing, malformed, DOCTYPE, unknown version).
    """
    with file_progress(files, "checking") as todo:
        reports = [check_file(path, quality=not skip_quality) for path in todo]
    emit_report(render(reports, output_format, strict, tool="sceml check-xosc"), output)
    sys.exit(exit_code(reports, strict))

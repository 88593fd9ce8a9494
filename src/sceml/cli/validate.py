"""`sceml validate FILE...`: check scenarios and libraries against every SceML rule, for people and CI."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import click

from ..errors import LoadError, SceMLError
from ..io import load, write_atomically
from ..report import FileReport, exit_code, render
from ..validation import Limits, load_limits
from ..validation import validate as validate_model
from .common import ReportedError

OSC_VERSIONS = ("1.0", "1.1", "1.2", "1.3")


def validate_file(path: Path, limits: Limits, osc_version: str | None) -> FileReport:
    """Load and validate one file; an unreadable one is reported, not raised."""
    try:
        document = load(path)
    except LoadError as error:
        where = f"line {error.line}: " if error.line else ""
        return FileReport(str(path), unreadable=where + error.message)
    diagnostics = validate_model(
        document.root, document=document, limits=limits, osc_version=osc_version
    )
    return FileReport(str(path), diagnostics)


@contextmanager
def _progress(files: tuple[Path, ...]) -> Iterator[Iterator[Path]]:
    # A bar only helps a person watching many files; CI logs and pipes get none.
    if len(files) > 1 and sys.stderr.isatty():
        with click.progressbar(files, label="validating", file=sys.stderr) as bar:
            yield iter(bar)
    else:
        yield iter(files)


@click.command("validate")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "--format",
    "output_format",
    type=click.Choice(["text", "json", "junit"]),
    default="text",
    show_default=True,
    help="text: compiler-style lines; json: see docs/validation-json.md; junit: JUnit XML, one "
    "testcase per file and one failure per error.",
)
@click.option("--strict", is_flag=True, help="Count warnings as errors (exit 1, JUnit failures).")
@click.option(
    "--limits",
    "limits_file",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    help="YAML or TOML file of plausibility limits per actor kind, laid over the built-in table.",
)
@click.option(
    "--osc-version",
    type=click.Choice(OSC_VERSIONS),
    default=None,
    help="Also check that every node kind of a concrete scenario can be exported to this "
    "OpenSCENARIO version.",
)
@click.option(
    "-o",
    "--output",
    type=click.Path(dir_okay=False, path_type=Path),
    default=None,
    help="Write the report to this file (atomically) instead of standard output.",
)
def validate(
    files: tuple[Path, ...],
    output_format: str,
    strict: bool,
    limits_file: Path | None,
    osc_version: str | None,
    output: Path | None,
) -> None:
    """Validate scenario and library FILES (.xmi) against the SceML rules.

    Every problem is reported with its rule code (docs/validation-rules.md), severity, file, line
    and model path. Module libraries a scenario uses are checked too. Exit status: 0 clean, 1 when
    a file has errors (with --strict: or warnings), 2 for usage errors or unreadable files.
    """
    try:
        limits = load_limits(limits_file) if limits_file is not None else Limits()
        with _progress(files) as todo:
            reports = [validate_file(path, limits, osc_version) for path in todo]
        text = render(reports, output_format, strict)
        if output is not None:
            write_atomically(output, text.encode("utf-8"))
        else:
            click.echo(text, nl=False)
    except SceMLError as error:
        raise ReportedError(error) from None
    sys.exit(exit_code(reports, strict))

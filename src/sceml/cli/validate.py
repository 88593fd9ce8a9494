"""`sceml validate FILE...`: check scenarios and libraries against every SceML rule, for people and CI."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from ..model.collector import collector_off_for_command
from ..report import exit_code, render
from ..validation import Limits, load_limits
from ..validation.files import validate_file
from ..xosc.profiles import PROFILES
from ..xosc.schema import SUPPORTED_VERSIONS
from .common import ReportsMigrations, allow_option, emit_report, file_progress, report_options


@click.command("validate", cls=ReportsMigrations)
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@report_options(json_help="see docs/validation-json.md")
@click.option(
    "--limits",
    "limits_file",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    help="YAML or TOML file of plausibility limits per actor kind, laid over the built-in table.",
)
@click.option(
    "--osc-version",
    type=click.Choice(SUPPORTED_VERSIONS),
    default=None,
    help="Also check that every node kind of a concrete scenario can be exported to this "
    "OpenSCENARIO version.",
)
@click.option(
    "--profile",
    "osc_profile",
    type=click.Choice(PROFILES),
    default=None,
    help="Also check that every node kind of a concrete scenario can be exported with this "
    "export profile (carla: what CARLA scenario_runner runs), at --osc-version or the "
    "profile's default version.",
)
@click.option(
    "-j",
    "--jobs",
    type=click.IntRange(1, 2),
    default=2,
    show_default=True,
    help="Processes to check a large scenario with (2000 nodes or more): 2 splits its checks "
    "over two processes where the machine has two processors, with the same report; 1 keeps "
    "them in this one.",
)
@allow_option
def validate(
    files: tuple[Path, ...],
    output_format: str,
    strict: bool,
    limits_file: Path | None,
    osc_version: str | None,
    output: Path | None,
    allow: tuple[Path, ...],
    osc_profile: str | None,
    jobs: int,
) -> None:
    """Validate scenario and library FILES (.xmi) against the SceML rules.

    Every problem is reported with its rule code (docs/validation-rules.md), severity, file, line
    and model path. Module libraries a scenario uses are checked too. Exit status: 0 clean, 1 when
    a file has errors (with --strict: or warnings), 2 for usage errors or unreadable files.
    """
    limits = load_limits(limits_file) if limits_file is not None else Limits()
    with file_progress(files, "validating") as todo, collector_off_for_command():
        reports = [
            validate_file(path, limits, osc_version, allow, osc_profile, jobs=jobs) for path in todo
        ]
    emit_report(render(reports, output_format, strict), output)
    sys.exit(exit_code(reports, strict))

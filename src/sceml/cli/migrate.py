"""`sceml migrate FILE...`: rewrite files saved with older metamodel releases in the current one."""

from __future__ import annotations

import json
from pathlib import Path

import click

from ..errors import ArgumentError
from ..model.migrating import Outcome, migrate_file
from .common import ReportsMigrations, allow_option


@click.command("migrate", cls=ReportsMigrations)
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    type=click.Path(path_type=Path),
    help="Where to write: a file for one FILE, a folder for several (made if missing).",
)
@click.option("--in-place", is_flag=True, help="Replace each FILE with its migrated version.")
@click.option(
    "--backup",
    is_flag=True,
    help="With --in-place: keep each original beside it as FILE.<release>.bak.",
)
@click.option(
    "--format",
    "output_format",
    type=click.Choice(["text", "json"]),
    default="text",
    show_default=True,
    help="How to print the report of what changed.",
)
@allow_option
def migrate(
    files: tuple[Path, ...],
    output: Path | None,
    in_place: bool,
    backup: bool,
    output_format: str,
    allow: tuple[Path, ...],
) -> None:
    """Rewrite scenario and library FILES saved with an older release of the SceML metamodel.

    Every SceML command reads such files already (migrating them in memory, with a notice);
    this writes them in the current release, so that Eclipse tools with the current .ecore
    read them too. The report lists every change made, with the element and the line it
    was on. The migration steps are in metamodel/migrations/ (docs/metamodel.md).

    Give either --output or --in-place. Exit 0 when every file was written or already current,
    2 for unreadable files or usage errors.
    """
    if in_place == (output is not None):
        raise click.UsageError("give either -o/--output or --in-place")
    if backup and not in_place:
        raise click.UsageError("--backup goes with --in-place")
    if output is not None and len(files) > 1 and output.exists() and not output.is_dir():
        raise ArgumentError(f"{output} is a file; several FILES need a folder for -o")
    outcomes = []
    for source in files:
        target = None
        if output is not None:
            target = output / source.name if len(files) > 1 or output.is_dir() else output
        outcomes.append(migrate_file(source, target, backup=backup, allow=allow))
    if output_format == "json":
        click.echo(json.dumps([_as_json(o) for o in outcomes], indent=2))
        return
    for outcome in outcomes:
        for line in _as_text(outcome):
            click.echo(line)


def _as_text(outcome: Outcome) -> list[str]:
    report = outcome.report
    if report is None:
        where = f"; written to {outcome.written}" if outcome.written else "; left as it is"
        return [f"{outcome.source}: already of the current metamodel release{where}"]
    lines = [
        f"{outcome.source}: release {report.from_release} -> {report.to_release}, "
        f"{len(report.changes)} change(s); written to {outcome.written}"
    ]
    if outcome.backup is not None:
        lines.append(f"  original kept as {outcome.backup}")
    lines.extend(f"  {change.describe()}" for change in report.changes)
    return lines


def _as_json(outcome: Outcome) -> dict[str, object]:
    report = outcome.report
    return {
        "file": str(outcome.source),
        "written": str(outcome.written) if outcome.written else None,
        "backup": str(outcome.backup) if outcome.backup else None,
        "migration": report.to_json() if report is not None else None,
    }

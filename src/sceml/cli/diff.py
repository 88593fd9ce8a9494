"""`sceml diff OLD NEW`: what changed in a scenario, in its own terms, for a person, a tool or CI."""

from __future__ import annotations

from pathlib import Path

import click

from ..diff import Change, compare_files
from ..diff.reports import FORMATS, DiffReport
from .common import SceMLCommand, emit_report, output_file

#: What git passes a `diff.<driver>.command`: path old-file old-hex old-mode new-file new-hex new-mode.
GIT_ARGUMENTS = 7


@click.command(cls=SceMLCommand)
@click.argument("files", nargs=-1, required=True, metavar="OLD NEW")
@click.option(
    "--format",
    "output_format",
    type=click.Choice([*FORMATS, "html"]),
    default="text",
    show_default=True,
    help="text: a heading per part, one line per change; json: for tools (docs/diff.md); "
    "markdown: a pull-request comment; junit: one test case per change, failing when it "
    "touches an --exit-code part; html: the new diagram with the changes marked, listed beside it.",
)
@output_file(
    "Write the report to this file (atomically) instead of standard output.", required=False
)
@click.option(
    "--no-layout",
    is_flag=True,
    help="Leave out changes of diagram positions only (they never change what a scenario means).",
)
@click.option(
    "--exit-code",
    "guarded",
    multiple=True,
    metavar="PART",
    help="Exit 1 when a change touches PART: root, actors, nodes, modules, flows or layout, the "
    "name of a node or actor, or `any` for any change; repeatable. For a pull-request job that "
    "guards a released scenario.",
)
@click.option(
    "--git",
    "git_driver",
    is_flag=True,
    help="Take the seven arguments git passes a diff driver (path, old file, hash, mode, new "
    "file, hash, mode) instead of OLD NEW; `sceml git-setup` configures this.",
)
def diff(
    files: tuple[str, ...],
    output_format: str,
    output: Path | None,
    no_layout: bool,
    guarded: tuple[str, ...],
    git_driver: bool,
) -> None:
    """Show what changed from scenario OLD to scenario NEW, by name and path.

    Changes are listed in the model's own terms: root settings, actors, nodes, module uses and
    their bindings, flows, parameters with their values, ranges and distributions
    (`TurnLeft_1.destination.x: -34 -> -30 m`), never by XML position. A renamed node or actor is
    shown as renamed. Diagram positions are listed apart, under Layout.

    Exits 0 (whatever changed) unless --exit-code names a part a change touches (1); 2 when a
    file cannot be read.
    """
    old, new, label_old, label_new = _inputs(files, git_driver)
    found = compare_files(old, new)
    changes = [c for c in found.changes if not (no_layout and c.part == "layout")]
    report = DiffReport(label_old, label_new, changes, _guards(guarded, changes))
    if output_format == "html":
        from ..diff.picture import diff_page  # graphviz loads only when a picture is asked for

        text = diff_page(found, report)
    else:
        text = FORMATS[output_format](report)
    emit_report(text, output)
    if report.blocked:
        raise click.exceptions.Exit(1)


def _inputs(files: tuple[str, ...], git_driver: bool) -> tuple[Path | None, Path | None, str, str]:
    if git_driver:
        if len(files) != GIT_ARGUMENTS:
            raise click.UsageError(f"--git takes the {GIT_ARGUMENTS} arguments git passes a driver")
        name = files[0]
        return _git_file(files[1]), _git_file(files[4]), f"a/{name}", f"b/{name}"
    if len(files) != 2:
        raise click.UsageError("give two scenario files: OLD NEW")
    for given in files:
        if not Path(given).is_file():
            raise click.BadParameter(f"no file {given!r}", param_hint="OLD NEW")
    return Path(files[0]), Path(files[1]), files[0], files[1]


def _git_file(given: str) -> Path | None:
    """git names a file that does not exist on one side (added, deleted) /dev/null."""
    return None if given == "/dev/null" else Path(given)


def _guards(guarded: tuple[str, ...], changes: list[Change]) -> tuple[str, ...]:
    """`any` guards every part a change is in."""
    if "any" in guarded:
        return tuple(dict.fromkeys([*guarded, *(c.part for c in changes)]))
    return guarded

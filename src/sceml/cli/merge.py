"""`sceml merge BASE OURS THEIRS -o OUT`: a three-way merge of scenarios, in the model's terms."""

from __future__ import annotations

from pathlib import Path

import click

import scemlmodel as scm

from ..diff.merge import merge as merge_models
from ..model.loading import load_scenario
from ..model.saving import save
from .common import SceMLCommand, output_file


def _scenario_file() -> click.Path:
    return click.Path(exists=True, dir_okay=False, path_type=Path)


def _scenario(path: Path) -> scm.Scenario:
    root = load_scenario(path).root
    assert isinstance(root, scm.Scenario)
    return root


@click.command(cls=SceMLCommand)
@click.argument("base", type=_scenario_file())
@click.argument("ours", type=_scenario_file())
@click.argument("theirs", type=_scenario_file())
@output_file(
    "Where to write the merged scenario (atomically; may be OURS itself, as git's merge "
    "driver does). Nothing is written when there is a conflict.",
    metavar="OUT",
)
@click.option(
    "--name",
    default=None,
    metavar="PATH",
    help="The file's name in messages (git's %P), instead of OURS.",
)
@click.option(
    "--no-validate",
    is_flag=True,
    help="Do not validate the merged scenario (validation errors that neither side had are "
    "conflicts otherwise).",
)
def merge(
    base: Path, ours: Path, theirs: Path, output: Path, name: str | None, no_validate: bool
) -> None:
    """Merge the changes from BASE to THEIRS into OURS, and write the result to OUT.

    Changes to different things merge; the same change on both sides is one change. A conflict
    (two values for one parameter, two new names for one node, a node deleted on one side and
    edited on the other, flows that together make a cycle, validation errors that neither side
    had) is listed with both sides on standard error, and nothing is written: exit 1. Exit 0
    when the merge is written, 2 when a file cannot be read.
    """
    # Each file in its own resource set: the three versions share names, not objects.
    roots = [_scenario(path) for path in (base, ours, theirs)]
    result = merge_models(roots[0], roots[1], roots[2], validate=not no_validate)
    label = name or str(ours)
    if not result.ok:
        for conflict in result.conflicts:
            click.echo(f"{label}: conflict: {conflict}", err=True)
        click.echo(f"{label}: {len(result.conflicts)} conflict(s); nothing written", err=True)
        raise click.exceptions.Exit(1)
    save(result.scenario, output, origin=ours)
    click.echo(f"{label}: merged ({len(result.taken)} change(s) from THEIRS) into {output}")

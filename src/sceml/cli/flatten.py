"""`sceml flatten FILE -o OUT`: expand every module use of a scenario into plain nodes."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import SceMLError
from ..modules import flatten_file
from .common import ReportedError


@click.command()
@click.argument("file", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    required=True,
    type=click.Path(dir_okay=False, path_type=Path),
    help="Where to write the flattened scenario (written atomically; may be FILE itself).",
)
@click.option(
    "--allow",
    "allowed",
    multiple=True,
    type=click.Path(file_okay=False, path_type=Path),
    help="Another folder that referenced libraries may be read from (repeatable); by default "
    "only FILE's folder and those below it.",
)
def flatten(file: Path, output: Path, allowed: tuple[Path, ...]) -> None:
    """Expand every module use in scenario FILE, recursively, and save the result as OUT.

    Expanded nodes are named after the use that holds them, e.g.
    `CrossingManeuver_1.Accelerate_1`; roles are replaced by the bound actors, parameters by the
    use's overrides or the module's defaults. The output refers to no library.
    """
    try:
        report = flatten_file(file, output, allowed_roots=allowed)
    except SceMLError as error:
        # Registered on the main group this is caught there too; alone it must report itself.
        raise ReportedError(error) from None
    count = len(report.expanded)
    names = f" ({', '.join(report.expanded)})" if count else ""
    click.echo(f"{report.output}: {report.nodes} nodes; {count} module uses expanded{names}")

"""`sceml flatten FILE -o OUT`: expand every module use of a scenario into plain nodes."""

from __future__ import annotations

from pathlib import Path

import click

from ..modules import flatten_file
from .common import SceMLCommand, allow_option, input_file, output_file


@click.command(cls=SceMLCommand)
@input_file()
@output_file(
    "Where to write the flattened scenario (written atomically; may be FILE itself).", metavar="OUT"
)
@allow_option
def flatten(file: Path, output: Path, allow: tuple[Path, ...]) -> None:
    """Expand every module use in scenario FILE, recursively, and save the result as OUT.

    Expanded nodes are named after the use that holds them, e.g.
    `CrossingManeuver_1.Accelerate_1`; roles are replaced by the bound actors, parameters by the
    use's overrides or the module's defaults. The output refers to no library.
    """
    report = flatten_file(file, output, allowed_roots=allow)
    count = len(report.expanded)
    names = f" ({', '.join(report.expanded)})" if count else ""
    click.echo(f"{report.output}: {report.nodes} nodes; {count} module uses expanded{names}")

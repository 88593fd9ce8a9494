"""`sceml promote FILE --ranges RANGES.yaml -o OUT`: make a functional scenario logical."""

from __future__ import annotations

from pathlib import Path

import click

from ..levels.paths import UnknownPathError
from ..levels.promote import load_ranges
from ..levels.promote import promote as make_logical
from ..model.loading import load_scenario
from ..model.saving import save
from .common import SceMLCommand, allow_option, input_file, output_file
from .concretize import report_validation


@click.command(cls=SceMLCommand)
@input_file()
@click.option(
    "--ranges",
    "ranges_file",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    metavar="RANGES",
    required=True,
    help="YAML (or .json) file mapping parameter paths to values, ranges, distributions or "
    "positions; see examples/uis1-ranges.yaml and docs/levels.md.",
)
@output_file("Where to write the logical scenario (.xmi); written atomically.", metavar="OUT")
@allow_option
def promote(file: Path, ranges_file: Path, output: Path, allow: tuple[Path, ...]) -> None:
    """Promote FILE to the logical level with the ranges and distributions in RANGES.

    Every required parameter and every position must be given (by FILE or by RANGES); the
    result is validated and written to OUT.
    """
    ranges = load_ranges(ranges_file)
    document = load_scenario(file, allow=allow)
    try:
        result = make_logical(document.root, ranges, source=ranges_file)
    except UnknownPathError as error:
        error.file = error.file or str(ranges_file)
        raise
    save(result, output, origin=file)
    click.echo(f"wrote {output}")
    report_validation(result, output)

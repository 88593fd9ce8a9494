"""`sceml export-distribution LOGICAL -o DIR`: a parameterized .xosc and its distribution file."""

from __future__ import annotations

from pathlib import Path

import click

from ..errors import SceMLError
from ..levels.pvd import MODES, export_distribution
from .common import ReportedError


@click.command("export-distribution")
@click.argument("logical", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option(
    "-o",
    "--output",
    "out_dir",
    type=click.Path(file_okay=False, path_type=Path),
    required=True,
    help="Folder for <name>.xosc (parameterized) and <name>.pvd.xosc (the distribution).",
)
@click.option(
    "--osc-version",
    type=click.Choice(["1.0", "1.1", "1.2", "1.3"]),
    default="1.3",
    show_default=True,
    help="OpenSCENARIO version; 1.0 has no distributions and is refused.",
)
@click.option(
    "--mode",
    type=click.Choice(MODES),
    default="auto",
    show_default=True,
    help="deterministic (ranges with steps and sets: a full factorial), stochastic "
    "(distributions, with a seed), or auto: deterministic when every varied parameter allows it.",
)
@click.option(
    "--runs",
    type=click.IntRange(min=1),
    default=100,
    show_default=True,
    help="numberOfTestRuns of a stochastic distribution.",
)
@click.option(
    "--seed", type=click.IntRange(min=0), default=0, show_default=True, help="randomSeed."
)
@click.option(
    "--date", default=None, help="FileHeader date (xsd:dateTime) [default: the model's date]."
)
def export_distribution_command(
    logical: Path,
    out_dir: Path,
    osc_version: str,
    mode: str,
    runs: int,
    seed: int,
    date: str | None,
) -> None:
    """Export the logical scenario LOGICAL as OpenSCENARIO parameters (1.1 and later).

    Writes a .xosc in which every varied parameter is a declared `$parameter` at its nominal
    value, and a ParameterValueDistribution file that refers to it. Both are checked against
    the official XSD before they are written.
    """
    try:
        files = export_distribution(
            logical, out_dir, version=osc_version, mode=mode, runs=runs, seed=seed, date=date
        )
    except SceMLError as error:
        raise ReportedError(error) from None
    click.echo(f"wrote {files.scenario}")
    click.echo(f"wrote {files.distribution} ({files.kind})")

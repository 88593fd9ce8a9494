"""`sceml export-distribution LOGICAL -o DIR`: a parameterized .xosc and its distribution file."""

from __future__ import annotations

from pathlib import Path

import click

from ..export.writer import header_date
from ..levels.pvd import MODES, export_distribution
from ..xosc.schema import DISTRIBUTION_VERSIONS
from .common import Parsed, SceMLCommand, allow_option, input_file, output_folder


@click.command("export-distribution", cls=SceMLCommand)
@input_file("logical")
@output_folder("Folder for <name>.xosc (parameterized) and <name>.pvd.xosc (the distribution).")
@click.option(
    "--osc-version",
    type=click.Choice(DISTRIBUTION_VERSIONS),
    default=DISTRIBUTION_VERSIONS[-1],
    show_default=True,
    help="OpenSCENARIO version (distributions came with 1.1).",
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
    "--date",
    type=Parsed("ISO", header_date),
    default=None,
    help="FileHeader date (ISO 8601) [default: the model's date].",
)
@allow_option
def export_distribution_command(
    logical: Path,
    out_dir: Path,
    osc_version: str,
    mode: str,
    runs: int,
    seed: int,
    date: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Export the logical scenario LOGICAL as OpenSCENARIO parameters (1.1 and later).

    Writes a .xosc in which every varied parameter is a declared `$parameter` at its nominal
    value, and a ParameterValueDistribution file that refers to it. Both are checked against
    the official XSD before they are written.
    """
    files = export_distribution(
        logical,
        out_dir,
        version=osc_version,
        mode=mode,
        runs=runs,
        seed=seed,
        date=date,
        allow=allow,
    )
    click.echo(f"wrote {files.scenario}")
    click.echo(f"wrote {files.distribution} ({files.kind})")

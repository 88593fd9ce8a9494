"""`sceml check-run MODEL --log LOG [--csv CSV]`: did a player's run keep the scenario's meaning?"""

from __future__ import annotations

import sys
from pathlib import Path

import click

from ..players.check import READERS, check_player_run, format_report
from ..xosc.schema import SUPPORTED_VERSIONS
from .common import SceMLCommand, allow_option, input_file


@click.command(cls=SceMLCommand)
@input_file("model")
@click.option(
    "--log",
    "log_path",
    required=True,
    metavar="LOG",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    help="The player's log of the run (esmini: --logfile_path).",
)
@click.option(
    "--csv",
    "csv_path",
    metavar="CSV",
    type=click.Path(exists=True, dir_okay=False, path_type=Path),
    default=None,
    help="The player's trace of the actors (esmini: --csv_logger); without it goals at each "
    "finish and teleports are not checked.",
)
@click.option(
    "--player",
    type=click.Choice(sorted(READERS)),
    default="esmini",
    show_default=True,
    help="Whose log and trace formats to read.",
)
@click.option(
    "--osc-version",
    type=click.Choice(SUPPORTED_VERSIONS),
    default=None,
    help="The OpenSCENARIO version MODEL was exported at [default: the one the log names].",
)
@allow_option
def check_run(
    model: Path,
    log_path: Path,
    csv_path: Path | None,
    player: str,
    osc_version: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Check that a player's run of MODEL's export kept the scenario's meaning.

    MODEL is the concrete scenario that was exported (sceml export) and played, e.g. with
    `esmini --headless --osc F.xosc --fixed_timestep 0.05 --logfile_path LOG --csv_logger CSV`.
    The run is checked against MODEL's graph: every node started only after its predecessors
    finished, every node the end node waits for finished, the end node stopped the run (not
    the time-out), each goal held when its node finished (speeds, distances, destinations,
    gaps, lanes), no actor jumped, and the player cut no maneuver short.

    Prints each node's start and finish and every violation. Exit 0 when the run kept the
    scenario's meaning, 1 when not, 2 when a file cannot be read.
    """
    report = check_player_run(
        model, log_path, csv_path, player=player, version=osc_version, allow=allow
    )
    click.echo(format_report(report))
    if not report.ok:
        sys.exit(1)

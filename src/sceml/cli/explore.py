"""`sceml explore LOGICAL --metric M --budget N -o DIR`: find the critical concrete scenarios."""

from __future__ import annotations

import sys
from contextlib import nullcontext
from pathlib import Path

import click

from ..executors import check
from ..levels.counts import parse_count
from ..model.loading import load_scenario
from ..xosc import PLAYER_STEP
from .common import (
    Parsed,
    SceMLCommand,
    allow_option,
    executor_options,
    input_file,
    output_folder,
    seed_option,
    workers_option,
    written_version_option,
)

_METRICS = ("min-ttc", "min-distance", "collision", "pet")


# Runs in this process unless asked otherwise, as before the executors (sample's default is
# processes): a batch is a tenth of the budget at a few ms per run and starts its workers
# afresh, so small searches gain little from more (figures in docs/simulate.md).
@click.command(cls=SceMLCommand, context_settings={"default_map": {"executor": "local"}})
@input_file("logical")
@click.option(
    "--metric",
    type=click.Choice(_METRICS),
    default="collision",
    show_default=True,
    help="What critical means (over every pair of actors): the least time to collision, the "
    "least distance between boxes, a collision (near misses rank next), the least "
    "post-encroachment time.",
)
@click.option(
    "--budget",
    type=Parsed("N", parse_count),
    default=200,
    show_default=True,
    help="Runs in all (at least 2): 200, 1e4 or 2^12. A budget whose runs this machine's free "
    "memory cannot hold is refused.",
)
@seed_option
@output_folder("Folder for runs.csv, parameter-space.png and the critical scenarios.")
@click.option(
    "--top",
    type=click.IntRange(min=0),
    default=10,
    show_default=True,
    help="How many of the most critical runs to write as concrete .xmi and .xosc.",
)
@written_version_option("OpenSCENARIO version of the .xosc files.")
@click.option(
    "--step", type=click.FloatRange(min=0.001, max=1.0), default=PLAYER_STEP, show_default=True
)
@workers_option
@executor_options
@allow_option
def explore_command(
    logical: Path,
    metric: str,
    budget: int,
    seed: int,
    out_dir: Path,
    top: int,
    osc_version: str,
    step: float,
    workers: int | None,
    executor: str,
    scheduler: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Search the logical scenario LOGICAL for its most critical concrete scenarios.

    Half the budget is a Latin hypercube over the varied parameters; the rest refines towards
    the most critical runs (cross-entropy), seeded: the same seed gives the same runs. Each run
    is the kinematic preview of `sceml simulate` (docs/simulate.md). Writes DIR/runs.csv (every
    run, its values and metrics), DIR/parameter-space.png, and the --top most critical runs as
    DIR/<name>_critical_NN.xmi and .xosc.

    Each batch of runs (the design, then each refinement) is simulated on --executor; the runs,
    and so every file written, are the same whichever executor runs them.
    """
    from ..explore.to_folder import ExploreRequest, check_budget, explore_to_folder

    check(executor, scheduler)
    document = load_scenario(logical, allow=allow)
    if budget < 2:
        raise click.BadParameter("the budget must allow at least 2 runs", param_hint="'--budget'")
    check_budget(document, budget, step)
    request = ExploreRequest(metric, budget, seed, step, top, osc_version, allow)
    # The bar is for a person watching; logs and pipes get none.
    bar = (
        click.progressbar(length=budget, label="exploring", file=sys.stderr)
        if sys.stderr.isatty()
        else None
    )
    try:
        with bar if bar is not None else nullcontext():
            outcome = explore_to_folder(
                document,
                logical,
                out_dir,
                request,
                executor=executor,
                scheduler=scheduler,
                workers=workers,
                progress=bar.update if bar is not None else None,
            )
    except KeyboardInterrupt:  # as sample: 130, and what became of the outputs
        click.echo("Interrupted: no output was written.", err=True)
        raise click.exceptions.Exit(130) from None
    found = outcome.exploration
    click.echo(
        f"{len(found.evaluations)} runs ({outcome.failed} failed), "
        f"{outcome.collisions} with a collision; metric {metric}"
    )
    for rank, critical in enumerate(outcome.critical, start=1):
        evaluation = critical.evaluation
        values = ", ".join(
            f"{p}={v:.4g}" for p, v in zip(found.space.paths, evaluation.values, strict=True)
        )
        click.echo(f"  #{rank} score {evaluation.score:.3g}: {values} -> {critical.files[0].name}")
        if critical.problem:
            click.echo(f"    no .xosc: {critical.problem}", err=True)
    click.echo(f"wrote {outcome.runs_csv}, {outcome.plot}")

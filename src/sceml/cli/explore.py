"""`sceml explore LOGICAL --metric M --budget N -o DIR`: find the critical concrete scenarios."""

from __future__ import annotations

import sys
from contextlib import nullcontext
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..executors import Executor, check, open_executor
from ..files.outputset import output_set
from ..files.writing import make_folder, remove_folders, write_atomically
from ..levels.counts import parse_count
from ..model.documents import Document
from ..model.loading import load_scenario
from ..xosc.schema import SUPPORTED_VERSIONS
from .common import (
    Parsed,
    SceMLCommand,
    allow_option,
    executor_options,
    input_file,
    output_folder,
    seed_option,
)

if TYPE_CHECKING:
    from ..explore import Exploration

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
@click.option(
    "--osc-version",
    type=click.Choice(SUPPORTED_VERSIONS),
    default=SUPPORTED_VERSIONS[-1],
    show_default=True,
    help="OpenSCENARIO version of the .xosc files.",
)
@click.option("--step", type=click.FloatRange(min=0.001, max=1.0), default=0.05, show_default=True)
@click.option(
    "--workers",
    type=click.IntRange(min=1),
    default=None,
    help="Worker processes of the processes executor, or of the dask executor's LocalCluster "
    "[default: the number of CPUs].",
)
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
    from ..explore.outputs import plot_space, runs_csv, write_critical

    check(executor, scheduler)
    document = load_scenario(logical, allow=allow)
    _check_budget(document, budget, step)
    # Made before the search, so that an output that cannot be written fails now, not after it.
    created = make_folder(out_dir)
    try:
        with open_executor(executor, workers=workers, scheduler=scheduler) as runner:
            found = _search(
                document, logical, runner, allow, metric=metric, budget=budget, seed=seed, step=step
            )
        # All outputs or none: a plot that fails must not leave runs.csv alone.
        with output_set() as outputs:
            runs = outputs.stage(out_dir / "runs.csv")
            write_atomically(runs, runs_csv(found).encode("utf-8"))
            plot_space(found, outputs.stage(out_dir / "parameter-space.png"))
            critical = write_critical(
                found, document.root, logical, out_dir, top, osc_version, stage=outputs.stage
            )
    except BaseException as error:
        remove_folders(created)  # where nothing was written
        if isinstance(error, KeyboardInterrupt):  # as sample: 130, and what became of the outputs
            click.echo("Interrupted: no output was written.", err=True)
            raise click.exceptions.Exit(130) from None
        raise
    ran = [e for e in found.evaluations if e.run is not None]
    collisions = sum(1 for e in ran if e.run is not None and e.run.collided)
    click.echo(
        f"{len(found.evaluations)} runs ({len(found.evaluations) - len(ran)} failed), "
        f"{collisions} with a collision; metric {metric}"
    )
    for rank, (evaluation, files, problem) in enumerate(critical, start=1):
        values = ", ".join(
            f"{p}={v:.4g}" for p, v in zip(found.space.paths, evaluation.values, strict=True)
        )
        click.echo(f"  #{rank} score {evaluation.score:.3g}: {values} -> {files[0].name}")
        if problem:
            click.echo(f"    no .xosc: {problem}", err=True)
    click.echo(f"wrote {out_dir / 'runs.csv'}, {out_dir / 'parameter-space.png'}")


def _check_budget(document: Document, budget: int, step: float) -> None:
    """Refuse, before anything runs, a budget whose runs would not fit in memory."""
    from ..levels.counts import check_count
    from ..simulate.limits import run_samples

    if budget < 2:
        raise click.BadParameter("the budget must allow at least 2 runs", param_hint="'--budget'")
    # Each run keeps its trajectories (about 40 bytes a sample) for the ranking and the plot.
    each = 40 * run_samples(document.root, step) + 8192
    check_count(budget, "runs", memory_each=each, hint="ask for fewer with --budget")


def _search(
    document: Document,
    logical: Path,
    runner: Executor,
    allow: tuple[Path, ...],
    *,
    metric: str,
    budget: int,
    seed: int,
    step: float,
) -> Exploration:
    """The search, with a progress bar when a person is watching."""
    from ..explore import explore

    bar = (
        click.progressbar(length=budget, label="exploring", file=sys.stderr)
        if sys.stderr.isatty()
        else None
    )
    with bar if bar is not None else nullcontext():
        return explore(
            document.root,
            logical,
            metric=metric,
            budget=budget,
            seed=seed,
            step=step,
            progress=bar.update if bar is not None else None,
            executor=runner,
            allow=allow,
        )

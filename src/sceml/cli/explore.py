"""`sceml explore LOGICAL --metric M --budget N -o DIR`: find the critical concrete scenarios."""

from __future__ import annotations

import sys
from contextlib import nullcontext
from pathlib import Path

import click

from ..io import load_scenario, write_atomically
from ..schema import SUPPORTED_VERSIONS
from .common import SceMLCommand, allow_option

_METRICS = ("min-ttc", "min-distance", "collision", "pet")


@click.command(cls=SceMLCommand)
@click.argument("logical", type=click.Path(exists=True, dir_okay=False, path_type=Path))
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
    "--budget", type=click.IntRange(min=2), default=200, show_default=True, help="Runs in all."
)
@click.option("--seed", type=click.IntRange(min=0), default=0, show_default=True, help="Seed.")
@click.option(
    "-o",
    "--output",
    "out_dir",
    type=click.Path(file_okay=False, path_type=Path),
    metavar="DIR",
    required=True,
    help="Folder for runs.csv, parameter-space.png and the critical scenarios.",
)
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
    allow: tuple[Path, ...],
) -> None:
    """Search the logical scenario LOGICAL for its most critical concrete scenarios.

    Half the budget is a Latin hypercube over the varied parameters; the rest refines towards
    the most critical runs (cross-entropy), seeded: the same seed gives the same runs. Each run
    is the kinematic preview of `sceml simulate` (docs/simulate.md). Writes DIR/runs.csv (every
    run, its values and metrics), DIR/parameter-space.png, and the --top most critical runs as
    DIR/<name>_critical_NN.xmi and .xosc.
    """
    from ..explore import explore
    from ..explore.outputs import plot_space, runs_csv, write_critical

    document = load_scenario(logical, allow=allow)
    bar = (
        click.progressbar(length=budget, label="exploring", file=sys.stderr)
        if sys.stderr.isatty()
        else None
    )
    with bar if bar is not None else nullcontext():
        found = explore(
            document.root,
            logical,
            metric=metric,
            budget=budget,
            seed=seed,
            step=step,
            progress=bar.update if bar is not None else None,
        )
    write_atomically(out_dir / "runs.csv", runs_csv(found).encode("utf-8"))
    plot_space(found, out_dir / "parameter-space.png")
    critical = write_critical(found, document.root, logical, out_dir, top, osc_version)
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

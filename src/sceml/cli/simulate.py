"""`sceml simulate FILE [-o RUN.html] [--csv T.csv] [--json S.json]`: watch a scenario move."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import click

from ..model.loading import load_scenario
from ..simulate import DEFAULT_STEP, Run, simulate
from ..simulate.outputs import write_run
from ..simulate.timeline import shown_nodes
from .common import SceMLCommand, allow_option, input_file, output_file

#: Runs with more steps than this show a progress bar (when a person is watching).
_BAR_STEPS = 2000


@click.command(cls=SceMLCommand)
@input_file()
@output_file(
    "The preview page (HTML, self-contained) [default: FILE's name with -preview.html, "
    "in the current folder].",
    required=False,
)
@click.option(
    "--csv",
    "csv_path",
    type=click.Path(dir_okay=False, path_type=Path),
    default=None,
    help="Also write the trajectories: time, actor, x, y, heading, speed per sample.",
)
@click.option(
    "--json",
    "json_path",
    type=click.Path(dir_okay=False, path_type=Path),
    default=None,
    help="Also write a JSON summary: how the run ended, the timeline, the metrics.",
)
@click.option(
    "--step",
    type=click.FloatRange(min=0.001, max=1.0),
    default=DEFAULT_STEP,
    show_default=True,
    help="Time step in seconds.",
)
@allow_option
def simulate_command(
    file: Path,
    output: Path | None,
    csv_path: Path | None,
    json_path: Path | None,
    step: float,
    allow: tuple[Path, ...],
) -> None:
    """Play the concrete scenario FILE in the kinematic preview.

    Actors follow their lanes, turn through the junction's connections, change lanes, cross
    and follow trajectories at the speeds the scenario sets; each node starts and finishes by
    the SceML semantics. Writes a page that plays the run over the map (with the timeline of
    the nodes and the conflict metrics of every pair of actors) and prints a summary.

    A preview, not a vehicle-dynamics simulator: docs/simulate.md says what it models. Exit 0
    when it ran, 2 when FILE cannot be simulated (not concrete, a position off the map).
    """
    document = load_scenario(file, allow=allow)
    with _progress() as progress:
        run = simulate(document.root, file, step=step, progress=progress)
    page = output or Path(f"{file.stem}-preview.html")
    written = write_run(run, document.root, file, page, csv_path, json_path)
    for line in describe(run):
        click.echo(line)
    click.echo(f"wrote {', '.join(map(str, written))}")


def describe(run: Run) -> Iterator[str]:
    """The run in a few lines: how it ended, each node's times, each pair's metrics."""
    yield f"{run.scenario}: ended at {run.end_time:.2f} s by the {run.end_reason}"
    for record in shown_nodes(run):
        start = "-" if record.started is None else f"{record.started:.2f}"
        finish = "-" if record.finished is None else f"{record.finished:.2f}"
        note = f"  ({record.note})" if record.note else ""
        yield f"  {record.name:<44} {start:>7} -> {finish:>7} s{note}"
    for m in run.metrics:
        ttc = "-" if m.min_ttc is None else f"{m.min_ttc:.2f} s"
        pet = "-" if m.pet is None else f"{m.pet:.2f} s"
        hit = f"COLLISION at {m.collision_time:.2f} s" if m.collision else "no collision"
        yield f"  {m.a}-{m.b}: least distance {m.min_distance:.2f} m, least TTC {ttc}, PET {pet}, {hit}"
    for note in run.notes:
        yield f"  note: {note}"


@contextmanager
def _progress() -> Iterator[Callable[[int, int], None] | None]:
    """A progress callback drawing a bar on a terminal; None in pipes and CI logs."""
    if not sys.stderr.isatty():
        yield None
        return
    state: dict[str, object] = {}

    def advance(done: int, total: int) -> None:
        if total < _BAR_STEPS:
            return
        bar = state.get("bar")
        if bar is None:
            bar = click.progressbar(length=total, label="simulating", file=sys.stderr)
            bar.__enter__()
            state["bar"], state["shown"] = bar, 0
        bar.update(done - int(state["shown"]))  # type: ignore[attr-defined, call-overload]
        state["shown"] = done

    try:
        yield advance
    finally:
        bar = state.get("bar")
        if bar is not None:
            bar.__exit__(None, None, None)  # type: ignore[attr-defined]

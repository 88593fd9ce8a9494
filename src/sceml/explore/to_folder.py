"""A search written to a folder: the workflow `sceml explore` runs.

    check_budget(document, budget, step)                  # refused before anything runs
    outcome = explore_to_folder(document, path, out_dir, ExploreRequest(...), progress=bar.update)

The folder gets runs.csv (every run), parameter-space.png and the most critical runs as
concrete .xmi and .xosc: all of them or, if anything fails or the search is cut short, none
(a folder made for them is removed again). Nothing here prints.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..executors import open_executor
from ..files.outputset import output_set
from ..files.writing import make_folder, remove_folders, write_atomically
from ..levels.counts import check_count
from ..model.documents import Document
from ..simulate.limits import run_samples
from ..xosc import PLAYER_STEP
from ..xosc.profiles import DEFAULT_VERSION
from .outputs import plot_space, runs_csv, write_critical
from .search import Evaluation, Exploration, explore

#: The file names of the outputs besides the critical runs.
RUNS_CSV = "runs.csv"
SPACE_PLOT = "parameter-space.png"


@dataclass(frozen=True)
class ExploreRequest:
    """What to search for and how: the options of `sceml explore`."""

    metric: str = "collision"
    budget: int = 200
    seed: int = 0
    step: float = PLAYER_STEP
    #: How many of the most critical runs to write as concrete scenarios.
    top: int = 10
    osc_version: str = DEFAULT_VERSION
    allow: tuple[Path, ...] = ()


@dataclass
class CriticalRun:
    """One of the most critical runs as written: its files, and why it has no .xosc if not."""

    evaluation: Evaluation
    files: list[Path]
    problem: str | None


@dataclass
class ExploreOutcome:
    """The search and what was written of it."""

    exploration: Exploration
    critical: list[CriticalRun]
    runs_csv: Path
    plot: Path

    @property
    def failed(self) -> int:
        """Runs that did not run (their error is in runs.csv)."""
        return sum(1 for e in self.exploration.evaluations if e.run is None)

    @property
    def collisions(self) -> int:
        return sum(1 for e in self.exploration.evaluations if e.run is not None and e.run.collided)


def check_budget(document: Document, budget: int, step: float) -> None:
    """Refuse, before anything runs, a budget whose runs would not fit in memory."""
    # Each run keeps its trajectories (about 40 bytes a sample) for the ranking and the plot.
    each = 40 * run_samples(document.root, step) + 8192
    check_count(budget, "runs", memory_each=each, hint="ask for fewer with --budget")


def explore_to_folder(
    document: Document,
    logical: Path,
    out_dir: Path,
    request: ExploreRequest,
    *,
    executor: str = "local",
    scheduler: str | None = None,
    workers: int | None = None,
    progress: Callable[[int], None] | None = None,
) -> ExploreOutcome:
    """Search `document` (the logical scenario read from `logical`) on `executor`
    (`sceml.executors`) and write the outputs into `out_dir`; `progress` hears of each run."""
    # Made before the search, so that an output that cannot be written fails now, not after it.
    created = make_folder(out_dir)
    try:
        with open_executor(executor, workers=workers, scheduler=scheduler) as runner:
            found = explore(
                document.root,
                logical,
                metric=request.metric,
                budget=request.budget,
                seed=request.seed,
                step=request.step,
                progress=progress,
                executor=runner,
                allow=request.allow,
            )
        # All outputs or none: a plot that fails must not leave runs.csv alone.
        with output_set() as outputs:
            write_atomically(outputs.stage(out_dir / RUNS_CSV), runs_csv(found).encode("utf-8"))
            plot_space(found, outputs.stage(out_dir / SPACE_PLOT))
            critical = write_critical(
                found,
                document.root,
                logical,
                out_dir,
                request.top,
                request.osc_version,
                stage=outputs.stage,
            )
    except BaseException:
        remove_folders(created)  # where nothing was written
        raise
    return ExploreOutcome(
        found,
        [CriticalRun(*written) for written in critical],
        out_dir / RUNS_CSV,
        out_dir / SPACE_PLOT,
    )

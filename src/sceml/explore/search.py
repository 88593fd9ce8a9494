"""The search: a space-filling design, then cross-entropy refinement towards critical runs.

Every varied parameter of the logical scenario is a dimension of the unit cube; a point u maps
to parameter values by each dimension's inverse distribution function (`levels.space`), so a
grid level, a normal distribution's shape and its bounds are kept. Each point is written into a
flattened concrete template (`levels.apply.FlatTemplate`, no copy per run) and simulated.

1. Design: a Latin hypercube of half the budget (scipy.stats.qmc, seeded).
2. Refinement, in batches of a tenth of the budget: fit an independent normal per dimension
   (in the cube) to the elite, the most critical fifth of all runs so far, and draw the next
   batch from it, clipped to the cube. Its spread never falls below `MIN_SPREAD`, so the search
   keeps looking around the critical region instead of collapsing on one point.

Everything random comes from one `numpy.random.default_rng(seed)` in the caller: the same seed,
budget and scenario give the same runs in the same order. Each batch (the design, then each
refinement) is simulated on an executor (`sceml.executors`, see `workers`); results are put
back in candidate order, so the executor changes how fast, never what.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import scemlmodel as scm

from ..errors import SceMLError
from ..executors import Executor, LocalExecutor
from ..levels.apply import FlatTemplate
from ..levels.space import ParameterSpace, parameter_space
from ..simulate import Run
from ..xosc import PLAYER_STEP
from .objective import METRICS
from .workers import Result, make_search_payload, run_candidates

ELITE_SHARE = 0.2
MIN_SPREAD = 0.03
DESIGN_SHARE = 0.5


class ExploreError(SceMLError):
    """The scenario cannot be explored: not logical, nothing varied, or an unknown metric."""

    exit_code = 2


@dataclass(frozen=True)
class Evaluation:
    """One run of the search: its values (in the space's path order), what it measured."""

    index: int
    phase: str  # "design" or "refine"
    values: tuple[float, ...]
    score: float
    run: Run | None
    error: str = ""


@dataclass(frozen=True)
class Exploration:
    """All runs of a search, in the order they were made."""

    space: ParameterSpace
    metric: str
    seed: int
    evaluations: tuple[Evaluation, ...]

    def ranked(self) -> list[Evaluation]:
        """The runs that ran, most critical first (ties by index)."""
        done = [e for e in self.evaluations if e.run is not None]
        return sorted(done, key=lambda e: (e.score, e.index))


def explore(
    logical: scm.Scenario,
    logical_file: str | Path,
    *,
    metric: str,
    budget: int,
    seed: int = 0,
    step: float = PLAYER_STEP,
    progress: Callable[[int], None] | None = None,
    executor: Executor | None = None,
    allow: tuple[Path, ...] = (),
) -> Exploration:
    """Search the logical scenario's parameter space for its most critical concrete runs.

    `logical` is what `logical_file` holds: workers simulate the file's bytes (and those of its
    libraries, reachable with `allow` as for sceml.model.loading.load_scenario, and its map). The runs happen on
    `executor`, by default in this process.
    """
    if metric not in METRICS:
        raise ExploreError(f"unknown metric {metric!r}; use one of {', '.join(METRICS)}")
    if budget < 2:
        raise ExploreError("the budget must allow at least 2 runs")
    space = parameter_space(logical)
    if not space.dimensions:
        raise ExploreError("the scenario varies no parameter: simulate it instead")
    # Workers build their own; this one refuses a scenario that cannot be flattened before any
    # worker starts, as every executor would then fail alike.
    FlatTemplate(logical, space.paths)
    payload = make_search_payload(logical, logical_file, space.paths, step=step, allow=allow)
    runner = executor if executor is not None else LocalExecutor()
    rng = np.random.default_rng(seed)
    score = METRICS[metric]
    evaluations: list[Evaluation] = []
    cubes: list[NDArray[np.float64]] = []  # where each run lies in the unit cube

    def evaluate(cube: NDArray[np.float64], phase: str) -> None:
        values = [_values(space, u) for u in cube]
        results = run_candidates(runner, payload, values, progress)
        for u, row, result in zip(cube, values, results, strict=True):
            cubes.append(u)
            evaluations.append(_evaluation(len(evaluations), phase, row, result, score))

    from scipy.stats import qmc  # slow to import: only a search needs it

    first = max(2, int(budget * DESIGN_SHARE))
    evaluate(qmc.LatinHypercube(len(space.dimensions), rng=rng).random(first), "design")
    batch = max(1, budget // 10)
    while len(evaluations) < budget:
        count = min(batch, budget - len(evaluations))
        evaluate(_refined(evaluations, cubes, rng, count), "refine")
    return Exploration(space, metric, seed, tuple(evaluations))


def _values(space: ParameterSpace, u: NDArray[np.float64]) -> tuple[float, ...]:
    """The parameter values at a point of the unit cube."""
    return tuple(
        float(d.values(np.array([x]))[0]) for d, x in zip(space.dimensions, u, strict=True)
    )


def _evaluation(
    index: int,
    phase: str,
    values: tuple[float, ...],
    result: Result,
    score: Callable[[Run], float],
) -> Evaluation:
    if isinstance(result, str):
        return Evaluation(index, phase, values, float("inf"), None, result)
    return Evaluation(index, phase, values, score(result), result)


def _refined(
    evaluations: list[Evaluation],
    cubes: list[NDArray[np.float64]],
    rng: np.random.Generator,
    count: int,
) -> NDArray[np.float64]:
    """A batch drawn around the elite: per dimension its mean and spread, clipped to the cube."""
    order = sorted(range(len(evaluations)), key=lambda i: (evaluations[i].score, i))
    elite = np.array([cubes[i] for i in order[: max(2, int(len(order) * ELITE_SHARE))]])
    mean, spread = elite.mean(axis=0), np.maximum(elite.std(axis=0), MIN_SPREAD)
    drawn = rng.normal(mean, spread, size=(count, elite.shape[1]))
    clipped: NDArray[np.float64] = np.clip(drawn, 0.0, np.nextafter(1.0, 0.0))
    return clipped

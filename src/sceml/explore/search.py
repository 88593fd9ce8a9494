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

Everything random comes from one `numpy.random.default_rng(seed)`: the same seed, budget and
scenario give the same runs in the same order.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import scemlmodel as scm

from ..errors import SceMLError
from ..levels.apply import FlatTemplate
from ..levels.space import ParameterSpace, parameter_space
from ..simulate import Run, simulate
from .objective import METRICS

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
    step: float = 0.05,
    progress: Callable[[int], None] | None = None,
) -> Exploration:
    """Search the logical scenario's parameter space for its most critical concrete runs."""
    if metric not in METRICS:
        raise ExploreError(f"unknown metric {metric!r}; use one of {', '.join(METRICS)}")
    if budget < 2:
        raise ExploreError("the budget must allow at least 2 runs")
    space = parameter_space(logical)
    if not space.dimensions:
        raise ExploreError("the scenario varies no parameter: simulate it instead")
    template = FlatTemplate(logical, space.paths)
    rng = np.random.default_rng(seed)
    score = METRICS[metric]
    evaluations: list[Evaluation] = []
    cubes: list[NDArray[np.float64]] = []  # where each run lies in the unit cube

    def evaluate(cube: NDArray[np.float64], phase: str) -> None:
        for u in cube:
            cubes.append(u)
            values = tuple(
                float(d.values(np.array([x]))[0]) for d, x in zip(space.dimensions, u, strict=True)
            )
            evaluations.append(
                _run(template, logical_file, len(evaluations), phase, values, score, step)
            )
            if progress is not None:
                progress(1)

    from scipy.stats import qmc  # slow to import: only a search needs it

    first = max(2, int(budget * DESIGN_SHARE))
    evaluate(qmc.LatinHypercube(len(space.dimensions), rng=rng).random(first), "design")
    batch = max(1, budget // 10)
    while len(evaluations) < budget:
        count = min(batch, budget - len(evaluations))
        evaluate(_refined(evaluations, cubes, rng, count), "refine")
    return Exploration(space, metric, seed, tuple(evaluations))


def _run(
    template: FlatTemplate,
    logical_file: str | Path,
    index: int,
    phase: str,
    values: tuple[float, ...],
    score: Callable[[Run], float],
    step: float,
) -> Evaluation:
    try:
        run = simulate(template.fill(values), logical_file, step=step)
    except SceMLError as error:
        return Evaluation(index, phase, values, float("inf"), None, error.message)
    return Evaluation(index, phase, values, score(run), run)


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

"""Sampling strategies over a parameter space: grid, Monte Carlo and Latin hypercube.

Every sample is reproducible from (seed, index) alone:

- grid: sample i is the i-th point of the full factorial over the set dimensions, in row-major
  order (the last varied parameter changes fastest); continuous dimensions stay at their
  nominal value. The seed plays no part.
- random: sample i draws its uniform numbers from its own generator,
  `np.random.default_rng(SeedSequence(seed, spawn_key=(i,)))`, which is what
  `SeedSequence(seed).spawn(n)[i]` gives, without creating the other n - 1.
- lhs: a Latin hypercube is a joint design of all n samples, so sample i is row i of the design
  scipy's `qmc.LatinHypercube(d, rng=default_rng(seed))` draws for (seed, n). Reproducing one
  LHS sample needs the n of the original run too. The design is drawn here with numpy alone,
  step for step as scipy draws it (importing `scipy.stats` costs half a second);
  tests/levels/test_sampling.py checks that both give the same design.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, get_args

import numpy as np
from numpy.typing import NDArray

from .paths import LevelArgumentError, LevelError
from .space import ParameterSpace

Strategy = Literal["grid", "random", "lhs"]
STRATEGIES: tuple[str, ...] = get_args(Strategy)


@dataclass(frozen=True)
class Plan:
    """What to sample: strategy, how many, from which seed."""

    strategy: Strategy
    n: int
    seed: int = 0

    def __post_init__(self) -> None:
        if self.strategy not in STRATEGIES:
            raise LevelError(f"unknown strategy {self.strategy!r}; use one of {STRATEGIES}")
        if self.n < 0 or self.seed < 0:
            raise LevelError("n and seed must be >= 0")


def plan_for(space: ParameterSpace, strategy: Strategy, n: int | None, seed: int) -> Plan:
    """A plan with n filled in: the grid size for grid (capped by n), else n (required)."""
    if strategy == "grid":
        size = space.grid_size
        return Plan("grid", size if n is None else min(n, size), seed)
    if n is None:
        raise LevelArgumentError(f"the {strategy} strategy needs a sample count (--n)")
    return Plan(strategy, n, seed)


@dataclass(frozen=True)
class IndexDraw:
    """The values of a plan whose samples each come from their index alone (grid, random).

    A batch hands this to its workers instead of the drawn values: each worker draws the
    values of the samples it makes, in parallel with the others, and its first sample need
    not wait for the whole run's values (2,000 random samples took the caller 40 ms before
    any worker could start). The values are those `values_at` gives for any set of indices.
    """

    space: ParameterSpace
    plan: Plan

    def __post_init__(self) -> None:
        if self.plan.strategy == "lhs":
            raise LevelError("a Latin hypercube is drawn as a whole, not sample by sample")

    def rows(self, indices: NDArray[np.int64]) -> NDArray[np.float64]:
        """The values of the samples at `indices`, one row per index."""
        return values_at(self.space, self.plan, indices)


def index_draw(space: ParameterSpace, plan: Plan) -> IndexDraw | None:
    """How workers draw the plan's values themselves; None for lhs (a joint design)."""
    return None if plan.strategy == "lhs" else IndexDraw(space, plan)


def design(space: ParameterSpace, plan: Plan) -> NDArray[np.float64]:
    """The values of all samples: an array of shape (n, number of dimensions)."""
    return values_at(space, plan, np.arange(plan.n))


def values_at(space: ParameterSpace, plan: Plan, indices: NDArray[np.int64]) -> NDArray[np.float64]:
    """The values of the samples at `indices` (each in [0, n)), one row per index."""
    indices = np.asarray(indices, dtype=np.int64)
    if indices.size and (indices.min() < 0 or indices.max() >= plan.n):
        raise LevelArgumentError(
            f"sample index out of range: the plan has {plan.n} samples (0..{plan.n - 1})"
        )
    if plan.strategy == "grid":
        return _grid_rows(space, indices)
    if plan.strategy == "random":
        uniforms = (
            np.stack([_random_uniforms(plan.seed, int(i), len(space.dimensions)) for i in indices])
            if indices.size
            else np.empty((0, len(space.dimensions)))
        )
    else:
        uniforms = _lhs_design(plan, len(space.dimensions))[indices]
    return _map_uniforms(space, uniforms)


def sample_row(space: ParameterSpace, plan: Plan, index: int) -> dict[str, float]:
    """One sample as {path: value}."""
    row = values_at(space, plan, np.array([index]))[0]
    return dict(zip(space.paths, (float(v) for v in row), strict=True))


def _grid_rows(space: ParameterSpace, indices: NDArray[np.int64]) -> NDArray[np.float64]:
    rows = np.empty((indices.size, len(space.dimensions)))
    shape = space.grid_shape
    coordinates = np.unravel_index(indices, shape) if shape else ()
    set_number = 0
    for column, dim in enumerate(space.dimensions):
        if dim.is_set:
            rows[:, column] = np.asarray(dim.levels)[coordinates[set_number]]
            set_number += 1
        else:
            rows[:, column] = dim.nominal()
    return rows


def _random_uniforms(seed: int, index: int, d: int) -> NDArray[np.float64]:
    generator = np.random.default_rng(np.random.SeedSequence(seed, spawn_key=(index,)))
    return generator.random(d)


def _lhs_design(plan: Plan, d: int) -> NDArray[np.float64]:
    if d == 0:
        return np.empty((plan.n, 0))
    # scipy's LatinHypercube spawns one child of the generator it is given and draws from it:
    # first the offsets within each cell, then one shuffle of the cells per dimension.
    generator = np.random.default_rng(np.random.SeedSequence(plan.seed, spawn_key=(0,)))
    offsets = generator.uniform(size=(plan.n, d))
    cells = np.tile(np.arange(1, plan.n + 1), (d, 1))
    for row in cells:
        generator.shuffle(row)
    design: NDArray[np.float64] = (cells.T - offsets) / plan.n
    return design


def _map_uniforms(space: ParameterSpace, uniforms: NDArray[np.float64]) -> NDArray[np.float64]:
    rows = np.empty_like(uniforms)
    for column, dim in enumerate(space.dimensions):
        rows[:, column] = dim.values(uniforms[:, column])
    return rows

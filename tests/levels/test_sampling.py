"""Grid, Monte Carlo and Latin hypercube sampling: counts, bounds and reproducibility."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest

from sceml.levels.paths import LevelError
from sceml.levels.sampling import Plan, design, plan_for, sample_row, values_at
from sceml.levels.space import Dimension, ParameterSpace, parameter_space
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def space() -> ParameterSpace:
    return parameter_space(load_scenario(EXAMPLES / "uis2-logical.xmi").root)


def test_grid_is_the_full_factorial(space: ParameterSpace) -> None:
    plan = plan_for(space, "grid", None, 0)
    rows = design(space, plan)
    assert len(rows) == 5 * 4 * 3 * 3
    grid_columns = [0, 2, 3, 4]
    combos = {tuple(row[grid_columns]) for row in rows}
    expected = set(itertools.product([3, 4, 5, 6, 7], [3, 4, 5, 6], [8, 10, 12], [10, 15, 20]))
    assert combos == {tuple(float(v) for v in c) for c in expected}
    # Continuous parameters stay nominal: the normal's mean, the uniform's midpoint.
    assert set(rows[:, 1]) == {7.0} and set(rows[:, 5]) == {1.5}


def test_grid_n_caps_the_sweep(space: ParameterSpace) -> None:
    assert plan_for(space, "grid", 10, 0).n == 10


@pytest.mark.parametrize("strategy", ["random", "lhs"])
def test_reproducible_by_seed_and_by_index(space: ParameterSpace, strategy: str) -> None:
    plan = Plan(strategy, 40, seed=11)  # type: ignore[arg-type]
    rows = design(space, plan)
    assert np.array_equal(rows, design(space, Plan(strategy, 40, seed=11)))  # type: ignore[arg-type]
    assert not np.array_equal(rows, design(space, Plan(strategy, 40, seed=12)))  # type: ignore[arg-type]
    for index in (0, 17, 39):
        single = sample_row(space, plan, index)
        assert list(single.values()) == list(rows[index])


@pytest.mark.parametrize("strategy", ["random", "lhs"])
def test_samples_respect_bounds_and_sets(space: ParameterSpace, strategy: str) -> None:
    rows = design(space, Plan(strategy, 300, seed=5))  # type: ignore[arg-type]
    assert set(rows[:, 0]) <= {3.0, 4.0, 5.0, 6.0, 7.0}
    assert rows[:, 1].min() >= 5.0 and rows[:, 1].max() <= 9.0  # truncated normal
    assert set(rows[:, 3]) == {8.0, 10.0, 12.0}
    assert rows[:, 5].min() >= 1.0 and rows[:, 5].max() <= 2.0


def test_lhs_stratifies_each_dimension(space: ParameterSpace) -> None:
    n = 50
    rows = design(space, Plan("lhs", n, seed=2))
    # The uniform column: exactly one sample in each of the n equal strata of [1, 2].
    strata = np.floor((rows[:, 5] - 1.0) * n).astype(int)
    assert sorted(strata) == list(range(n))


def test_random_sample_does_not_depend_on_n(space: ParameterSpace) -> None:
    small = values_at(space, Plan("random", 10, seed=3), np.array([7]))
    large = values_at(space, Plan("random", 10_000, seed=3), np.array([7]))
    assert np.array_equal(small, large)


def test_index_out_of_range_is_refused(space: ParameterSpace) -> None:
    with pytest.raises(LevelError):
        values_at(space, Plan("random", 5, seed=0), np.array([5]))


@pytest.mark.parametrize(("seed", "n", "d"), [(0, 1, 1), (7, 50, 6), (12345, 2000, 3)])
def test_lhs_design_is_scipys(seed: int, n: int, d: int) -> None:
    # The design is drawn without scipy; it must stay the one scipy's LatinHypercube draws.
    from scipy.stats import qmc

    dims = tuple(Dimension(f"p{i}", "uniform", low=0.0, high=1.0) for i in range(d))
    ours = design(ParameterSpace(dims), Plan("lhs", n, seed))
    theirs = qmc.LatinHypercube(d, rng=np.random.default_rng(seed)).random(n)
    assert np.array_equal(ours, theirs)

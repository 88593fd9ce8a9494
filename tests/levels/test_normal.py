"""The truncated normal's inverse distribution function gives scipy's truncnorm values."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import truncnorm

from sceml.levels.normal import truncated_normal_ppf

INF = math.inf

#: (low, high, mean, sd): untruncated, one-sided on either side of the mean, both sides,
#: wholly in either tail, far out in the tails, and UIS2's distribution.
CASES = [
    (-INF, INF, 0.0, 1.0),
    (-INF, INF, 13.9, 2.5),
    (0.0, 30.0, 10.0, 3.0),
    (-1.0, 1.0, 0.0, 1.0),
    (-INF, 2.0, 0.0, 1.0),
    (-2.0, INF, 0.0, 1.0),
    (0.5, INF, 0.0, 1.0),
    (-INF, -0.5, 0.0, 1.0),
    (5.0, 7.0, 0.0, 1.0),
    (-7.0, -5.0, 0.0, 1.0),
    (30.0, 40.0, 0.0, 1.0),
    (-40.0, -30.0, 0.0, 1.0),
    (8.0, 12.0, 10.0, 0.5),
]


@pytest.mark.parametrize(("low", "high", "mean", "sd"), CASES)
def test_values_are_scipys(low: float, high: float, mean: float, sd: float) -> None:
    # Up to u = 1 - 1e-5; above that scipy's log(u) loses the digits that place x (see below).
    u = np.concatenate(
        [np.random.default_rng(3).random(5000), [0.0, 1e-300, 1e-12, 0.5, 0.999, 1 - 1e-5]]
    )
    u = np.minimum(u, 1 - 1e-5)
    a, b = (low - mean) / sd, (high - mean) / sd
    theirs = np.clip(truncnorm.ppf(u, a, b, loc=mean, scale=sd), low, high)
    ours = truncated_normal_ppf(u, low, high, mean, sd)
    finite = np.isfinite(theirs)
    assert np.array_equal(ours[~finite], theirs[~finite])  # u = 0 below an open lower end
    assert np.max(np.abs(ours[finite] - theirs[finite])) <= 1e-12 * sd


def test_zero_is_the_lower_bound() -> None:
    assert truncated_normal_ppf(np.array([0.0]), 2.0, 5.0, 0.0, 1.0)[0] == 2.0


@pytest.mark.parametrize("gap", [1e-5, 1e-7, 1e-9, 2.0**-53])
def test_top_of_the_unit_interval_is_placed_by_the_mass_above(gap: float) -> None:
    # u = 1 - gap, normal truncated below at its mean - 2 sd: the mass above x must be gap
    # times the truncated mass, which erfc checks independently of the inverse. scipy misses
    # this by up to 3e-9 in x at gap 1e-9 and places the last x at 8.239 instead of 8.212
    # (20 % off in that mass): one draw in 100,000 differs from scipy's in its last digits.
    x = truncated_normal_ppf(np.array([1.0 - gap]), -2.0, INF, 0.0, 1.0)[0]
    truncated_mass = 1.0 - 0.5 * math.erfc(2.0 / math.sqrt(2.0))
    above = 0.5 * math.erfc(x / math.sqrt(2.0))
    assert above == pytest.approx((1.0 - (1.0 - gap)) * truncated_mass, rel=1e-12)

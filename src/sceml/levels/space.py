"""The parameter space of a logical scenario: one dimension per parameter that is not a value.

Each dimension maps a number u in [0, 1) to a value by its inverse distribution function, so
every strategy (Monte Carlo, Latin hypercube) draws uniform numbers and this module turns them
into parameter values:

- a Range with a step is a *set* of grid levels min, min+step, ... <= max, equally likely;
- a DiscreteDistribution is a set of its options, weighted (missing weights count as 1);
- a Range without a step and a UniformDistribution are continuous uniform;
- a NormalDistribution is normal, truncated to its bounds where given (the values of
  scipy's truncnorm, computed by `levels.normal` without importing scipy).

Sets are what grid sampling enumerates; a continuous dimension is held at its *nominal* value
during a grid sweep (the midpoint, or the normal's mean clipped into its bounds).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

import scemlmodel as scm

from .normal import truncated_normal_ppf
from .paths import LevelError, slots

#: A grid dimension may have at most this many levels (a typo'd step must not eat the disk).
MAX_LEVELS = 1_000_000


@dataclass(frozen=True)
class Dimension:
    """One varied parameter: its path, kind (`set`, `uniform`, `normal`) and shape."""

    path: str
    kind: str
    levels: tuple[float, ...] = ()
    weights: tuple[float, ...] = ()
    low: float = -math.inf
    high: float = math.inf
    mean: float = 0.0
    sd: float = 1.0
    #: The step of a Range with a step (its levels are min, min+step, ... <= max).
    step: float | None = None

    @property
    def is_set(self) -> bool:
        """Whether grid sampling enumerates this dimension."""
        return self.kind == "set"

    def values(self, u: NDArray[np.float64]) -> NDArray[np.float64]:
        """The values at uniform numbers `u` in [0, 1) (inverse distribution function)."""
        if self.kind == "set":
            cumulative = np.cumsum(self.weights) / sum(self.weights)
            picks = np.searchsorted(cumulative, u, side="right")
            return np.asarray(self.levels)[np.minimum(picks, len(self.levels) - 1)]
        if self.kind == "uniform":
            return self.low + u * (self.high - self.low)
        return truncated_normal_ppf(u, self.low, self.high, self.mean, self.sd)

    def nominal(self) -> float:
        """The value a grid sweep holds a continuous dimension at."""
        if self.kind == "set":
            return self.levels[0]
        if self.kind == "uniform":
            return (self.low + self.high) / 2
        return min(max(self.mean, self.low), self.high)


@dataclass(frozen=True)
class ParameterSpace:
    """The varied parameters of a logical scenario, in model order."""

    dimensions: tuple[Dimension, ...]

    @property
    def paths(self) -> tuple[str, ...]:
        """The varied parameter paths, in dimension order."""
        return tuple(d.path for d in self.dimensions)

    @property
    def grid_shape(self) -> tuple[int, ...]:
        """The number of levels of each set dimension, in dimension order."""
        return tuple(len(d.levels) for d in self.dimensions if d.is_set)

    @property
    def grid_size(self) -> int:
        """How many samples a full-factorial grid has (1 when nothing is a set)."""
        return math.prod(self.grid_shape)


def parameter_space(scenario: scm.Scenario) -> ParameterSpace:
    """Every parameter of `scenario` that holds a range or a distribution, as a dimension."""
    dimensions = []
    for path, slot in slots(scenario).items():
        held = slot.held()
        if held is None or isinstance(held, scm.Value):
            continue
        dimensions.append(dimension(path, held))
    return ParameterSpace(tuple(dimensions))


def dimension(path: str, held: scm.ParameterValue) -> Dimension:
    """The dimension a range or distribution spans; LevelError if it is malformed."""
    if isinstance(held, scm.Range):
        low, high = _bounds(path, held.min, held.max)
        if held.step is None:
            return Dimension(path, "uniform", low=low, high=high)
        levels = grid_levels(path, low, high, float(held.step))
        weights = (1.0,) * len(levels)
        return Dimension(path, "set", levels, weights, low, high, step=float(held.step))
    if isinstance(held, scm.UniformDistribution):
        low, high = _bounds(path, held.min, held.max)
        return Dimension(path, "uniform", low=low, high=high)
    if isinstance(held, scm.NormalDistribution):
        return _normal(path, held)
    if isinstance(held, scm.DiscreteDistribution):
        return _discrete(path, held)
    kind = held.eClass.name
    raise LevelError(f"{path} holds a {kind}, which cannot be sampled", element=path)


def grid_levels(path: str, low: float, high: float, step: float) -> tuple[float, ...]:
    """min, min+step, ..., up to max (inclusive, with a tolerance for float steps)."""
    if not step > 0:
        raise LevelError(f"{path}: range step must be > 0, got {step:g}", element=path)
    count = math.floor((high - low) / step + 1e-9) + 1
    if count > MAX_LEVELS:
        raise LevelError(f"{path}: range has {count} levels, above {MAX_LEVELS}", element=path)
    # Rounded so that 0.1-steps give 0.3, not 0.30000000000000004, in files and manifests;
    # by numpy, as a million levels one by one took seconds.
    levels: list[float] = np.round(low + np.arange(count) * step, 12).tolist()
    return tuple(levels)


def _bounds(path: str, low: float | None, high: float | None) -> tuple[float, float]:
    if low is None or high is None:
        raise LevelError(f"{path}: range needs both min and max", element=path)
    if not low <= high:
        raise LevelError(f"{path}: range min {low:g} is above max {high:g}", element=path)
    return float(low), float(high)


def _normal(path: str, held: scm.NormalDistribution) -> Dimension:
    if held.mean is None or held.standardDeviation is None or not held.standardDeviation > 0:
        raise LevelError(f"{path}: normal distribution needs a mean and sd > 0", element=path)
    low = -math.inf if held.lowerBound is None else float(held.lowerBound)
    high = math.inf if held.upperBound is None else float(held.upperBound)
    if not low < high:
        raise LevelError(f"{path}: normal bounds [{low:g}, {high:g}] are empty", element=path)
    return Dimension(
        path, "normal", low=low, high=high, mean=float(held.mean), sd=float(held.standardDeviation)
    )


def _discrete(path: str, held: scm.DiscreteDistribution) -> Dimension:
    if not held.options:
        raise LevelError(f"{path}: discrete distribution has no options", element=path)
    levels = tuple(float(o.value) for o in held.options)
    weights = tuple(1.0 if o.weight is None else float(o.weight) for o in held.options)
    if any(w < 0 for w in weights) or not sum(weights) > 0:
        raise LevelError(f"{path}: discrete weights must be >= 0, not all 0", element=path)
    return Dimension(path, "set", levels=levels, weights=weights)

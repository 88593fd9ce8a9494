"""What `explore` minimises: one criticality score per run, lower is more critical.

Every metric is taken over all pairs of actors (the most critical pair counts):

- `min-ttc`: the least time to collision (a run in which no pair ever closes in scores
  `NO_CONFLICT`);
- `min-distance`: the least distance between two bounding boxes;
- `collision`: the least distance between boxes, and below it every collision at -1, so the
  search is drawn towards near misses first and then into the region where boxes overlap;
- `pet`: the least post-encroachment time where driven paths cross (`NO_CONFLICT` without).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from ..simulate import Run

#: The score of a run without the conflict a metric measures (no TTC, no crossing).
NO_CONFLICT = 1e3

METRICS: dict[str, Callable[[Run], float]] = {}


def _metric(name: str) -> Callable[[Callable[[Run], float]], Callable[[Run], float]]:
    def register(score: Callable[[Run], float]) -> Callable[[Run], float]:
        METRICS[name] = score
        return score

    return register


def _least(values: list[float | None]) -> float:
    finite = [v for v in values if v is not None and math.isfinite(v)]
    return min(finite) if finite else NO_CONFLICT


@_metric("min-ttc")
def min_ttc(run: Run) -> float:
    return _least([m.min_ttc for m in run.metrics])


@_metric("min-distance")
def min_distance(run: Run) -> float:
    return _least([m.min_distance for m in run.metrics])


@_metric("collision")
def collision(run: Run) -> float:
    return -1.0 if run.collided else min_distance(run)


@_metric("pet")
def pet(run: Run) -> float:
    return _least([m.pet for m in run.metrics])

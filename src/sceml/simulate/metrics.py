"""Conflict metrics of every pair of actors from their trajectories, vectorised over samples.

Minimum distance between the boxes, minimum time to collision (constant velocities), collision
(the boxes overlap) with its first time, and the post-encroachment time (PET) where the driven
paths cross: the time between one actor leaving the conflict zone and the other entering it.
The conflict zone on each path is the stretch within half its own length plus half the other's
width of the crossing point (0 when both occupy it at once).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import NDArray

from .geometry import Boxes, gap, least_gap_candidates, overlapping, time_to_collision
from .run import ActorInfo, PairMetrics

Array = NDArray[np.float64]
#: PET compares paths resampled every this many metres.
PET_SPACING = 1.0  # m


def box_centres(states: Array, ahead: float) -> Array:
    """An actor's states (x, y, heading, speed, ...) with x, y moved from its reference point
    to its box's centre, `ahead` metres along the heading (Actor.boxCenterX)."""
    if not ahead:
        return states
    moved = states.copy()
    moved[:, 0] += ahead * np.cos(states[:, 2])
    moved[:, 1] += ahead * np.sin(states[:, 2])
    return moved


def pair_metrics(
    times: Array, actors: tuple[ActorInfo, ...], states: Array
) -> tuple[PairMetrics, ...]:
    """The metrics of each pair of actors, in actor order; none for a trailer and its tower."""
    centred = [box_centres(s, a.box_ahead) for a, s in zip(actors, states, strict=True)]
    boxes = [
        Boxes.moving(s[:, 0], s[:, 1], s[:, 2], s[:, 3], a.length, a.width)
        for a, s in zip(actors, centred, strict=True)
    ]
    results = []
    for i, j in itertools.combinations(range(len(actors)), 2):
        if actors[i].towed_by == actors[j].name or actors[j].towed_by == actors[i].name:
            continue
        results.append(
            _pair(times, actors[i], actors[j], boxes[i], boxes[j], centred[i], centred[j])
        )
    return tuple(results)


def _pair(
    times: Array, a: ActorInfo, b: ActorInfo, box_a: Boxes, box_b: Boxes, sa: Array, sb: Array
) -> PairMetrics:
    # One overlap test for the gap, the time to collision and the collision (each took its own).
    overlap = overlapping(box_a, box_b)
    distances = gap(box_a, box_b, least_gap_candidates(box_a, box_b), overlap)
    nearest = int(np.argmin(distances))
    ttc = time_to_collision(box_a, box_b, overlap)
    finite = np.isfinite(ttc)
    min_ttc = min_ttc_time = None
    if finite.any():
        k = int(np.argmin(np.where(finite, ttc, np.inf)))
        min_ttc, min_ttc_time = float(ttc[k]), float(times[k])
    hits = np.nonzero(overlap)[0]
    pet, point = post_encroachment(
        times, sa[:, :2], sb[:, :2], (a.length, a.width), (b.length, b.width)
    )
    return PairMetrics(
        a.name,
        b.name,
        float(distances[nearest]),
        float(times[nearest]),
        min_ttc,
        min_ttc_time,
        pet,
        point,
        bool(hits.size),
        float(times[hits[0]]) if hits.size else None,
    )


def _arc(xy: Array) -> Array:
    return np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(xy, axis=0).T))))


def _resample(xy: Array, arc: Array) -> tuple[Array, Array]:
    """The driven path every PET_SPACING m (where it moves): points and their arc length."""
    if arc[-1] < PET_SPACING:
        return xy[:1], arc[:1]
    grid = np.append(np.arange(0.0, arc[-1], PET_SPACING), arc[-1])
    points = np.column_stack([np.interp(grid, arc, xy[:, 0]), np.interp(grid, arc, xy[:, 1])])
    return points, grid


def _first_time(times: Array, arc: Array, s: float) -> float:
    """When the driven arc length first reaches `s` (inf if never; the start if s <= 0)."""
    if s <= 0:
        return float(times[0])
    k = int(np.searchsorted(arc, s, side="left"))
    if k >= len(arc):
        return math.inf
    if k == 0 or arc[k] <= arc[k - 1]:
        return float(times[k])
    u = (s - arc[k - 1]) / (arc[k] - arc[k - 1])
    return float(times[k - 1] + u * (times[k] - times[k - 1]))


def post_encroachment(
    times: Array,
    xy_a: Array,
    xy_b: Array,
    size_a: tuple[float, float],
    size_b: tuple[float, float],
) -> tuple[float | None, tuple[float, float] | None]:
    """The least PET over the crossings of two driven paths, and where; (None, None) without
    a crossing both actors reach."""
    full_a, full_b = _arc(xy_a), _arc(xy_b)
    pa, arc_a = _resample(xy_a, full_a)
    pb, arc_b = _resample(xy_b, full_b)
    if len(pa) < 2 or len(pb) < 2:
        return None, None
    crossings = _crossings(pa, pb)
    best: tuple[float, tuple[float, float]] | None = None
    for i, u, j, v in crossings:
        sa = arc_a[i] + u * (arc_a[i + 1] - arc_a[i])
        sb = arc_b[j] + v * (arc_b[j + 1] - arc_b[j])
        half_a = size_a[0] / 2 + size_b[1] / 2
        half_b = size_b[0] / 2 + size_a[1] / 2
        a_in = _first_time(times, full_a, sa - half_a)
        a_out = _first_time(times, full_a, sa + half_a)
        b_in = _first_time(times, full_b, sb - half_b)
        b_out = _first_time(times, full_b, sb + half_b)
        if math.isinf(a_in) or math.isinf(b_in):
            continue  # one of them never got there
        pet = max(b_in - a_out, a_in - b_out, 0.0)
        if math.isinf(pet):
            continue
        point = (
            float(pa[i, 0] + u * (pa[i + 1, 0] - pa[i, 0])),
            float(pa[i, 1] + u * (pa[i + 1, 1] - pa[i, 1])),
        )
        if best is None or pet < best[0]:
            best = (pet, point)
    return (best[0], best[1]) if best is not None else (None, None)


def _crossings(pa: Array, pb: Array) -> list[tuple[int, float, int, float]]:
    """Every pair of segments that cross: (segment of a, fraction, segment of b, fraction)."""
    a0, da = pa[:-1], np.diff(pa, axis=0)
    b0, db = pb[:-1], np.diff(pb, axis=0)
    cross = da[:, None, 0] * db[None, :, 1] - da[:, None, 1] * db[None, :, 0]
    offset = b0[None, :, :] - a0[:, None, :]
    with np.errstate(divide="ignore", invalid="ignore"):
        u = (offset[..., 0] * db[None, :, 1] - offset[..., 1] * db[None, :, 0]) / cross
        v = (offset[..., 0] * da[:, None, 1] - offset[..., 1] * da[:, None, 0]) / cross
    hit = (np.abs(cross) > 1e-12) & (u >= 0) & (u < 1) & (v >= 0) & (v < 1)
    return [
        (int(i), float(u[i, j]), int(j), float(v[i, j]))
        for i, j in zip(*np.nonzero(hit), strict=True)
    ]

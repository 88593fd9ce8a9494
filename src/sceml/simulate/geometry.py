"""Oriented bounding boxes over time: overlap, gap and time to collision, vectorised over samples.

A box series is its centre (x, y), heading, length and width at each sample. Overlap is the
separating-axis test on the four edge normals of the two boxes. Time to collision extrapolates
both boxes at constant velocity and fixed heading: on each axis the projections overlap during
one interval of time (the relative motion is linear), so the boxes first touch at the latest
start of those four intervals, if that comes before the earliest end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from .actors import Actor

Array = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class Boxes:
    """A box at each sample: centre, heading (rad), size (m) and velocity (m/s)."""

    x: Array
    y: Array
    heading: Array
    length: float
    width: float
    vx: Array
    vy: Array

    @staticmethod
    def moving(
        x: Array, y: Array, heading: Array, speed: Array, length: float, width: float
    ) -> Boxes:
        """Boxes that move along their heading at `speed`."""
        return Boxes(x, y, heading, length, width, speed * np.cos(heading), speed * np.sin(heading))

    @cached_property
    def cos(self) -> Array:
        return np.cos(self.heading)

    @cached_property
    def sin(self) -> Array:
        return np.sin(self.heading)

    def corners(self) -> Array:
        """The four corners at each sample (N x 4 x 2), counter-clockwise from front left."""
        c, s = self.cos, self.sin
        half = np.array([(1, 1), (-1, 1), (-1, -1), (1, -1)], dtype=float) * (
            self.length / 2,
            self.width / 2,
        )
        xs = self.x[:, None] + half[None, :, 0] * c[:, None] - half[None, :, 1] * s[:, None]
        ys = self.y[:, None] + half[None, :, 0] * s[:, None] + half[None, :, 1] * c[:, None]
        return np.stack([xs, ys], axis=-1)


def _axes(a: Boxes, b: Boxes) -> list[tuple[Array, Array]]:
    ca, sa, cb, sb = a.cos, a.sin, b.cos, b.sin
    return [(ca, sa), (-sa, ca), (cb, sb), (-sb, cb)]


def _reach(box: Boxes, ax: Array, ay: Array) -> Array:
    """Half the extent of a box projected on an axis."""
    c, s = box.cos, box.sin
    along = np.abs(c * ax + s * ay)
    across = np.abs(-s * ax + c * ay)
    return box.length / 2 * along + box.width / 2 * across


def collision_interval(a: Boxes, b: Boxes) -> tuple[Array, Array]:
    """When the extrapolated boxes overlap, relative to each sample: (first, last) seconds;
    first > last when they never do."""
    first = np.full(a.x.shape, -np.inf)
    last = np.full(a.x.shape, np.inf)
    dx, dy = b.x - a.x, b.y - a.y
    dvx, dvy = b.vx - a.vx, b.vy - a.vy
    for ax, ay in _axes(a, b):
        reach = _reach(a, ax, ay) + _reach(b, ax, ay)
        p = dx * ax + dy * ay
        q = dvx * ax + dvy * ay
        still = np.abs(q) < 1e-12
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = np.where(still, -np.inf, (-reach - p) / q)
            t2 = np.where(still, np.inf, (reach - p) / q)
        low, high = np.minimum(t1, t2), np.maximum(t1, t2)
        apart = still & (np.abs(p) >= reach)
        low = np.where(apart, np.inf, low)
        high = np.where(apart, -np.inf, high)
        first, last = np.maximum(first, low), np.minimum(last, high)
    return first, last


def overlapping(a: Boxes, b: Boxes) -> NDArray[np.bool_]:
    """Whether the boxes overlap at each sample (touching is not overlapping)."""
    inside = np.ones(a.x.shape, dtype=bool)
    dx, dy = b.x - a.x, b.y - a.y
    for ax, ay in _axes(a, b):
        inside &= np.abs(dx * ax + dy * ay) < _reach(a, ax, ay) + _reach(b, ax, ay)
    return inside


def time_to_collision(a: Boxes, b: Boxes, overlap: NDArray[np.bool_] | None = None) -> Array:
    """Seconds until the boxes touch at constant velocity; 0 while they overlap; inf if never.

    `overlap`: `overlapping(a, b)`, when the caller has it already."""
    first, last = collision_interval(a, b)
    ttc = np.where((first < last) & (last > 0), np.maximum(first, 0.0), np.inf)
    return np.where(overlapping(a, b) if overlap is None else overlap, 0.0, ttc)


def gap(
    a: Boxes,
    b: Boxes,
    where: NDArray[np.bool_] | None = None,
    overlap: NDArray[np.bool_] | None = None,
) -> Array:
    """The distance between the boxes' outlines at each sample (0 while they overlap); inf
    at samples `where` leaves out. `overlap`: `overlapping(a, b)`, if the caller has it."""
    result = np.full(a.x.shape, np.inf)
    chosen = np.arange(a.x.size) if where is None else np.nonzero(where)[0]
    if chosen.size:
        pa, pb = a.corners()[chosen], b.corners()[chosen]
        best = np.minimum(_corner_to_edges(pa, pb), _corner_to_edges(pb, pa))
        result[chosen] = best
    return np.where(overlapping(a, b) if overlap is None else overlap, 0.0, result)


def least_gap_candidates(a: Boxes, b: Boxes) -> NDArray[np.bool_]:
    """The samples where the least gap may lie: the gap is at most the centre distance and at
    least the centre distance less both half diagonals."""
    centres = np.hypot(b.x - a.x, b.y - a.y)
    reach = np.hypot(a.length, a.width) / 2 + np.hypot(b.length, b.width) / 2
    candidates: NDArray[np.bool_] = centres - reach <= centres.min()
    return candidates


def _corner_to_edges(points: Array, polygon: Array) -> Array:
    """The least distance from any of the points (N x 4 x 2) to any edge of the polygon."""
    start = polygon[:, None, :, :]
    edge = np.roll(polygon, -1, axis=1)[:, None, :, :] - start
    offset = points[:, :, None, :] - start
    squared = np.maximum(np.sum(edge * edge, axis=-1), 1e-12)
    u = np.clip(np.sum(offset * edge, axis=-1) / squared, 0.0, 1.0)
    nearest = offset - u[..., None] * edge
    distances: Array = np.sqrt(np.sum(nearest * nearest, axis=-1))
    return np.asarray(distances.reshape(len(points), -1).min(axis=1))


def _now(actor: Actor) -> Boxes:
    """The actor's box now: centred `box_ahead` metres ahead of its reference point."""
    one = np.array
    ahead = actor.box_ahead
    return Boxes.moving(
        one([actor.x + ahead * math.cos(actor.heading)]),
        one([actor.y + ahead * math.sin(actor.heading)]),
        one([actor.heading]),
        one([actor.speed]),
        actor.length,
        actor.width,
    )


def time_to_collision_now(a: Actor, b: Actor) -> float:
    """Time to collision of two actors in their current state."""
    return float(time_to_collision(_now(a), _now(b))[0])


def free_distance_now(a: Actor, b: Actor) -> float:
    """The distance between two actors' boxes in their current state (0 while they overlap)."""
    return float(gap(_now(a), _now(b))[0])

"""A path an actor moves along: a polyline by arc length, extended straight beyond both ends.

Each vertex may carry where on the map it lies (road, lane, s and the direction of travel on
that lane), so a maneuver that starts part-way (a turn, a lane change) knows which lane the
actor is on without projecting its position back onto the map.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LaneSpot:
    """Where a path vertex lies on the map: road, lane, s, and whether travel runs along s."""

    road: str
    lane: int
    s: float
    forward: bool


class Path:
    """A polyline parametrised by arc length `d` (m), straight beyond its ends."""

    def __init__(
        self,
        points: np.ndarray,
        spots: Sequence[LaneSpot | None] | None = None,
        dead_end: bool = False,
    ) -> None:
        points = np.asarray(points, dtype=float)
        keep = np.concatenate(([True], np.hypot(*np.diff(points, axis=0).T) > 1e-9))
        points = points[keep]
        if spots is not None:
            spots = [spot for spot, kept in zip(spots, keep, strict=True) if kept]
        if len(points) == 1:
            points = np.vstack([points, points + (1e-6, 0.0)])
            spots = None if spots is None else [spots[0], spots[0]]
        self.points = points
        steps = np.diff(points, axis=0)
        self.length_of = np.hypot(steps[:, 0], steps[:, 1])
        self.d = np.concatenate(([0.0], np.cumsum(self.length_of)))
        self.length = float(self.d[-1])
        #: Where the road ends without a link (players stop an actor there); None: it goes on.
        self.end_of_road: float | None = self.length if dead_end else None
        self._d = self.d.tolist()
        self._xy = points.tolist()
        self._headings = np.arctan2(steps[:, 1], steps[:, 0]).tolist()
        self.spots = list(spots) if spots is not None else [None] * len(points)

    def _segment(self, d: float) -> int:
        return min(max(bisect_right(self._d, d) - 1, 0), len(self._headings) - 1)

    def pose(self, d: float) -> tuple[float, float, float]:
        """Point and heading at arc length `d` (extrapolated straight before 0 and past the end)."""
        i = self._segment(d)
        heading = self._headings[i]
        x0, y0 = self._xy[i]
        along = d - self._d[i]
        return x0 + along * math.cos(heading), y0 + along * math.sin(heading), heading

    def spot(self, d: float) -> LaneSpot | None:
        """The lane the path runs on at `d`, with s interpolated; None off the map."""
        i = self._segment(d)
        a, b = self.spots[i], self.spots[i + 1]
        if a is None:
            return None
        if b is None or b.road != a.road or b.lane != a.lane:
            return a
        span = self._d[i + 1] - self._d[i]
        u = min(max((d - self._d[i]) / span, 0.0), 1.0) if span > 0 else 0.0
        return LaneSpot(a.road, a.lane, a.s + u * (b.s - a.s), a.forward)

    def distance_to(self, x: float, y: float) -> float:
        """The shortest distance from a point to the polyline."""
        a, b = self.points[:-1], self.points[1:]
        ab = b - a
        squared = np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-12)
        u = np.clip(np.einsum("ij,ij->i", np.array([x, y]) - a, ab) / squared, 0.0, 1.0)
        nearest = a + u[:, None] * ab
        return float(np.min(np.hypot(nearest[:, 0] - x, nearest[:, 1] - y)))


def straight(points: Sequence[tuple[float, float]]) -> Path:
    """A path through the given points, off the map (Cross, FollowTrajectory)."""
    return Path(np.array(points, dtype=float))


def heading_path(x: float, y: float, heading: float) -> Path:
    """A straight line from a point along a heading: an actor that is on no lane."""
    return Path(np.array([(x, y), (x + math.cos(heading), y + math.sin(heading))]))


def offset_path(path: Path, lateral: float) -> Path:
    """The same path moved `lateral` m to the left of its direction of travel."""
    if lateral == 0.0:
        return path
    headings = np.array(path._headings + path._headings[-1:])
    shifted = path.points + lateral * np.column_stack([-np.sin(headings), np.cos(headings)])
    return Path(shifted, path.spots, path.end_of_road is not None)


def joined(first: Path, then: Path) -> Path:
    """`first`, then on along `then` (which starts near where `first` ends)."""
    points = np.vstack([first.points, then.points])
    return Path(points, [*first.spots, *then.spots], then.end_of_road is not None)

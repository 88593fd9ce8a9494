"""Which roads of a map may have a lane near a point: a grid of square cells over the map.

`RoadMap.world_to_lane` projects a point onto every road it asks about, which is the costly part;
this index narrows the roads down first. It stood on shapely's STRtree, whose import (with numpy's)
took about 110 ms of a 10k-node validation's 1 s for a map of 20 roads. The grid needs neither,
and answers with every road the tree found (possibly a few more, which the projection that
follows turns away), in the map's order.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

#: Side of a cell (m). A query with the rules' tolerance (0.5 m) reads one to four cells.
CELL = 20.0
#: How many polyline samples one box covers (at 0.5 m a sample, 8 m of reference line).
_RUN = 16


class RoadIndex:
    """The roads (by position in the map's order) each cell of the grid may need.

    A road is entered in every cell that the box around a run of its reference line's samples,
    grown by the road's reach, touches. Any point within reach + d of the line then lies within
    d (in x and in y) of one of those boxes, so `near(x, y, d)` reads the cells of the square of
    half-side d around the point and misses no road.
    """

    def __init__(self, lines: Sequence[Sequence[tuple[float, float]]], reach: Sequence[float]):
        self._cells: dict[tuple[int, int], set[int]] = {}
        for index, (xy, grow) in enumerate(zip(lines, reach, strict=True)):
            # Runs overlap by a sample, so that every segment of the polyline is in one box.
            for start in range(0, max(len(xy) - 1, 1), _RUN):
                run = xy[start : start + _RUN + 1]
                xs = [x for x, _ in run]
                ys = [y for _, y in run]
                self._enter(index, min(xs) - grow, min(ys) - grow, max(xs) + grow, max(ys) + grow)

    def _enter(self, index: int, x0: float, y0: float, x1: float, y1: float) -> None:
        for i in range(_cell(x0), _cell(x1) + 1):
            for j in range(_cell(y0), _cell(y1) + 1):
                self._cells.setdefault((i, j), set()).add(index)

    def near(self, x: float, y: float, distance: float) -> list[int]:
        """The roads whose reference line may pass within their reach + `distance` of (x, y),
        as positions in the map's order, ascending."""
        found: set[int] = set()
        for i in range(_cell(x - distance), _cell(x + distance) + 1):
            for j in range(_cell(y - distance), _cell(y + distance) + 1):
                found.update(self._cells.get((i, j), ()))
        return sorted(found)


def _cell(coordinate: float) -> int:
    return math.floor(coordinate / CELL)

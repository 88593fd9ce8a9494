"""The grid of `sceml.maps.roadindex` misses no road: every road whose reference line passes
within its reach + d of a point is among `near(x, y, d)`, as the STRtree's distance test had it
(issue 31; the answers of `world_to_lane` themselves are compared in test_road_index)."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from maps import test_intersection_map as evaluator
from sceml.maps import load_map
from sceml.maps.roadindex import CELL, RoadIndex

coordinate = st.floats(-300.0, 300.0, allow_nan=False)
polyline = st.lists(st.tuples(coordinate, coordinate), min_size=1, max_size=40)


def _distance_to_line(x: float, y: float, xy: list[tuple[float, float]]) -> float:
    """The Euclidean distance from (x, y) to the polyline, segment by segment (a lone point
    is a polyline of no length)."""
    best = math.dist((x, y), xy[0])
    for (ax, ay), (bx, by) in zip(xy, xy[1:], strict=False):
        dx, dy = bx - ax, by - ay
        squared = dx * dx + dy * dy
        u = 0.0 if squared == 0 else min(max(((x - ax) * dx + (y - ay) * dy) / squared, 0.0), 1.0)
        best = min(best, math.dist((x, y), (ax + u * dx, ay + u * dy)))
    return best


@settings(max_examples=300, deadline=None)
@given(
    lines=st.lists(polyline, min_size=1, max_size=6),
    reaches=st.lists(st.floats(0.0, 30.0), min_size=6, max_size=6),
    point=st.tuples(coordinate, coordinate),
    distance=st.sampled_from([1.0, 2.0, 3.0, 101.0]),
)
def test_near_holds_every_road_within_reach(
    lines: list[list[tuple[float, float]]],
    reaches: list[float],
    point: tuple[float, float],
    distance: float,
) -> None:
    reach = reaches[: len(lines)]
    near = RoadIndex(lines, reach).near(*point, distance)
    assert near == sorted(set(near))
    for index, xy in enumerate(lines):
        if _distance_to_line(*point, xy) <= reach[index] + distance:
            assert index in near, (index, point)


def test_near_leaves_out_roads_far_away() -> None:
    """Two short lines 10 cells apart: a point at one is not near the other."""
    index = RoadIndex([[(0.0, 0.0), (1.0, 0.0)], [(10 * CELL, 0.0), (10 * CELL + 1, 0.0)]], [2, 2])
    assert index.near(0.5, 0.0, 1.0) == [0]
    assert index.near(10 * CELL, 0.5, 1.0) == [1]
    assert index.near(5 * CELL, 0.0, 1.0) == []


def test_a_point_at_infinity_or_nan_is_near_no_road() -> None:
    road_map = load_map(evaluator.XODR)
    for x, y in ((math.inf, 0.0), (0.0, -math.inf), (math.nan, 0.0)):
        assert road_map._near(x, y, 0.5) == []

"""One meaning of a Position on a map (sceml.maps.resolve), checked by hand on a straight road:
road 1 of highway.xodr runs along x from the origin, three 3.5 m lanes on each side."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from sceml.maps import PositionError, RoadMap, WorldPose, load_map
from sceml.maps.positions import centre, is_concrete, locate
from sceml.maps.resolve import resolve, road_pose, road_to_lane
from sceml.model.build import lane, road, world
from sceml.model.params import span

HIGHWAY = Path(__file__).resolve().parents[1] / "importer" / "files" / "highway.xodr"


@pytest.fixture(scope="module")
def highway() -> RoadMap:
    return load_map(HIGHWAY)


def test_a_road_coordinate_lies_in_the_lane_whose_band_holds_t(highway: RoadMap) -> None:
    # t = -5.5 is in lane -2 (-3.5 .. -7), whose centre is -5.25.
    found = road_to_lane(highway, "1", 120.0, -5.5)
    assert (found.road_id, found.lane_id, found.s, round(found.offset, 9)) == (
        "1",
        -2,
        120.0,
        -0.25,
    )
    assert road_to_lane(highway, "1", 120.0, 1.75).lane_id == 1


@pytest.mark.parametrize(
    ("s", "t", "words"),
    [(1200.0, -1.75, "outside road '1'"), (50.0, -30.0, "t=-30 m is off road '1'")],
)
def test_a_road_coordinate_off_the_road_says_which(
    highway: RoadMap, s: float, t: float, words: str
) -> None:
    with pytest.raises(PositionError, match=words):
        road_to_lane(highway, "1", s, t)


def test_the_heading_follows_the_lane_unless_given_relative_to_the_road(highway: RoadMap) -> None:
    right = road_pose(highway, "1", 50.0, -5.5)
    assert (right.x, right.y, right.heading) == pytest.approx((50.0, -5.5, 0.0))
    # Lane 1 carries traffic against s on a right-hand-traffic road.
    left = road_pose(highway, "1", 50.0, 1.75)
    assert (left.x, left.y, abs(left.heading)) == pytest.approx((50.0, 1.75, math.pi))
    turned = road_pose(highway, "1", 50.0, 1.75, 0.25)
    assert turned.heading == pytest.approx(0.25)


def test_resolve_gives_one_pose_for_each_kind(highway: RoadMap) -> None:
    kept = resolve(road(1, 90.0, -1.75, h=0.05), highway)
    assert kept is not None and (kept.x, kept.y, kept.heading) == pytest.approx((90.0, -1.75, 0.05))
    on_lane = resolve(lane(1, -1, 90.0), highway)
    assert on_lane is not None and (on_lane.x, on_lane.y) == pytest.approx((90.0, -1.75))
    assert resolve(world(3.0, 4.0, h=1.0), None) == WorldPose(3.0, 4.0, 1.0)
    assert resolve(road(1, 90.0), None) is None  # a road coordinate needs the map


def test_locate_spans_a_logical_road_position(highway: RoadMap) -> None:
    position = road(1, span(20.0, 60.0), -1.75)
    assert not is_concrete(position)
    points = locate(position, highway)
    assert [p.x for p in points] == pytest.approx([20.0, 40.0, 60.0])
    assert [p.y for p in points] == pytest.approx([-1.75] * 3)
    assert [p.lane[:3] for p in points if p.lane] == [("1", -1, s) for s in (20.0, 40.0, 60.0)]
    middle = centre(position, highway)
    assert middle is not None and (middle.x, middle.y) == pytest.approx((40.0, -1.75))

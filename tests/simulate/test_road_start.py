"""An actor starting on a RoadPosition stands where the road coordinate is (checked by hand on
the straight road 1 of highway.xodr, along x from the origin) and follows its lane."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.build import road
from sceml.maps import RoadMap, load_map
from sceml.params import value
from sceml.render.labels import describe_position
from sceml.simulate.setup import make_actor
from sceml.simulate.world import SimulationError

HIGHWAY = Path(__file__).resolve().parents[1] / "importer" / "files" / "highway.xodr"


@pytest.fixture(scope="module")
def highway() -> RoadMap:
    return load_map(HIGHWAY)


def car(position: scm.Position) -> scm.Car:
    return scm.Car(name="car", startPosition=position, initialSpeed=value(10.0))


def test_a_road_start_is_placed_in_the_lane_it_lies_in(highway: RoadMap) -> None:
    actor = make_actor(car(road(1, 50.0, -5.5)), highway)
    actor.place()
    assert (actor.x, actor.y, actor.heading) == pytest.approx((50.0, -5.5, 0.0))
    assert actor.lateral == pytest.approx(-0.25)  # lane -2's centre is t = -5.25


def test_a_road_start_with_a_heading_starts_like_the_world_pose_it_names(
    highway: RoadMap,
) -> None:
    # As any actor on a lane (simulate/lanes.py), it moves along the lane, in the direction its
    # heading is nearer to (esmini 3.6 too keeps this one on y = -1.75 while it drives).
    actor = make_actor(car(road(1, 90.0, -1.75, h=0.05)), highway)
    actor.place()
    assert (actor.x, actor.y, actor.heading) == pytest.approx((90.0, -1.75, 0.0))
    against = make_actor(car(road(1, 90.0, -1.75, h=3.0)), highway)
    against.place()
    assert (against.x, against.y, abs(against.heading)) == pytest.approx((90.0, -1.75, math.pi))


def test_a_road_start_off_the_road_or_without_a_map_is_refused(highway: RoadMap) -> None:
    with pytest.raises(SimulationError, match="t=-30 m is off road '1'"):
        make_actor(car(road(1, 50.0, -30.0)), highway)
    with pytest.raises(SimulationError, match="needs an OpenDRIVE map"):
        make_actor(car(road(1, 50.0, -5.5)), None)


def test_the_label_shows_the_road_coordinate() -> None:
    assert describe_position(road(1, 50.0, -5.5), {}) == "road 1 s 50 m t -5.5 m"
    assert describe_position(road(1, 50.0, h=0.05), {}) == "road 1 s 50 m t 0 m, h 0.05 rad"

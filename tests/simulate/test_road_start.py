"""Road and relative positions in the preview (checked by hand on the straight road 1 of
highway.xodr, along x from the origin): a road start stands where its coordinate is and follows
its lane; a relative position is taken where its entity is when it is used."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.importer import import_file
from sceml.maps import RoadMap, load_map
from sceml.model.build import road
from sceml.model.params import value
from sceml.render.labels import describe_position
from sceml.simulate import simulate
from sceml.simulate.setup import make_actor
from sceml.simulate.world import SimulationError

REPO = Path(__file__).resolve().parents[2]
HIGHWAY = REPO / "tests" / "importer" / "files" / "highway.xodr"


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


def test_relative_starts_destinations_and_conditions_follow_their_entity() -> None:
    # files/relative-positions.xosc, worked out by hand on road 1 (along x, lanes 3.5 m wide):
    # Ego starts at (50, -5.25) in lane -2; Lead one lane left and 30 m on, 0.25 m left of
    # lane -1's centre: (80, -1.5); Side 10 m back and 3.5 m right: (40, -8.75); Behind 15 m
    # behind Ego: (35, -5.25).
    source = REPO / "tests" / "importer" / "files" / "relative-positions.xosc"
    run = simulate(import_file(source).scenario, source)
    starts = {
        name: tuple(round(float(v), 6) for v in run.states[run.actor_index(name), 0, :2])
        for name in ("Ego", "Lead", "Side", "Behind")
    }
    assert starts == {
        "Ego": (50.0, -5.25),
        "Lead": (80.0, -1.5),
        "Side": (40.0, -8.75),
        "Behind": (35.0, -5.25),
    }
    # NearLead's point is 40 m behind Lead and 3.5 m right of it, where Lead is at each step:
    # (x_lead - 40, -5.0). Behind (20 m/s) gains 5 m/s on it from 5 m behind, within 3 m
    # after 0.4 s (0.45 s: the first step past it), and Slow, whose StartTrigger holds the
    # condition (xosc.flows.inlined), starts then too.
    assert run.node("NearLead").finished == pytest.approx(0.45)
    assert run.node("Slow").started == pytest.approx(0.45)
    # DriveThere's destination is 100 m beyond Lead's x when it starts (t = 0.05 s: Lead at
    # 80.75), 3.5 m right of it: (180.75, -5.0). Ego covers the 130 m at 20 m/s.
    assert run.node("DriveThere").finished == pytest.approx(6.45, abs=0.05)

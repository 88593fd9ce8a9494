"""The concrete examples' routed maneuvers can be driven on the map: the junction connects the
actor's start lane to its destination road, turning the way the maneuver says.

No OpenSCENARIO player is installable here (esmini and CARLA are not packaged), so this checks the
part a player relies on: a routing action whose destination no lane leads to is ignored.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml import io
from sceml.graph import actors
from sceml.modules import flatten
from sceml.params import concrete

REPO = Path(__file__).resolve().parents[2]
POSITIONS = json.loads((REPO / "maps" / "positions.json").read_text())
ARMS = POSITIONS["map"]["arms"]


def connections() -> dict[tuple[str, int], dict[str, str]]:
    """(incoming road, lane) -> {destination road: connecting road}, read from the map."""
    tree = etree.parse(str(REPO / "maps" / "intersection.xodr"))
    successor_of = {
        road.get("id"): road.find("link/successor").get("elementId")
        for road in tree.iter("road")
        if road.get("junction") not in (None, "-1")
    }
    found: dict[tuple[str, int], dict[str, str]] = {}
    for connection in tree.iter("connection"):
        connecting = connection.get("connectingRoad")
        for link in connection.iter("laneLink"):
            key = (connection.get("incomingRoad"), int(link.get("from")))
            found.setdefault(key, {})[successor_of[connecting]] = connecting
    return found


def arm_of(road_id: str) -> str:
    return next(name for name, arm in ARMS.items() if arm["roadId"] == road_id)


def road_at(x: float, y: float) -> str:
    """The arm road whose lanes contain a point beyond the junction (arms are straight)."""
    for arm in ARMS.values():
        angle = arm["direction_from_centre"]
        along = x * math.cos(angle) + y * math.sin(angle)
        across = -x * math.sin(angle) + y * math.cos(angle)
        if along > POSITIONS["map"]["junction_radius"] and abs(across) < 7.5:
            return str(arm["roadId"])
    raise AssertionError(f"({x}, {y}) is on no arm")


def turn_angle(from_road: str, to_road: str) -> float:
    """Signed heading change in degrees driving in on one arm and out on another (left > 0)."""
    heading_in = ARMS[arm_of(from_road)]["direction_from_centre"] + math.pi
    heading_out = ARMS[arm_of(to_road)]["direction_from_centre"]
    change = math.degrees(heading_out - heading_in)
    return (change + 180) % 360 - 180


@pytest.mark.parametrize("name", ["uis1-concrete.xmi", "uis2-concrete.xmi"])
def test_every_turn_has_a_junction_connection_that_turns_that_way(name: str) -> None:
    scenario = flatten(io.load(REPO / "examples" / name).root)
    links = connections()
    turns = [n for n in scenario.nodes if isinstance(n, scm.TurnLeft | scm.TurnRight)]
    assert turns, "the example has no routed turn to check"
    for turn in turns:
        start = turn.referenceActor.startPosition
        destination = turn.destination
        to_road = road_at(concrete(destination, "x"), concrete(destination, "y"))
        reachable = links.get((start.roadId, start.laneId), {})
        assert to_road in reachable, f"{turn.name}: no lane from road {start.roadId} to {to_road}"
        expected = 90.0 if isinstance(turn, scm.TurnLeft) else -90.0
        assert turn_angle(start.roadId, to_road) == pytest.approx(expected, abs=0.01), turn.name


def test_the_oncoming_car_can_drive_straight_through_for_its_distance() -> None:
    scenario = flatten(io.load(REPO / "examples" / "uis2-concrete.xmi").root)
    car = next(a for a in actors(scenario) if a.name == "car")
    drive = next(n for n in scenario.nodes if isinstance(n, scm.DriveDistance))
    start = car.startPosition
    straight = connections()[(start.roadId, start.laneId)]
    opposite = next(
        road for road in straight if turn_angle(start.roadId, road) == pytest.approx(0.0, abs=0.01)
    )
    tree = etree.parse(str(REPO / "maps" / "intersection.xodr"))
    through = next(r for r in tree.iter("road") if r.get("id") == straight[opposite])
    # From its start to the junction, through it, and on along the far arm.
    available = (
        concrete(start, "s") + float(through.get("length")) + ARMS[arm_of(opposite)]["length"]
    )
    assert concrete(drive, "distance") < available

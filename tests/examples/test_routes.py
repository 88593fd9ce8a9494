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
from sceml.model.graph import actors
from sceml.model.loading import load
from sceml.model.params import concrete
from sceml.modules import flatten
from sceml.validation import validate

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


def turn_angle(from_road: str, to_road: str) -> float:
    """Signed heading change in degrees driving in on one arm and out on another (left > 0)."""
    heading_in = ARMS[arm_of(from_road)]["direction_from_centre"] + math.pi
    heading_out = ARMS[arm_of(to_road)]["direction_from_centre"]
    change = math.degrees(heading_out - heading_in)
    return (change + 180) % 360 - 180


def _r006(scenario_text: str, tmp_path: Path, name: str) -> list[str]:
    """SCEML-R006 messages for a changed copy of an example (the map and library stay reachable)."""
    copy = tmp_path / "examples" / name
    copy.parent.mkdir(parents=True, exist_ok=True)
    (tmp_path / "maps").mkdir(exist_ok=True)
    (tmp_path / "maps" / "intersection.xodr").write_bytes(
        (REPO / "maps" / "intersection.xodr").read_bytes()
    )
    library = tmp_path / "examples" / "library"
    if not library.exists():
        library.mkdir()
        for file in (REPO / "examples" / "library").glob("*.xmi"):
            (library / file.name).write_bytes(file.read_bytes())
    copy.write_text(scenario_text, encoding="utf-8")
    (tmp_path / ".sceml-root").touch()  # one project, as the repository is
    document = load(copy)
    return [d.message for d in validate(document.root, document=document) if d.code == "SCEML-R006"]


# The check that each example's turn follows a junction connection turning its way is the map
# rule SCEML-R006 (src/sceml/validation/map_turns.py); here: it passes on the examples and
# objects when an example's turn is named the other way.
@pytest.mark.parametrize("name", ["uis1-concrete.xmi", "uis2-concrete.xmi"])
def test_every_turn_follows_a_junction_connection_that_turns_that_way(
    name: str, tmp_path: Path
) -> None:
    text = (REPO / "examples" / name).read_text(encoding="utf-8")
    assert "scemlmodel:TurnLeft" in text or "scemlmodel:TurnRight" in text
    assert _r006(text, tmp_path, name) == []
    swapped = (
        text.replace("scemlmodel:TurnLeft", "scemlmodel:TURN")
        .replace("scemlmodel:TurnRight", "scemlmodel:TurnLeft")
        .replace("scemlmodel:TURN", "scemlmodel:TurnRight")
    )
    found = _r006(swapped, tmp_path, name)
    assert len(found) == 1, found
    assert ("not a left turn" in found[0]) == (name == "uis1-concrete.xmi"), found


def test_the_oncoming_car_can_drive_straight_through_for_its_distance() -> None:
    scenario = flatten(load(REPO / "examples" / "uis2-concrete.xmi").root)
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

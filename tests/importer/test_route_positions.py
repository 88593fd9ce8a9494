"""Positions on a route (metamodel 1.3): a hand-written file whose actors start on routes (one
from a route catalog in lane coordinates, one written in place in road coordinates) and whose
condition is a place on a route imports to RoutePositions, not opaque nodes; exports back at
every version with the same routes and places; and the preview places the starts where esmini
3.6 does on this map (checked by hand with esmini: Ego at (50, -4.75), the brake at 4.95 s)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.simulate import simulate
from sceml.simulate.world import SimulationError
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
ROUTES = FILES / "route-positions.xosc"


def _actors(scenario: Any) -> dict[str, Any]:
    return {actor.name: actor for actor in graph.root_node(scenario).actors}


def _route_elements(path: Path) -> list[tuple[Any, ...]]:
    """Each RoutePosition as (route name, [(strategy, road, lane, s)], where on the route)."""
    found = []
    for element in etree.parse(str(path)).iter("RoutePosition"):
        route = element.find("RouteRef/Route")
        points = [
            (
                w.get("routeStrategy"),
                w.find("Position/LanePosition").get("roadId"),
                w.find("Position/LanePosition").get("laneId"),
                float(w.find("Position/LanePosition").get("s")),
            )
            for w in route.iterfind("Waypoint")
        ]
        place = element.find("InRoutePosition/*")
        numbers = {k: float(v) for k, v in place.attrib.items()}
        found.append((route.get("name"), points, place.tag, numbers))
    return found


def test_route_starts_and_a_route_condition_are_mapped_not_opaque() -> None:
    imported = import_file(ROUTES)
    assert imported.report.counts()["opaque"] == 0
    actors = _actors(imported.scenario)
    ego, target = actors["Ego"].startPosition, actors["Target"].startPosition
    assert ego.eClass.name == target.eClass.name == "RoutePosition"
    assert (ego.routeName, ego.laneId, ego.pathS.value, ego.laneOffset.value) == (
        "KeepRight",
        -2,
        30.0,
        0.5,
    )
    assert [
        (w.routeStrategy.name, w.position.laneId, w.position.s.value) for w in ego.waypoints
    ] == [
        ("shortest", -2, 20.0),
        ("fastest", -2, 900.0),
    ]
    assert (target.routeName, target.laneId, target.pathS.value, target.t.value) == (
        "InTheMiddle",
        None,
        25.0,
        -1.75,
    )
    (reach,) = [n for n in imported.scenario.nodes if n.eClass.name == "InLocationRadius"]
    assert reach.position.eClass.name == "RoutePosition"
    assert (reach.position.pathS.value, reach.radius.value) == (130.0, 2.0)


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_route_positions_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    first = import_file(ROUTES)
    exported = tmp_path / "routes.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=ROUTES)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    keep_right = [("shortest", "1", "-2", 20.0), ("fastest", "1", "-2", 900.0)]
    in_the_middle = [("shortest", "1", "-1", 100.0), ("leastIntersections", "1", "-1", 800.0)]
    # The catalog's route is written in place; the lane offset a lane place leaves out is 0.
    assert sorted(_route_elements(exported), key=repr) == sorted(
        [
            (
                "KeepRight",
                keep_right,
                "FromLaneCoordinates",
                {"pathS": 30, "laneId": -2, "laneOffset": 0.5},
            ),
            (
                "KeepRight",
                keep_right,
                "FromLaneCoordinates",
                {"pathS": 130, "laneId": -2, "laneOffset": 0},
            ),
            ("InTheMiddle", in_the_middle, "FromRoadCoordinates", {"pathS": 25, "t": -1.75}),
        ],
        key=repr,
    )
    again = import_file(exported, allow=[FILES]).scenario
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_the_preview_starts_route_actors_where_the_route_puts_them() -> None:
    run = simulate(import_file(ROUTES).scenario, ROUTES)
    ego, target = (run.states[run.actor_index(name), 0] for name in ("Ego", "Target"))
    # KeepRight starts at s=20 in lane -2 (centre t=-5.25), which drives along s: 30 m on and
    # 0.5 m to the left of the centre. esmini 3.6 puts the ego at (50, -4.75) too.
    assert (ego[0], ego[1], ego[2]) == pytest.approx((50.0, -4.75, 0.0))
    # InTheMiddle starts at s=100: 25 m on, t=-1.75 from the reference line (esmini 3.6 puts
    # it at y=-1.0 on this map, for reasons not found: a difference the preview keeps).
    assert (target[0], target[1]) == pytest.approx((125.0, -1.75))
    # The brake point is 130 m along KeepRight (s=150): within 2 m once the ego, at 20 m/s from
    # s=50 and 0.5 m beside the point, has driven 98.06 m, after 4.903 s; the condition holds at the step
    # after, 4.95 s, as in esmini 3.6.
    (reach,) = [n for n in run.timeline if n.kind == "InLocationRadius"]
    assert reach.finished == pytest.approx(4.95)


def test_a_route_start_beyond_the_first_road_is_refused_by_the_preview_with_the_reason() -> None:
    scenario = import_file(ROUTES).scenario
    _actors(scenario)["Ego"].startPosition.pathS.value = 2000.0
    with pytest.raises(SimulationError) as refused:
        simulate(scenario, ROUTES)
    assert "Ego's start position: pathS=2000 m leaves road '1'" in str(refused.value)
    assert "only on the road its route starts on" in str(refused.value)

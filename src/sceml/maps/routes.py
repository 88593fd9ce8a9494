"""Routes through junctions: from a lane, which roads traffic can reach and how it turns.

Traffic on a lane runs to one end of its road (see `RoadMap.drives_along_s`). Roads linked end to
end are followed to the first junction; there every connection whose incoming road and lane match
leads, through its connecting road, to an exit road. The turn is read from the change of heading
between entering and leaving the connecting road: more than 30 degrees to the left is a left turn,
to the right a right turn, more than 150 degrees either way a U-turn, and straight otherwise.
`way_to` chains these routes junction by junction to a road further away, as players route an
actor to a destination beyond the next junction (esmini's AcquirePositionAction and routes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from .model import PositionError, Road, wrap_angle

if TYPE_CHECKING:
    from .roadmap import RoadMap

STRAIGHT_LIMIT = math.radians(30)
U_TURN_LIMIT = math.radians(150)
#: Roads followed end to end before giving up on reaching a junction.
MAX_ROADS_TO_JUNCTION = 20
#: Junctions passed before giving up on reaching a road (a city map's far side is within it).
MAX_JUNCTIONS = 30


@dataclass(frozen=True)
class Route:
    """One way through a junction: where it enters and leaves, and how it turns."""

    junction: str
    entry_road: str
    entry_lane: int
    connecting_road: str
    connecting_lane: int
    exit_road: str | None
    exit_lane: int | None
    turn: str  # left, right, straight or u-turn
    roads_before: tuple[str, ...] = ()

    def reaches(self, road_id: str, lane_id: int | None = None) -> bool:
        """Whether the route ends on (or passes along) this road (and lane)."""
        if road_id == self.connecting_road:
            return lane_id is None or lane_id == self.connecting_lane
        if road_id in self.roads_before:
            return False
        return road_id == self.exit_road and (lane_id is None or lane_id == self.exit_lane)


def turn_of(change: float) -> str:
    """The name of a heading change (rad, counter-clockwise positive)."""
    change = wrap_angle(change)
    if abs(change) >= U_TURN_LIMIT:
        return "u-turn"
    if change > STRAIGHT_LIMIT:
        return "left"
    if change < -STRAIGHT_LIMIT:
        return "right"
    return "straight"


def routes_from(road_map: RoadMap, road_id: str, lane_id: int) -> list[Route]:
    """Every route from a lane through the first junction its traffic reaches."""
    road = road_map.road(road_id)
    before: list[str] = []
    for _ in range(MAX_ROADS_TO_JUNCTION):
        before.append(road.id)
        forward = road_map.drives_along_s(road, lane_id)
        link = road.successor if forward else road.predecessor
        if link is None:
            return []
        if link.element_type == "junction":
            return _through_junction(road_map, road, lane_id, link.element_id, tuple(before[:-1]))
        section = road.section_at(road.length if forward else 0.0)
        lane = section.lane(lane_id)
        next_lane = None if lane is None else (lane.successor if forward else lane.predecessor)
        if next_lane is None or link.element_id not in road_map.roads:
            return []
        road, lane_id = road_map.roads[link.element_id], next_lane
    return []


def _through_junction(
    road_map: RoadMap, road: Road, lane_id: int, junction_id: str, before: tuple[str, ...]
) -> list[Route]:
    junction = road_map.junctions.get(junction_id)
    if junction is None:
        return []
    forward = road_map.drives_along_s(road, lane_id)
    entry = road_map.traffic_heading(road.id, lane_id, road.length if forward else 0.0)
    routes = []
    for connection in junction.connections:
        if connection.incoming_road != road.id:
            continue
        connecting = road_map.roads.get(connection.connecting_road)
        if connecting is None:
            continue
        for link in connection.lane_links:
            if link.source != lane_id:
                continue
            along = connection.contact_point != "end"
            far_s = connecting.length if along else 0.0
            try:
                leaving = road_map.traffic_heading(connecting.id, link.target, far_s)
            except PositionError:
                continue  # a lane link to a lane the connecting road does not have
            exit_link = connecting.successor if along else connecting.predecessor
            exit_road = exit_lane = None
            if exit_link is not None and exit_link.element_type == "road":
                exit_road = exit_link.element_id
                lane = connecting.section_at(far_s).lane(link.target)
                if lane is not None:
                    exit_lane = lane.successor if along else lane.predecessor
            routes.append(
                Route(
                    junction_id,
                    road.id,
                    lane_id,
                    connecting.id,
                    link.target,
                    exit_road,
                    exit_lane,
                    turn_of(leaving - entry),
                    before,
                )
            )
    return routes


def way_to(
    road_map: RoadMap, road_id: str, lane_id: int, goal_road: str, goal_lane: int | None = None
) -> list[Route] | None:
    """The routes, one per junction, by which traffic on a lane reaches `goal_road` (and
    `goal_lane`) through the fewest junctions; None when no way within `MAX_JUNCTIONS` does.

    Searched breadth first over the lanes each junction leads onto, in the map's order of
    connections, so the answer is the same every time; roads before the first junction count as
    reached only when they lie ahead on the lane (`Route.reaches`).
    """
    frontier = [(road_id, lane_id)]
    came: dict[tuple[str, int], tuple[tuple[str, int], Route] | None] = {frontier[0]: None}
    for _ in range(MAX_JUNCTIONS):
        following: list[tuple[str, int]] = []
        for lane in frontier:
            for route in routes_from(road_map, *lane):
                if route.reaches(goal_road, goal_lane):
                    return _chain(came, lane, route)
                if route.exit_road is None or route.exit_lane is None:
                    continue
                ahead = (route.exit_road, route.exit_lane)
                if ahead not in came:
                    came[ahead] = (lane, route)
                    following.append(ahead)
        if not following:
            return None
        frontier = following
    return None


def _chain(
    came: dict[tuple[str, int], tuple[tuple[str, int], Route] | None],
    lane: tuple[str, int],
    last: Route,
) -> list[Route]:
    """The routes from the search's first lane to `last`, first junction first."""
    chain = [last]
    step = came[lane]
    while step is not None:
        lane, route = step
        chain.append(route)
        step = came[lane]
    return chain[::-1]

"""Which way a routed action turns: TurnLeft, TurnRight or Cross, from the destination.

With a readable OpenDRIVE map the routes through the next junction from the actor's lane decide
(`sceml.maps.routes_from`): the route that reaches the destination's road names the turn. Without
one, or when no route reaches it, the change of heading decides: from the actor's heading before
the maneuver to the destination's heading (its `h`, or the lane's direction of traffic), or, when
the destination has no heading, to the bearing of the destination; more than 30 degrees to the
left is a left turn, to the right a right turn, anything else crosses straight on.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import scemlmodel as scm

from ..maps import PositionError, wrap_angle
from ..maps.positions import Located, centre
from ..maps.routes import routes_from, turn_of

if TYPE_CHECKING:
    from ..maps import RoadMap

KINDS = {"left": "TurnLeft", "right": "TurnRight", "straight": "Cross", "u-turn": "TurnLeft"}


@dataclass(frozen=True)
class Turn:
    """The kind chosen and how it was decided (for the report)."""

    kind: str
    how: str
    guessed: bool


def classify(
    start: scm.Position | None, destination: scm.Position | None, road_map: RoadMap | None
) -> Turn:
    """TurnLeft, TurnRight or Cross for an actor at `start` routed to `destination`."""
    here, there = centre(start, road_map), centre(destination, road_map)
    if here is None or there is None:
        return Turn("Cross", "no usable start or destination: taken as crossing straight", True)
    if road_map is not None:
        by_route = _by_route(road_map, start, here, there)
        if by_route is not None:
            return by_route
    return _by_heading(here, there)


def _by_route(
    road_map: RoadMap, start: scm.Position | None, here: Located, there: Located
) -> Turn | None:
    try:
        lanes = [here.lane[:2]] if here.lane else _lanes(road_map, here)
        targets = {lane[:2] for lane in ([there.lane] if there.lane else [])} or set(
            _lanes(road_map, there)
        )
        for road_id, lane_id in lanes:
            for route in routes_from(road_map, str(road_id), int(lane_id)):
                if any(route.reaches(str(r), int(lane)) for r, lane in targets):
                    how = f"the map's route through junction {route.junction} turns {route.turn}"
                    return Turn(KINDS[route.turn], how, route.turn == "u-turn")
    except PositionError:
        return None
    return None


def _lanes(road_map: RoadMap, point: Located) -> list[tuple[str, int]]:
    return [(c.road_id, c.lane_id) for c in road_map.world_to_lane(point.x, point.y, 0.5)]


def _by_heading(here: Located, there: Located) -> Turn:
    if here.heading is None:
        return Turn("Cross", "the start has no heading: taken as crossing straight", True)
    if there.heading is not None:
        change, what = wrap_angle(there.heading - here.heading), "heading"
    else:
        bearing = math.atan2(there.y - here.y, there.x - here.x)
        change, what = wrap_angle(bearing - here.heading), "bearing"
    turn = turn_of(change)
    how = f"the {what} changes by {math.degrees(change):.0f} degrees (no route on a map decided)"
    return Turn(KINDS[turn], how, True)

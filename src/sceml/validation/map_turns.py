"""Map rules on where actors go (SPEC §12): a turn's destination is reachable from where its actor
is, turning that way at a junction (SCEML-R006), and a crossing crosses the road (SCEML-R007).

The rules on positions and the map file itself are in `map_rules`, whose helpers these share.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..maps import (
    VEHICLE_LANE_TYPES,
    LaneCoordinate,
    PositionError,
    wrap_angle,
)
from ..maps.positions import Located, centre
from ..maps.routes import Route, routes_from, way_to
from ..model.departure import latest_placing, place_after
from ..model.graph import Flows, reachable
from .adjacency import own_adjacency
from .context import Context, is_kind
from .map_rules import (
    HEADING_LIMIT,
    POSITION_TOLERANCE,
    SOURCE,
    lane_words,
    map_of,
    point_text,
    usable_lanes,
)
from .reads import ROUTE, VALUE, Reads
from .registry import Finding, constraint

if TYPE_CHECKING:
    from ..maps.roadmap import RoadMap

ERROR = Severity.ERROR


def _flows_of(node: EObject, context: Context) -> Flows:
    """The graph `node` is read in: the expanded scenario for a module internal, else its own."""
    graph = node.eContainer()
    if graph is None:  # only the expansion's copies of module internals have no container
        flat = context.flat()
        if flat is not None and flat.holds(node):
            return flat
    return own_adjacency(graph, context)


def _ancestors(node: EObject, flows: Flows, context: Context) -> set[EObject]:
    """Every node a path of flows leads from to `node`, itself excluded (once per run and graph)."""
    return context.memo(
        ("ancestors", id(flows), node),
        lambda: reachable([node], backwards=True, flows=flows) - {node},
    )


def _actions_by_actor(flows: Flows, context: Context) -> dict[object, list[scm.ActionNode]]:
    """Each actor's action nodes in the graph's order (once per run and graph), so that a
    departure looks at one actor's nodes rather than at every node of the graph."""

    def group() -> dict[object, list[scm.ActionNode]]:
        by_actor: dict[object, list[scm.ActionNode]] = {}
        for n in flows.nodes:
            if isinstance(n, scm.ActionNode):
                by_actor.setdefault(n.referenceActor, []).append(n)
        return by_actor

    return context.memo(("actions by actor", id(flows)), group)


def _history(
    node: scm.ActionNode, context: Context
) -> tuple[Flows, list[scm.ActionNode], list[EObject]]:
    """The graph `node` is read in, its actor's action nodes before it (in the graph's order,
    so that of two parallel latest maneuvers the same one counts) and the latest of those that
    place the actor (`model.departure`); once per run and node, for its departure and for
    R006's lane change since."""

    def read() -> tuple[Flows, list[scm.ActionNode], list[EObject]]:
        flows = _flows_of(node, context)
        earlier = _ancestors(node, flows, context)
        actions = _actions_by_actor(flows, context).get(node.referenceActor, ())
        mine = [n for n in actions if n in earlier]
        return flows, mine, latest_placing(mine, lambda other: _ancestors(other, flows, context))

    return context.memo(("history", node), read)


def _departure(node: scm.ActionNode, context: Context) -> EObject | None:
    """Where the actor is when `node` starts (`model.departure`: the place of its latest earlier
    routed maneuver, trajectory or InLocationRadius, else its start)."""
    _, _, latest = _history(node, context)
    if latest:
        return place_after(latest[0])
    actor = node.referenceActor
    return actor.startPosition if actor is not None else None


def _lane_open(node: scm.ActionNode, context: Context) -> bool:
    """Whether a lane change or overtake of the actor since its departure leaves its lane open
    (R006 only: R007's crossing does not ask which lane the walker is on)."""
    flows, mine, latest = _history(node, context)
    if latest:
        since = reachable(latest, backwards=False, flows=flows)
        return any(isinstance(n, scm.LaneChange | scm.Overtake) for n in mine if n in since)
    return any(isinstance(n, scm.LaneChange | scm.Overtake) for n in mine)


def _lanes_at(road_map: RoadMap, point: Located, usable: frozenset[str]) -> list[LaneCoordinate]:
    if point.lane is not None:
        road_id, lane_id, s, offset = point.lane
        lane_type = road_map.band(road_id, lane_id, s).lane.type
        return [LaneCoordinate(road_id, lane_id, s, offset, lane_type)]
    return [
        lane
        for lane in road_map.world_to_lane(point.x, point.y, POSITION_TOLERANCE)
        if lane.lane_type in usable
    ]


@constraint(
    "SCEML-R006",
    ERROR,
    ("TurnLeft", "TurnRight"),
    "a turn's destination is reachable from the actor's lane through the junctions' "
    "connections, turning the named way at the next junction (or, beyond it, at one of them)",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, ROUTE),
)
def turn_follows_junction(node: scm.RoutedManeuver, context: Context) -> Iterator[Finding]:
    road_map = map_of(node, context)
    actor = node.referenceActor
    if (
        road_map is None
        or not isinstance(actor, scm.Actor)
        or is_kind(actor.eClass.name, "Pedestrian")
    ):
        return
    usable, _ = usable_lanes(actor)
    departure, lane_open = _departure(node, context), _lane_open(node, context)
    try:
        start = centre(departure, road_map)
        goal = centre(node.destination, road_map)
        if start is None or goal is None:
            return
        starts = _lanes_at(road_map, start, usable)
        goals = _lanes_at(road_map, goal, usable)
    except PositionError:
        return  # SCEML-R003
    if not starts or not goals:
        return  # SCEML-R004
    if start.heading is not None:
        facing = [
            lane
            for lane in starts
            if abs(
                wrap_angle(
                    start.heading - road_map.traffic_heading(lane.road_id, lane.lane_id, lane.s)
                )
            )
            <= HEADING_LIMIT
        ]
        starts = facing or starts
    if lane_open:  # after a lane change any lane of the road in the same direction will do
        starts = _same_direction_lanes(road_map, starts, usable)
    wanted = "left" if isinstance(node, scm.TurnLeft) else "right"
    routes = [
        route for lane in starts for route in routes_from(road_map, lane.road_id, lane.lane_id)
    ]
    arriving = [r for r in routes if any(r.reaches(g.road_id) for g in goals)]
    farther = None if arriving or not routes else _way_beyond(road_map, starts, goals)
    if farther is not None:
        # Players route to a destination beyond the next junction through as many as it
        # takes (esmini's AcquirePositionAction and the export's AssignRouteAction); the turn
        # is then one the way takes at some junction.
        if not any(r.turn == wanted for r in farther):
            yield (
                node.destination or node,
                f"{node.name}: the way to the destination from {lane_words(starts[0])} is "
                f"{_way_words(farther)}, with no {wanted} turn",
            )
        return
    if not routes:
        lane = starts[0]
        yield (
            node.destination or node,
            (
                f"{node.name}: from {lane_words(lane)} no junction connection leads anywhere, "
                f"so the {wanted} turn cannot be driven"
            ),
        )
    elif not arriving:
        goal_lane = goals[0]
        exits = sorted({f"{r.turn} to road {r.exit_road}" for r in routes})
        yield (
            node.destination or node,
            (
                f"{node.name}: the destination on {lane_words(goal_lane)} cannot be reached from "
                f"{lane_words(starts[0])} through junction {routes[0].junction} "
                f"(its connections go {', '.join(exits)})"
            ),
        )
    elif not any(r.turn == wanted for r in arriving):
        turns = " or ".join(sorted({_TURN_WORDS[r.turn] for r in arriving}))
        yield (
            node.destination or node,
            f"{node.name}: the way to the destination from {lane_words(starts[0])} is "
            f"{turns} at junction {arriving[0].junction}, not a {wanted} turn",
        )


_TURN_WORDS = {
    "left": "a left turn",
    "right": "a right turn",
    "straight": "straight on",
    "u-turn": "a U-turn",
}


def _way_beyond(
    road_map: RoadMap, starts: list[LaneCoordinate], goals: list[LaneCoordinate]
) -> list[Route] | None:
    """The way through the fewest junctions from one of the start lanes to one of the goals
    (on the goal's road; its lane is the position rule's business), or None."""
    ways = [
        way
        for lane in starts
        for goal in goals
        if (way := way_to(road_map, lane.road_id, lane.lane_id, goal.road_id)) is not None
    ]
    return min(ways, key=len) if ways else None


def _way_words(way: list[Route]) -> str:
    """`straight on at junction 7, then a left turn at junction 8`."""
    return ", then ".join(f"{_TURN_WORDS[r.turn]} at junction {r.junction}" for r in way)


def _same_direction_lanes(
    road_map: RoadMap, lanes: list[LaneCoordinate], usable: frozenset[str]
) -> list[LaneCoordinate]:
    widened = list(lanes)
    for lane in lanes:
        road = road_map.road(lane.road_id)
        along = road_map.drives_along_s(road, lane.lane_id)
        for band in road_map.bands(road, lane.s):
            same = road_map.drives_along_s(road, band.lane.id) == along
            if same and band.lane.type in usable and band.lane.id != lane.lane_id:
                widened.append(
                    LaneCoordinate(lane.road_id, band.lane.id, lane.s, 0.0, band.lane.type)
                )
    return widened


#: Points along a crossing path that are tested for lying on the roadway.
_CROSSING_SAMPLES = 40


@constraint(
    "SCEML-R007",
    ERROR,
    "Cross",
    "a Cross destination lies across the road: the way there crosses a driving lane",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, ROUTE),
)
def cross_crosses_the_road(node: scm.Cross, context: Context) -> Iterator[Finding]:
    road_map = map_of(node, context)
    if road_map is None or node.referenceActor is None:
        return
    departure = _departure(node, context)
    try:
        start = centre(departure, road_map)
        goal = centre(node.destination, road_map)
    except PositionError:
        return
    if start is None or goal is None:
        return
    for i in range(1, _CROSSING_SAMPLES):
        x = start.x + (goal.x - start.x) * i / _CROSSING_SAMPLES
        y = start.y + (goal.y - start.y) * i / _CROSSING_SAMPLES
        if any(lane.lane_type in VEHICLE_LANE_TYPES for lane in road_map.world_to_lane(x, y)):
            return
    yield (
        node.destination or node,
        (
            f"{node.name}: the way from {point_text(start.x, start.y)} to the destination "
            f"{point_text(goal.x, goal.y)} crosses no driving lane, so it does not cross the road"
        ),
    )

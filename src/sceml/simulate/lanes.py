"""Paths along lanes of the map: lane following, routes through junctions, neighbour lanes.

An actor on a lane follows the lane's centre line in its direction of travel and, at the end of
the road, the lane it links to: through a junction straight on (or the one way there is).
Lane centre lines are sampled once per map and lane, every `SAMPLE_STEP` m of s.
"""

from __future__ import annotations

import math
from weakref import WeakKeyDictionary

import numpy as np

from ..maps import LaneCoordinate, PositionError, RoadMap
from ..maps.routes import Route, routes_from, way_to
from .paths import LaneSpot, Path, offset_path

SAMPLE_STEP = 0.5  # m of s between samples of a lane's centre line
#: How far ahead a lane path is built; the path goes on straight after that.
AHEAD = 250.0  # m
_MAX_ROADS = 12

_Samples = tuple[np.ndarray, np.ndarray]
_samples: WeakKeyDictionary[RoadMap, dict[tuple[str, int], _Samples]] = WeakKeyDictionary()
#: Paths already built, per map (a path is never changed once built); at most `_KEEP` per map.
_paths: WeakKeyDictionary[RoadMap, dict[tuple[LaneSpot, tuple[Route, ...]], Path]] = (
    WeakKeyDictionary()
)
_KEEP = 512


def centre_samples(road_map: RoadMap, road_id: str, lane_id: int) -> _Samples:
    """The lane's centre line: s values (ascending) and points (N x 2), where the lane exists."""
    cache = _samples.setdefault(road_map, {})
    key = (road_id, lane_id)
    if key not in cache:
        road = road_map.road(road_id)
        line = road_map.reference_line(road_id)
        count = max(2, math.ceil(road.length / SAMPLE_STEP) + 1)
        cuts = [section.s for section in road.sections]
        ss, points = [], []
        for s in sorted({*np.linspace(0.0, road.length, count).tolist(), *cuts}):
            band = next((b for b in road_map.bands(road, s) if b.lane.id == lane_id), None)
            if band is None or band.width <= 0:
                continue
            x, y, h = line.pose(s)
            ss.append(s)
            points.append((x - band.centre * math.sin(h), y + band.centre * math.cos(h)))
        if len(ss) < 2:
            raise PositionError(f"road {road_id!r} has no lane {lane_id} to follow")
        cache[key] = (np.array(ss), np.array(points))
    return cache[key]


def start_spot(road_map: RoadMap, road_id: str, lane_id: int, s: float) -> LaneSpot:
    """A lane position, travelling in the lane's direction of traffic."""
    return LaneSpot(road_id, lane_id, s, road_map.drives_along_s(road_map.road(road_id), lane_id))


def lane_path(road_map: RoadMap, spot: LaneSpot, via: Route | tuple[Route, ...] = ()) -> Path:
    """The centre line ahead of `spot`, through linked roads, up to `AHEAD` m (or, given
    several routes, until past the last of them).

    At a junction the path takes the route of `via` that enters there, else the straight
    route, else the only route; it stops (and goes on straight) when there is no such choice.
    """
    built = _paths.setdefault(road_map, {})
    key = (spot, via if isinstance(via, tuple) else (via,))
    if key not in built:
        if len(built) >= _KEEP:
            built.pop(next(iter(built)))
        built[key] = _build_lane_path(road_map, spot, key[1])
    return built[key]


def _build_lane_path(road_map: RoadMap, spot: LaneSpot, via: tuple[Route, ...]) -> Path:
    points: list[tuple[float, float]] = []
    spots: list[LaneSpot | None] = []
    road, lane, s_from, forward = spot.road, spot.lane, spot.s, spot.forward
    travelled = 0.0
    dead_end = False
    # A chain of routes is followed past its last junction, however far (with up to
    # `_MAX_ROADS` more roads for each junction after the first).
    entries = {route.entry_road for route in via[1:]}
    for _ in range(_MAX_ROADS * (1 + len(entries))):
        ss, xy = centre_samples(road_map, road, lane)
        s_from = min(max(s_from, float(ss[0])), float(ss[-1]))
        first = (float(np.interp(s_from, ss, xy[:, 0])), float(np.interp(s_from, ss, xy[:, 1])))
        order = (
            np.nonzero(ss > s_from + 1e-9)[0]
            if forward
            else np.nonzero(ss < s_from - 1e-9)[0][::-1]
        )
        piece = [first, *map(tuple, xy[order].tolist())]
        piece_s = [s_from, *ss[order].tolist()]
        if points and math.dist(points[-1], piece[0]) < 1e-6:
            piece, piece_s = piece[1:], piece_s[1:]
        points.extend(piece)
        spots.extend(LaneSpot(road, lane, s, forward) for s in piece_s)
        travelled += (
            float(np.sum(np.hypot(*np.diff(np.array(piece), axis=0).T))) if len(piece) > 1 else 0.0
        )
        entries.discard(road)
        if travelled >= AHEAD and not entries:
            break
        following = next_lane(road_map, road, lane, forward, via)
        if following is None:
            dead_end = _ends_here(road_map, road, forward)
            break
        road, lane, forward, s_from = following
    return Path(np.array(points), spots, dead_end)


def _ends_here(road_map: RoadMap, road_id: str, forward: bool) -> bool:
    """Whether the road has no link at all at this end: the end of the road, where players
    stop an actor. (A junction with no way on for this lane is not a dead end.)"""
    road = road_map.road(road_id)
    return (road.successor if forward else road.predecessor) is None


def next_lane(
    road_map: RoadMap, road_id: str, lane_id: int, forward: bool, via: tuple[Route, ...] = ()
) -> tuple[str, int, bool, float] | None:
    """The lane that continues this one at its end in the direction of travel, or None."""
    road = road_map.road(road_id)
    link = road.successor if forward else road.predecessor
    if link is None:
        return None
    if link.element_type == "road":
        lane = road.section_at(road.length if forward else 0.0).lane(lane_id)
        following = None if lane is None else (lane.successor if forward else lane.predecessor)
        if following is None or link.element_id not in road_map.roads:
            return None
        ahead = link.contact_point != "end"
        next_road = road_map.roads[link.element_id]
        return next_road.id, following, ahead, 0.0 if ahead else next_road.length
    if road_map.drives_along_s(road, lane_id) != forward:
        return None  # against the traffic: the junction's connections do not say where to go
    route = next((r for r in via if r.entry_road == road_id), None)
    if route is None:
        routes = [r for r in routes_from(road_map, road_id, lane_id) if r.entry_road == road_id]
        straight = [r for r in routes if r.turn == "straight"]
        route = straight[0] if straight else (routes[0] if len(routes) == 1 else None)
    if route is None:
        return None
    connecting = road_map.road(route.connecting_road)
    ahead = road_map.drives_along_s(connecting, route.connecting_lane)
    return connecting.id, route.connecting_lane, ahead, 0.0 if ahead else connecting.length


def turn_path(
    road_map: RoadMap, spot: LaneSpot, turn: str, destination: tuple[float, float]
) -> Path | None:
    """The path from `spot` through the next junction turning `turn` (left or right), by the
    route that passes nearest to `destination`; when no such route leads to the destination's
    road but a way through several junctions that turns so does, that way (as players route
    there); None when there is neither."""
    if road_map.drives_along_s(road_map.road(spot.road), spot.lane) != spot.forward:
        return None
    candidates = [r for r in routes_from(road_map, spot.road, spot.lane) if r.turn == turn]
    goals = {lane.road_id for lane in road_map.world_to_lane(*destination)}
    if goals and not any(r.reaches(goal) for r in candidates for goal in goals):
        ways = [w for g in sorted(goals) if (w := way_to(road_map, spot.road, spot.lane, g))]
        way = min(ways, key=len) if ways else None
        if way is not None and len(way) > 1 and any(r.turn == turn for r in way):
            return lane_path(road_map, spot, via=tuple(way))
    paths = [lane_path(road_map, spot, via=route) for route in candidates]
    if not paths:
        return None
    return min(paths, key=lambda path: path.distance_to(*destination))


def neighbour(road_map: RoadMap, spot: LaneSpot, side: str) -> tuple[LaneSpot, float] | None:
    """The lane beside `spot` on the `side` (left or right) of travel, and how far its centre
    lies to the left of the current lane's centre (negative: to the right)."""
    road = road_map.road(spot.road)
    bands = [b for b in road_map.bands(road, spot.s) if b.width > 0]
    current = next((b for b in bands if b.lane.id == spot.lane), None)
    if current is None:
        return None
    towards = (1.0 if side == "left" else -1.0) * (1.0 if spot.forward else -1.0)  # along t
    beside = [b for b in bands if (b.centre - current.centre) * towards > 1e-6]
    if not beside:
        return None
    target = min(beside, key=lambda b: abs(b.centre - current.centre))
    shift = (target.centre - current.centre) * (1.0 if spot.forward else -1.0)
    return LaneSpot(spot.road, target.lane.id, spot.s, spot.forward), shift


def lane_under(
    road_map: RoadMap, x: float, y: float, heading: float
) -> tuple[LaneCoordinate, bool] | None:
    """The lane under a world point whose direction (either way along s) is nearest the
    heading, and whether travel runs along s; None off the lanes.

    As players do (esmini 3.6): an actor on a lane moves along it, forward unless its heading
    is more than 90 degrees off the lane's; one facing straight across (a pedestrian waiting at
    a kerb) walks along s.
    """
    best: tuple[LaneCoordinate, bool, float] | None = None
    for coordinate in road_map.world_to_lane(x, y):
        _, _, along = road_map.reference_line(coordinate.road_id).pose(coordinate.s)
        relative = math.atan2(math.sin(heading - along), math.cos(heading - along))
        closeness = abs(math.cos(relative))
        if best is None or closeness > best[2] + 1e-9:
            best = (coordinate, abs(relative) <= math.pi / 2 + 1e-9, closeness)
    return None if best is None else (best[0], best[1])


def onward(road_map: RoadMap, x: float, y: float, heading: float) -> Path | None:
    """The way on from a point along the lane under it, at the point's offset from the lane's
    centre; None off the lanes."""
    found = lane_under(road_map, x, y, heading)
    if found is None:
        return None
    coordinate, forward = found
    spot = LaneSpot(coordinate.road_id, coordinate.lane_id, coordinate.s, forward)
    lateral = coordinate.offset if forward else -coordinate.offset
    return offset_path(lane_path(road_map, spot), lateral)

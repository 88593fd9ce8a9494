"""Any model Position as one world pose on a map: the single meaning every stage shares.

Validation's map rules, the preview, the map view and the importer all ask "where is this
position?"; they ask here, so a road coordinate means the same point to each of them.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING

from pyecore.ecore import EObject

import scemlmodel as scm

from .model import LaneCoordinate, PositionError, WorldPose, wrap_angle
from .positions import nominal

if TYPE_CHECKING:
    from .roadmap import RoadMap


def road_to_lane(road_map: RoadMap, road_id: str, s: float, t: float) -> LaneCoordinate:
    """The lane holding road coordinate (s, t), with the offset from that lane's centre.

    PositionError names the road, or the s or t that lies off it.
    """
    road = road_map.road(road_id)
    if not -1e-6 <= s <= road.length + 1e-6:
        raise PositionError(
            f"s={s:g} m is outside road {road.id!r}, which is {road.length:g} m long"
        )
    bands = road_map.bands(road, s)
    for band in bands:
        low, high = sorted((band.inner, band.outer))
        if band.lane.id != 0 and band.width > 0 and low - 1e-9 <= t <= high + 1e-9:
            return LaneCoordinate(road.id, band.lane.id, s, t - band.centre, band.lane.type)
    edges = [edge for band in bands for edge in (band.inner, band.outer)]
    span = f"{min(edges):g} to {max(edges):g} m" if edges else "no lanes"
    raise PositionError(f"t={t:g} m is off road {road.id!r} at s={s:g} (its lanes span {span})")


def road_pose(
    road_map: RoadMap, road_id: str, s: float, t: float, h: float | None = None
) -> WorldPose:
    """The world pose of a road coordinate.

    Without `h` the heading is the direction of traffic of the lane the point lies in (as a
    lane position there); with `h` it is the road's direction at s turned by h, as
    OpenSCENARIO's relative Orientation of a RoadPosition says.
    """
    lane = road_to_lane(road_map, road_id, s, t)
    pose = road_map.lane_to_world(lane.road_id, lane.lane_id, s, lane.offset)
    if h is None:
        return pose
    _, _, road_heading = road_map.reference_line(lane.road_id).pose(s)
    return WorldPose(pose.x, pose.y, wrap_angle(road_heading + h))


#: The relative kinds: each names an entity and means a place relative to where it is.
RELATIVE_KINDS = (
    "RelativeLanePosition",
    "RelativeRoadPosition",
    "RelativeObjectPosition",
    "RelativeWorldPosition",
)


def is_relative(position: EObject | None) -> bool:
    """Whether a position names an entity (its meaning moves with that entity)."""
    return position is not None and position.eClass.name in RELATIVE_KINDS


def resolve(
    position: EObject | None,
    road_map: RoadMap | None,
    poses: Mapping[EObject, WorldPose] | None = None,
) -> WorldPose | None:
    """The world pose a position stands for (its nominal value); None when it has no number,
    needs a map that is not given, or is relative to an entity `poses` does not place.

    `poses`: where each actor is at the moment the position is used (Init: the starts; a
    destination: when its maneuver starts; a condition: when it is evaluated), as OpenSCENARIO
    players read a relative position. PositionError when the result lies off the map.
    """
    if is_relative(position):
        assert position is not None
        anchor = None if poses is None else poses.get(position.entity)
        return None if anchor is None else _relative(position, anchor, road_map)
    if isinstance(position, scm.WorldPosition):
        x, y, h = nominal(position.x), nominal(position.y), nominal(position.h, 0.0)
        if x is None or y is None or h is None:
            return None
        return WorldPose(x, y, wrap_angle(h))
    if road_map is None:
        return None
    if isinstance(position, scm.LanePosition):
        s, offset = nominal(position.s), nominal(position.offset, 0.0)
        if s is None or offset is None or not position.roadId or position.laneId is None:
            return None
        pose = road_map.lane_to_world(str(position.roadId), int(position.laneId), s, offset)
        h = nominal(position.h, 0.0)
        if h is None:
            return None
        return WorldPose(pose.x, pose.y, wrap_angle(pose.heading + h))
    if isinstance(position, scm.RoadPosition):
        s, t = nominal(position.s), nominal(position.t, 0.0)
        if s is None or t is None or not position.roadId:
            return None
        return road_pose(road_map, str(position.roadId), s, t, nominal(position.h))
    if isinstance(position, scm.RoutePosition):
        return route_pose(position, road_map)
    return None


def route_pose(position: scm.RoutePosition, road_map: RoadMap) -> WorldPose | None:
    """Where a RoutePosition is, as esmini 3.6 places one: pathS from the first waypoint in the
    direction of traffic of its lane. Only a place on the first waypoint's own road is worked
    out (no routing through junctions): PositionError says so for one beyond it, rather than
    guessing which road the route takes there."""
    if len(position.waypoints) < 2:
        raise PositionError("a route position needs a route of at least two waypoints")
    first = position.waypoints[0].position
    start = resolve(first, road_map)
    if start is None:
        return None
    lanes = road_map.world_to_lane(start.x, start.y)
    if not lanes:
        raise PositionError("the route's first waypoint is on no lane")
    lane = min(lanes, key=lambda c: abs(wrap_angle(start.heading - _traffic(road_map, c))))
    path_s = nominal(position.pathS, 0.0)
    if path_s is None:
        return None
    road = road_map.road(lane.road_id)
    s = lane.s + path_s if road_map.drives_along_s(road, lane.lane_id) else lane.s - path_s
    if not -1e-6 <= s <= road.length + 1e-6:
        raise PositionError(
            f"pathS={path_s:g} m leaves road {road.id!r} (the first waypoint's, "
            f"{road.length:g} m long) at s={s:g}: SceML places a route position only on the "
            "road its route starts on"
        )
    if position.laneId is None:
        t = nominal(position.t, 0.0)
        return None if t is None else road_pose(road_map, road.id, s, t)
    offset = nominal(position.laneOffset, 0.0)
    if offset is None:
        return None
    return road_map.lane_to_world(road.id, int(position.laneId), s, offset)


def _traffic(road_map: RoadMap, lane: LaneCoordinate) -> float:
    return road_map.traffic_heading(lane.road_id, lane.lane_id, lane.s)


def _relative(position: EObject, anchor: WorldPose, road_map: RoadMap | None) -> WorldPose | None:
    kind = position.eClass.name
    if kind == "RelativeWorldPosition":
        dx, dy = nominal(position.dx, 0.0), nominal(position.dy, 0.0)
        if dx is None or dy is None:
            return None
        return WorldPose(anchor.x + dx, anchor.y + dy, anchor.heading)
    if kind == "RelativeObjectPosition":
        dx, dy, h = nominal(position.dx, 0.0), nominal(position.dy, 0.0), nominal(position.h, 0.0)
        if dx is None or dy is None or h is None:
            return None
        cos, sin = math.cos(anchor.heading), math.sin(anchor.heading)
        return WorldPose(
            anchor.x + dx * cos - dy * sin,
            anchor.y + dx * sin + dy * cos,
            wrap_angle(anchor.heading + h),
        )
    if road_map is None:
        return None
    lane = _lane_under(road_map, anchor)
    if kind == "RelativeLanePosition":
        ds, offset = nominal(position.ds, 0.0), nominal(position.offset, 0.0)
        if ds is None or offset is None:
            return None
        moved = lane_after(lane.lane_id, int(position.dLane or 0))
        return road_map.lane_to_world(lane.road_id, moved, lane.s + ds, offset)
    ds, dt = nominal(position.ds, 0.0), nominal(position.dt, 0.0)
    if ds is None or dt is None:
        return None
    t = road_map.band(lane.road_id, lane.lane_id, lane.s).centre + lane.offset
    return road_pose(road_map, lane.road_id, lane.s + ds, t + dt)


def _lane_under(road_map: RoadMap, anchor: WorldPose) -> LaneCoordinate:
    """The lane the entity stands in (the one whose direction of traffic is nearest its heading
    where lanes overlap, at a junction)."""
    found = road_map.world_to_lane(anchor.x, anchor.y)
    if not found:
        raise PositionError(f"the entity at ({anchor.x:.2f}, {anchor.y:.2f}) is on no lane")
    return min(
        found,
        key=lambda c: abs(
            wrap_angle(anchor.heading - road_map.traffic_heading(c.road_id, c.lane_id, c.s))
        ),
    )


def lane_after(lane: int, delta: int) -> int:
    """`lane` moved by `delta` lanes (positive to the left), skipping the reference line's 0."""
    moved = lane + delta
    if lane < 0 <= moved or moved <= 0 < lane:
        moved += 1 if delta > 0 else -1
    return moved


def start_poses(actors: Iterable[EObject], road_map: RoadMap | None) -> dict[EObject, WorldPose]:
    """Where each actor starts, relative starts resolved after the actor they name (as players
    do in Init); an actor whose start cannot be resolved (off the map, a cycle) is left out."""
    poses: dict[EObject, WorldPose] = {}
    waiting = list(actors)
    while waiting:
        placed = []
        for actor in waiting:
            start = actor.startPosition
            if is_relative(start) and start.entity not in poses:
                continue
            try:
                pose = resolve(start, road_map, poses)
            except PositionError:
                pose = None
            if pose is not None:
                poses[actor] = pose
            placed.append(actor)
        if not placed:
            break  # the rest name each other in a cycle (or an actor not among them)
        waiting = [actor for actor in waiting if actor not in placed]
    return poses

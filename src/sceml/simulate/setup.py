"""Actors at their start: place, heading, path ahead, speed and box, from the model and map."""

from __future__ import annotations

from collections.abc import Mapping

from pyecore.ecore import EObject

import scemlmodel as scm

from ..maps import PositionError, RoadMap, WorldPose
from ..maps.resolve import is_relative, resolve, road_pose, road_to_lane, route_pose
from ..model.params import concrete
from . import lanes
from .actors import Actor
from .paths import LaneSpot, heading_path
from .world import SimulationError


def make_actor(
    actor: scm.Actor, road_map: RoadMap | None, starts: Mapping[EObject, WorldPose] | None = None
) -> Actor:
    """An actor at its start position with its initial speed, following its lane if on one.

    `starts`: where the actors start (maps.resolve.start_poses), for a start relative to one.
    """
    made = _placed(actor, road_map, starts)
    # Positions are the reference point; the box (gaps, collisions) is centred this far ahead.
    made.box_ahead = concrete(actor, "boxCenterX")
    return made


def trailer_at_rest(actor: scm.Actor) -> Actor:
    """A towed actor without a start of its own: `trailers.couple` places it at the hitch."""
    size = (concrete(actor, "length"), concrete(actor, "width"))
    made = Actor(*_identity(actor), size, heading_path(0.0, 0.0, 0.0), 0.0)
    made.box_ahead = concrete(actor, "boxCenterX")
    return made


def _placed(
    actor: scm.Actor, road_map: RoadMap | None, starts: Mapping[EObject, WorldPose] | None
) -> Actor:
    name = str(actor.name)
    size = (concrete(actor, "length"), concrete(actor, "width"))
    speed = concrete(actor, "initialSpeed")
    position = actor.startPosition
    try:
        if isinstance(position, scm.LanePosition):
            return _on_lane(actor, position, road_map, size, speed)
        if isinstance(position, scm.WorldPosition):
            return _in_world(actor, position, road_map, size, speed)
        if isinstance(position, scm.RoadPosition):
            return _on_road(actor, position, road_map, size, speed)
        if isinstance(position, scm.RoutePosition):
            return _on_route(actor, position, road_map, size, speed)
        if is_relative(position):
            pose = resolve(position, road_map, starts or {})
            if pose is None:
                other = getattr(position.entity, "name", None)
                raise SimulationError(
                    f"{name}'s start is relative to {other!r}, whose start is not known "
                    "(no such actor, a start off the map, or starts relative to each other)",
                    element=name,
                )
            return _in_world(actor, _world(pose), road_map, size, speed)
    except (PositionError, ValueError) as error:
        raise SimulationError(f"{name}'s start position: {error}", element=name) from None
    raise SimulationError(f"{name} has no start position", element=name)


def _on_lane(
    actor: scm.Actor,
    position: scm.LanePosition,
    road_map: RoadMap | None,
    size: tuple[float, float],
    speed: float,
) -> Actor:
    if road_map is None:
        raise SimulationError(
            f"{actor.name} starts on a lane, which needs an OpenDRIVE map", element=str(actor.name)
        )
    s, offset = concrete(position, "s"), concrete(position, "offset")
    road_map.band(str(position.roadId), int(position.laneId), s)  # PositionError when off the map
    if position.h is not None and concrete(position, "h") != 0.0:
        # turned against its lane: placed as at that world pose, as a turned road position is
        pose = road_map.lane_to_world(str(position.roadId), int(position.laneId), s, offset)
        turned = WorldPose(pose.x, pose.y, pose.heading + concrete(position, "h"))
        return _in_world(actor, _world(turned), road_map, size, speed)
    spot = lanes.start_spot(road_map, str(position.roadId), int(position.laneId), s)
    lateral = offset if spot.forward else -offset
    return Actor(*_identity(actor), size, lanes.lane_path(road_map, spot), speed, lateral)


def _in_world(
    actor: scm.Actor,
    position: scm.WorldPosition,
    road_map: RoadMap | None,
    size: tuple[float, float],
    speed: float,
) -> Actor:
    x, y = concrete(position, "x"), concrete(position, "y")
    heading = concrete(position, "h")
    spot = lanes.lane_under(road_map, x, y, heading) if road_map is not None else None
    if spot is None or road_map is None:
        return Actor(*_identity(actor), size, heading_path(x, y, heading), speed)
    coordinate, forward = spot
    lane_spot = LaneSpot(coordinate.road_id, coordinate.lane_id, coordinate.s, forward)
    lateral = coordinate.offset if forward else -coordinate.offset
    return Actor(*_identity(actor), size, lanes.lane_path(road_map, lane_spot), speed, lateral)


def _on_road(
    actor: scm.Actor,
    position: scm.RoadPosition,
    road_map: RoadMap | None,
    size: tuple[float, float],
    speed: float,
) -> Actor:
    """A road coordinate is the lane position it lies in (maps/resolve.py); a heading given
    relative to the road places the actor as at that world pose."""
    if road_map is None:
        raise SimulationError(
            f"{actor.name} starts on a road, which needs an OpenDRIVE map", element=str(actor.name)
        )
    road_id, s, t = str(position.roadId), concrete(position, "s"), concrete(position, "t")
    if position.h is not None:
        pose = road_pose(road_map, road_id, s, t, concrete(position, "h"))
        return _in_world(actor, _world(pose), road_map, size, speed)
    lane = road_to_lane(road_map, road_id, s, t)
    in_lane = scm.LanePosition(
        roadId=lane.road_id,
        laneId=lane.lane_id,
        s=scm.Value(value=s),
        offset=scm.Value(value=lane.offset),
    )
    return _on_lane(actor, in_lane, road_map, size, speed)


def _on_route(
    actor: scm.Actor,
    position: scm.RoutePosition,
    road_map: RoadMap | None,
    size: tuple[float, float],
    speed: float,
) -> Actor:
    """A route start is placed where the route puts it on its first road (maps/resolve.py:
    PositionError beyond it); from there the actor follows its lane, not the route's turns."""
    if road_map is None:
        raise SimulationError(
            f"{actor.name} starts on a route, which needs an OpenDRIVE map",
            element=str(actor.name),
        )
    pose = route_pose(position, road_map)
    if pose is None:
        raise SimulationError(
            f"{actor.name}'s start on a route has no concrete pathS or waypoint",
            element=str(actor.name),
        )
    return _in_world(actor, _world(pose), road_map, size, speed)


def _world(pose: WorldPose) -> scm.WorldPosition:
    return scm.WorldPosition(
        x=scm.Value(value=pose.x), y=scm.Value(value=pose.y), h=scm.Value(value=pose.heading)
    )


def _identity(actor: scm.Actor) -> tuple[str, str, bool]:
    return str(actor.name), actor.eClass.name, bool(actor.isEgo)

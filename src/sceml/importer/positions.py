"""Position elements to SceML positions: World, Lane, Road, the four relative positions (these
when the entity they name is an actor) and Route positions (their route given or taken from a
catalog, resolved before); None for the others."""

from __future__ import annotations

import math
from collections.abc import Mapping

from lxml import etree

import scemlmodel as scm

from . import traced
from .context import last_name
from .errors import BadValue


def position(
    holder: etree._Element | None, actors: Mapping[str, scm.Actor] | None = None
) -> scm.Position | None:
    """The SceML position of a `<Position>` element (or of the element holding one).

    `actors` by name: the entities a relative position may name (without, none maps).
    """
    if holder is None:
        return None
    if holder.tag != "Position":
        holder = holder.find("Position")
        if holder is None:
            return None
    kind = next((child for child in holder if isinstance(child.tag, str)), None)
    if kind is None:
        return None
    try:
        if kind.tag == "WorldPosition":
            return scm.WorldPosition(
                x=_value(kind, "x"),
                y=_value(kind, "y"),
                z=_value(kind, "z", 0.0),
                h=None if kind.get("h") is None else _value(kind, "h"),
            )
        if kind.tag == "LanePosition":
            return scm.LanePosition(
                roadId=str(kind.get("roadId")),
                laneId=lane_id(kind),
                s=_value(kind, "s"),
                offset=_value(kind, "offset", 0.0),
                h=_relative_heading(kind),
            )
        if kind.tag == "RoadPosition":
            return scm.RoadPosition(
                roadId=str(kind.get("roadId")),
                s=_value(kind, "s"),
                t=_value(kind, "t", 0.0),
                h=_relative_heading(kind),
            )
        if kind.tag in _RELATIVE and actors is not None:
            return _relative(kind, actors)
        if kind.tag == "RoutePosition":
            return _on_route(kind, actors)
    except ValueError:
        return None
    return None


def _relative_heading(kind: etree._Element) -> scm.Value | None:
    """A Road- or LanePosition's Orientation h (relative to the road or lane, the default type);
    None when absent.

    An absolute orientation has no place in the model's relative h: ValueError keeps the element
    for the caller's fallback (placing.py turns it with the map).
    """
    orientation = kind.find("Orientation")
    if orientation is None or orientation.get("h") is None:
        return None
    if orientation.get("type", "relative") != "relative":
        raise ValueError("absolute orientation")
    return _value(orientation, "h")


def _relative(kind: etree._Element, actors: Mapping[str, scm.Actor]) -> scm.Position | None:
    entity = actors.get(last_name(str(kind.get("entityRef"))))
    if entity is None:
        return None
    if kind.tag == "RelativeLanePosition":
        if kind.get("ds") is None and kind.get("dsLane") is not None:
            raise ValueError("dsLane")  # measured along the lane: SceML's ds is along the road
        return scm.RelativeLanePosition(
            entity=entity,
            dLane=lane_id(kind, "dLane"),
            ds=_value(kind, "ds", 0.0),
            offset=_value(kind, "offset", 0.0),
        )
    if kind.tag == "RelativeRoadPosition":
        return scm.RelativeRoadPosition(entity=entity, ds=_value(kind, "ds"), dt=_value(kind, "dt"))
    orientation = kind.find("Orientation")
    turned = orientation is not None and orientation.get("h") is not None
    if turned and orientation.get("type", "relative") != "relative":
        raise ValueError("absolute orientation")  # SceML's h is relative to the entity
    if kind.tag == "RelativeObjectPosition":
        return scm.RelativeObjectPosition(
            entity=entity,
            dx=_value(kind, "dx"),
            dy=_value(kind, "dy"),
            dz=_value(kind, "dz", 0.0),
            h=_value(orientation, "h") if turned else None,
        )
    if turned:
        raise ValueError("a turned RelativeWorldPosition")  # SceML's heads as its entity
    return scm.RelativeWorldPosition(
        entity=entity, dx=_value(kind, "dx"), dy=_value(kind, "dy"), dz=_value(kind, "dz", 0.0)
    )


def _on_route(kind: etree._Element, actors: Mapping[str, scm.Actor] | None) -> scm.RoutePosition:
    """A RoutePosition whose route is in its RouteRef (a catalog entry is already copied in)
    and whose place on it is given in road or lane coordinates; ValueError for the others
    (FromCurrentEntity, a route of fewer than two waypoints, a waypoint SceML cannot hold)."""
    route = kind.find("RouteRef/Route")
    lane = kind.find("InRoutePosition/FromLaneCoordinates")
    road = kind.find("InRoutePosition/FromRoadCoordinates")
    if route is None or (lane is None and road is None):
        raise ValueError("a route position from the current entity, or with no route")
    made = scm.RoutePosition(
        routeName=route.get("name"), closed=route.get("closed") in ("true", "1")
    )
    for waypoint in route.iterfind("Waypoint"):
        at = position(waypoint, actors)
        strategy = scm.RouteStrategy.getEEnumLiteral(waypoint.get("routeStrategy", "shortest"))
        # A route is fixed when it is given: no waypoint moves with an entity.
        if at is None or at.eClass.name in _RELATIVE or strategy is None:
            raise ValueError("a waypoint SceML cannot hold")
        made.waypoints.append(scm.RouteWaypoint(position=at, routeStrategy=strategy))
    if len(made.waypoints) < 2:
        raise ValueError("a route of fewer than two waypoints")
    if lane is not None:
        made.pathS = _value(lane, "pathS")
        made.laneId = lane_id(lane)
        made.laneOffset = _value(lane, "laneOffset", 0.0)
    else:
        assert road is not None
        made.pathS = _value(road, "pathS")
        made.t = _value(road, "t", 0.0)
    return made


_RELATIVE = frozenset(
    {
        "RelativeLanePosition",
        "RelativeRoadPosition",
        "RelativeObjectPosition",
        "RelativeWorldPosition",
    }
)

#: Lane ids are 32-bit integers in OpenSCENARIO (and in the model's EInt).
_LANE_LIMIT = 2**31 - 1


def lane_id(element: etree._Element, key: str = "laneId") -> int:
    """An integer lane id; BadValue (with the element) for NaN, infinity or beyond 32 bits."""
    value = number(element, key)
    if abs(value) > _LANE_LIMIT or value != int(value):
        raise BadValue(f"<{element.tag} {key}={element.get(key)!r}>: not a lane id", element)
    return int(value)


def _value(element: etree._Element, key: str, default: float | None = None) -> scm.Value:
    return traced.value(number(element, key, default))


def number(element: etree._Element, key: str, default: float | None = None) -> float:
    """A numeric attribute (already resolved); ValueError when missing without a default.

    A number that was a distributed `$parameter` comes back Traced (`traced.py`).
    """
    text = element.get(key)
    if text is None:
        if default is None:
            raise ValueError(key)
        return default
    value = float(text)
    if not math.isfinite(value):
        raise BadValue(f"<{element.tag} {key}={text!r}>: not a finite number", element)
    return traced.read(element, key, value)

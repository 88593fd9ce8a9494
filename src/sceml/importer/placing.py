"""Positions SceML has no class for, computed as the Lane or World position they stand for.

SceML knows World, Lane, Road and the four relative positions (positions.py). What those do
not hold (a dsLane, an absolute Orientation) is computed here: in Init, where every entity's
place is known, a RelativeLanePosition,
RelativeRoadPosition, RelativeWorldPosition or RelativeObjectPosition is the position it names
relative to an entity already placed. The relative meaning is lost (reported as guessed), the
start is not: a concrete scenario needs one for every actor. Later in the story the entity has
moved, so there these stay unresolved (None) and the caller keeps the element opaque.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from lxml import etree

import scemlmodel as scm

from ..maps.model import PositionError, WorldPose, wrap_angle
from ..maps.resolve import road_to_lane
from . import traced
from .context import Build, last_name
from .positions import lane_id, number, position

#: Position kinds that name an entity, readable only where that entity's place is known.
RELATIVE = frozenset(
    {
        "RelativeLanePosition",
        "RelativeRoadPosition",
        "RelativeWorldPosition",
        "RelativeObjectPosition",
    }
)


@dataclass(frozen=True)
class _Lane:
    """Where an entity stands on the map: road, lane, s, offset and its world pose."""

    road: str
    lane: int
    s: float
    offset: float
    pose: WorldPose


def place(build: Build, holder: etree._Element | None, *, initial: bool) -> scm.Position | None:
    """The SceML position of a `<Position>` (or its holder); None when it cannot be computed.

    `initial`: read in Init, where relative positions can be resolved.
    """
    plain = position(holder, build.actors)
    if isinstance(plain, scm.LanePosition) and build.road_map is not None:
        return _in_its_lane(build, plain, holder)
    if plain is not None or holder is None:
        return plain
    element = holder if holder.tag == "Position" else holder.find("Position")
    kind = None if element is None else next((c for c in element if isinstance(c.tag, str)), None)
    if kind is None or build.road_map is None and kind.tag != "RelativeWorldPosition":
        return None
    if kind.tag == "RoadPosition":
        return _turned_to_the_road(build, kind)
    if kind.tag == "LanePosition":
        return _turned_to_the_lane(build, kind)
    if kind.tag in RELATIVE and not initial:
        return None
    try:
        made = _compute(build, kind)
    except (PositionError, ValueError, KeyError, ZeroDivisionError):
        return None
    if made is not None:
        build.report.add(
            "guessed",
            f"<{kind.tag}> computed as the {made.eClass.name} {_text(made)} it stands for at "
            "the start (SceML has no such position; the relative meaning is not kept)",
            build.where(kind),
        )
    return made


def _turned_to_the_road(build: Build, kind: etree._Element) -> scm.RoadPosition | None:
    """A RoadPosition with an absolute Orientation: the same heading relative to the road at s
    (the model's h), exact, as the road's direction at s is fixed."""
    assert build.road_map is not None
    orientation = kind.find("Orientation")
    try:
        s, t = number(kind, "s"), number(kind, "t", 0.0)
        _, _, along = build.road_map.reference_line(str(kind.get("roadId"))).pose(s)
        h = number(orientation, "h") if orientation is not None else 0.0
    except (PositionError, ValueError):
        return None
    return scm.RoadPosition(
        roadId=str(kind.get("roadId")),
        s=traced.value(s),
        t=traced.value(t),
        h=scm.Value(value=wrap_angle(h - along)),
    )


def _turned_to_the_lane(build: Build, kind: etree._Element) -> scm.LanePosition | None:
    """A LanePosition with an absolute Orientation: the same heading relative to the lane's
    direction of traffic at s (the model's h), exact, as that direction is fixed."""
    assert build.road_map is not None
    orientation = kind.find("Orientation")
    try:
        road, lane = str(kind.get("roadId")), lane_id(kind)
        s, offset = number(kind, "s"), number(kind, "offset", 0.0)
        along = build.road_map.lane_to_world(road, lane, s, offset).heading
        h = number(orientation, "h") if orientation is not None else 0.0
    except (PositionError, ValueError):
        return None
    return scm.LanePosition(
        roadId=road,
        laneId=lane,
        s=traced.value(s),
        offset=traced.value(offset),
        h=scm.Value(value=wrap_angle(h - along)),
    )


def _in_its_lane(
    build: Build, given: scm.LanePosition, holder: etree._Element | None
) -> scm.LanePosition:
    """A lane position whose offset reaches into another lane, as that lane's position (the
    same point: players place it there, SceML's map rules want the lane it lies in)."""
    assert build.road_map is not None
    offset = float(given.offset.value) if given.offset is not None else 0.0
    try:
        band = build.road_map.band(str(given.roadId), int(given.laneId), float(given.s.value))
        if abs(offset) <= band.width / 2 + 1e-6:
            return given
        moved = _on_road(build, str(given.roadId), float(given.s.value), band.centre + offset)
    except (PositionError, ValueError):
        return given
    if moved is None or isinstance(given.s.value, traced.Traced):
        return given  # off the road, or a distributed s: left as written
    heading = _same_heading(build, given, moved)
    if heading is not None:
        moved.h = heading
    where = None if holder is None else holder.find(".//LanePosition")
    build.report.add(
        "guessed",
        f"lane {given.laneId} with offset {offset:g} m lies in lane {moved.laneId}: "
        f"read as {_text(moved)}",
        None if where is None else build.where(where),
    )
    return moved


def _same_heading(
    build: Build, given: scm.LanePosition, moved: scm.LanePosition
) -> scm.ParameterValue | None:
    """`given`'s heading relative to `moved`'s lane, which may carry traffic the other way;
    None when `given` has none and `moved`'s traffic runs the same way. A position without a
    heading faces along its own lane's traffic (as players place it), so moved into a lane of
    the other direction it faces backwards there (speed-profile's Car2: lane -1 with offset
    3.07 m lies in lane 1, and drives along lane -1's direction)."""
    assert build.road_map is not None
    h = given.h.value if isinstance(given.h, scm.Value) else (None if given.h else 0.0)
    if h is None or isinstance(h, traced.Traced):
        return given.h
    s = float(given.s.value)
    old = build.road_map.lane_to_world(str(given.roadId), int(given.laneId), s).heading
    new = build.road_map.lane_to_world(str(moved.roadId), int(moved.laneId), s).heading
    turned = wrap_angle(float(h) + old - new)
    if given.h is None and abs(turned) < 1e-9:
        return None
    return scm.Value(value=turned)


def _compute(build: Build, kind: etree._Element) -> scm.Position | None:
    tag = kind.tag
    if tag not in RELATIVE:
        return None
    anchor = _anchor(build, kind)
    if anchor is None:
        return None
    if tag == "RelativeLanePosition":
        ds = number(kind, "ds", 0.0) if kind.get("ds") else number(kind, "dsLane", 0.0)
        lane = _lane_after(anchor.lane, int(number(kind, "dLane")))
        return scm.LanePosition(
            roadId=anchor.road,
            laneId=lane,
            s=scm.Value(value=anchor.s + ds),
            offset=scm.Value(value=number(kind, "offset", 0.0)),
        )
    if tag == "RelativeRoadPosition":
        assert build.road_map is not None
        t = build.road_map.band(anchor.road, anchor.lane, anchor.s).centre + anchor.offset
        return _on_road(build, anchor.road, anchor.s + number(kind, "ds"), t + number(kind, "dt"))
    dx, dy = number(kind, "dx"), number(kind, "dy")
    h = anchor.pose.heading
    if tag == "RelativeObjectPosition":
        dx, dy = dx * math.cos(h) - dy * math.sin(h), dx * math.sin(h) + dy * math.cos(h)
    return scm.WorldPosition(
        x=scm.Value(value=anchor.pose.x + dx),
        y=scm.Value(value=anchor.pose.y + dy),
        z=scm.Value(value=0.0),
        h=_heading(kind, h),
    )


def _on_road(build: Build, road_id: str, s: float, t: float) -> scm.LanePosition | None:
    """The lane position of a road coordinate: the lane whose band holds t at s."""
    assert build.road_map is not None
    try:
        lane = road_to_lane(build.road_map, road_id, s, t)
    except PositionError:
        return None
    return scm.LanePosition(
        roadId=lane.road_id,
        laneId=lane.lane_id,
        s=scm.Value(value=s),
        offset=scm.Value(value=lane.offset),
    )


def _t(position: scm.RoadPosition) -> float:
    return float(position.t.value) if position.t is not None else 0.0


def _lane_after(lane: int, delta: int) -> int:
    """`lane` moved by `delta` lanes, skipping the reference line's lane 0."""
    moved = lane + delta
    if lane < 0 <= moved or moved <= 0 < lane:
        moved += 1 if delta > 0 else -1
    return moved


def _anchor(build: Build, kind: etree._Element) -> _Lane | None:
    """Where the entity a relative position names starts (it must be placed already)."""
    actor = build.actors.get(last_name(str(kind.get("entityRef"))))
    start = None if actor is None else actor.startPosition
    road_map = build.road_map
    if isinstance(start, scm.RoadPosition) and road_map is not None:
        start = _on_road(build, str(start.roadId), float(start.s.value), _t(start))
    if isinstance(start, scm.LanePosition) and road_map is not None:
        s, offset = float(start.s.value), float(start.offset.value) if start.offset else 0.0
        pose = road_map.lane_to_world(str(start.roadId), int(start.laneId), s, offset)
        if start.h is not None:
            turned = pose.heading + float(start.h.value)
            pose = WorldPose(pose.x, pose.y, wrap_angle(turned))
        return _Lane(str(start.roadId), int(start.laneId), s, offset, pose)
    if isinstance(start, scm.WorldPosition):
        x, y = float(start.x.value), float(start.y.value)
        heading = float(start.h.value) if start.h is not None else 0.0
        found = [] if road_map is None else road_map.world_to_lane(x, y)
        if not found:
            if kind.tag in ("RelativeWorldPosition", "RelativeObjectPosition"):
                return _Lane("", 0, 0.0, 0.0, WorldPose(x, y, heading))
            return None
        lane = found[0]
        return _Lane(lane.road_id, lane.lane_id, lane.s, lane.offset, WorldPose(x, y, heading))
    return None


def _heading(kind: etree._Element, entity: float) -> scm.Value | None:
    """The heading an Orientation gives (relative ones to the entity's), else the entity's."""
    orientation = kind.find("Orientation")
    if orientation is None or orientation.get("h") is None:
        return scm.Value(value=entity)
    h = number(orientation, "h")
    return scm.Value(value=h if orientation.get("type") == "absolute" else entity + h)


def _text(made: scm.Position) -> str:
    if isinstance(made, scm.LanePosition):
        offset = made.offset.value if made.offset is not None else 0.0
        return (
            f"(road {made.roadId}, lane {made.laneId}, s {made.s.value:.2f}, offset {offset:.2f})"
        )
    assert isinstance(made, scm.WorldPosition)
    return f"(x {made.x.value:.2f}, y {made.y.value:.2f})"

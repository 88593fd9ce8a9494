"""Map rules (SPEC §12): positions lie on the OpenDRIVE map the scenario names.

They run whenever the root node's map is an `.xodr` path; a simulator town name is left alone
with an info diagnostic. Positions inside module uses are checked with the values the use gives
them (through modules). A world position is on a lane when it lies inside the lane's edges or
within `POSITION_TOLERANCE` of them.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..maps import (
    BICYCLE_LANE_TYPES,
    PEDESTRIAN_LANE_TYPES,
    VEHICLE_EDGE_LANE_TYPES,
    VEHICLE_LANE_TYPES,
    LaneCoordinate,
    MapError,
    PositionError,
    wrap_angle,
)
from ..maps.positions import Located, locate, spread
from ..maps.reference import MapReference, is_town_name, map_reference
from ..maps.resolve import RELATIVE_KINDS, is_relative, road_to_lane, route_pose, start_poses
from ..model.graph import root_node
from .context import Context, is_kind, performer
from .reads import LEVEL, SELF, VALUE, Aspect, Reads
from .registry import Finding, constraint

if TYPE_CHECKING:
    from ..maps.roadmap import RoadMap

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
#: How far outside a lane's edges a world position may lie and still be on it (m).
POSITION_TOLERANCE = 0.5
#: How far a vehicle's heading may differ from its lane's direction of traffic.
HEADING_LIMIT = math.radians(45)
SOURCE = "SPEC §12"


# --- which map, which actor -------------------------------------------------------------------


def _reference(obj: EObject, context: Context) -> MapReference | None:
    top = context.home(obj)
    if not isinstance(top, scm.Scenario):
        return None  # a module definition on its own: its uses are checked in the scenario
    # Once per scenario: finding the root node walks every node, and every position asks.
    scenario = top
    return context.memo(("map reference", scenario), lambda: _scenario_reference(scenario, context))


def _scenario_reference(scenario: scm.Scenario, context: Context) -> MapReference | None:
    root = root_node(scenario)
    if root is None:
        return None  # no root node, so no map (SCEML-S001 says so)
    file = context.document.path if context.document is not None else None
    # A model built in Python has no folder for a relative path to start from, and the working
    # directory is an accident: it is checked against an absolute map path only.
    text = (root.map or "").strip()
    if file is None and text and not is_town_name(text) and not Path(text).is_absolute():
        return None
    roots = context.document.allowed_roots if context.document is not None else None
    return map_reference(root.map, file, roots)


def _loaded(reference: MapReference, context: Context) -> RoadMap | MapError:
    def read() -> RoadMap | MapError:
        from ..maps.roadmap import load_map  # numpy and pyclothoids only when a map is read

        try:
            return load_map(reference.path, reference.roots)  # type: ignore[arg-type]
        except MapError as error:
            return error

    return context.memo(("map", reference.path), read)


def map_of(obj: EObject, context: Context) -> RoadMap | None:
    """The readable OpenDRIVE map `obj`'s scenario names, or None (no map, a town, unreadable)."""
    reference = _reference(obj, context)
    if reference is None or reference.path is None:
        return None
    loaded = _loaded(reference, context)
    return None if isinstance(loaded, MapError) else loaded


def _what(position: EObject) -> str:
    """Whose position it is, in words: "start of actor 'ego'", "destination of TurnRight_1"."""
    owner = position.eContainer()
    feature = position.eContainmentFeature()
    role = {"startPosition": "start", "waypoints": "waypoint"}.get(
        str(feature.name) if feature is not None else "", str(getattr(feature, "name", "position"))
    )
    if isinstance(owner, scm.Actor):
        return f"{role} of actor {owner.name!r}"
    return f"{role} of {getattr(owner, 'name', None) or owner.eClass.name}"


def usable_lanes(actor: scm.Actor) -> tuple[frozenset[str], str]:
    """The lane types an actor may be on, and what it needs in words."""
    name = actor.eClass.name
    if is_kind(name, "Pedestrian"):
        return PEDESTRIAN_LANE_TYPES, "a sidewalk or the roadway"
    if is_kind(name, "Bicycle"):
        return BICYCLE_LANE_TYPES, "the roadway, a bike lane or a sidewalk"
    return VEHICLE_LANE_TYPES, "a driving lane"


def _is_vehicle(actor: scm.Actor) -> bool:
    return not (is_kind(actor.eClass.name, "Pedestrian") or is_kind(actor.eClass.name, "Bicycle"))


def _kind(actor: scm.Actor) -> str:
    return str(actor.eClass.name).lower()


def point_text(x: float, y: float) -> str:
    return f"({x:.2f}, {y:.2f})"


def lane_words(lane: LaneCoordinate) -> str:
    return f"road {lane.road_id}, lane {lane.lane_id}"


# --- the map itself ---------------------------------------------------------------------------


@constraint(
    "SCEML-R001",
    ERROR,
    "RootNode",
    "a map given as an OpenDRIVE path names a readable OpenDRIVE file",
    source=SOURCE,
    reads=Reads(SELF, LEVEL),
)
def map_file_is_opendrive(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    reference = _reference(root, context)
    if reference is None or reference.path is None:
        return
    loaded = _loaded(reference, context)
    if isinstance(loaded, MapError):
        detail = loaded.message + (f" (line {loaded.line})" if loaded.line else "")
        yield root, f"map {reference.text!r} ({reference.path}): {detail}"


@constraint(
    "SCEML-R002",
    INFO,
    "RootNode",
    "a map given as a simulator town name or a scene graph (3D scenery with no roads) is not "
    "read: positions are not checked against it",
    source=SOURCE,
    reads=Reads(SELF, LEVEL),
)
def town_is_not_checked(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    reference = _reference(root, context)
    if reference is None or reference.path is not None:
        return
    what = (
        "a scene graph with no roads (every position is a world position)"
        if reference.scenery is not None
        else "a simulator town, not an OpenDRIVE file"
    )
    yield root, f"map {reference.text!r} is {what}: positions are not checked against it"


# --- positions --------------------------------------------------------------------------------


@constraint(
    "SCEML-R003",
    ERROR,
    "LanePosition",
    "a lane position names a road and lane of the map, with s within the road and the offset "
    "within the lane",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, LEVEL),
    judges_stated_values=True,
)
def lane_position_exists(position: scm.LanePosition, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    if road_map is None or position.roadId is None or position.laneId is None:
        return
    for s in spread(position.s) or []:
        for offset in spread(position.offset, 0.0) or []:
            problem = road_map.lane_problem(str(position.roadId), int(position.laneId), s, offset)
            if problem is not None:
                yield position, f"{_what(position)}: {problem}"
                return


@constraint(
    "SCEML-R008",
    ERROR,
    "RoadPosition",
    "a road position names a road of the map, with s within the road and t on one of its lanes",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, LEVEL),
    judges_stated_values=True,
)
def road_position_exists(position: scm.RoadPosition, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    if road_map is None or not position.roadId:
        return
    for s in spread(position.s) or []:
        for t in spread(position.t, 0.0) or []:
            try:
                road_to_lane(road_map, str(position.roadId), s, t)
            except PositionError as error:
                yield position, f"{_what(position)}: {error}"
                return


@constraint(
    "SCEML-R010",
    ERROR,
    "RoutePosition",
    "a route position can be placed on the map: its route has two or more waypoints, the first "
    "on a lane, and pathS stays on the road the route starts on (SceML does not route through "
    "junctions)",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, LEVEL),
)
def route_position_placed(position: scm.RoutePosition, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    if road_map is None:
        return
    try:
        route_pose(position, road_map)
    except PositionError as error:
        yield position, f"{_what(position)}: {error}"


@dataclass(frozen=True)
class _Ground:
    """What a position stands on: the lane types there (none: off the road network) and how to
    name the place in a message."""

    types: tuple[str, ...]
    place: str  # "lane -2 of road 1" or "(5.00, -15.00)"
    lane: str  # "" for a lane position; " (road 1, lane -2)" for a world point
    off_road: str = ""  # the nearest lane, for a point off the road network

    def words(self, lane_type: str) -> str:
        return (
            f"{self.place} is a {lane_type} lane"
            if not self.lane
            else f"{self.place} is on a {lane_type} lane{self.lane}"
        )


def _grounds(position: EObject, road_map: RoadMap, context: Context) -> list[_Ground]:
    """The ground under each point of a position (a relative start where the starts put it);
    once per run and position, for SCEML-R004 and R009 alike."""
    return context.memo(
        ("grounds", position), lambda: list(_find_grounds(position, road_map, context))
    )


def _find_grounds(position: EObject, road_map: RoadMap, context: Context) -> Iterator[_Ground]:
    try:
        points = _relative_start(position, road_map, context) or locate(position, road_map)
    except PositionError:
        return  # SCEML-R003, R008 or R010 says what is wrong with the position
    for point in points:
        if point.lane is not None:
            road_id, lane_id, s, _ = point.lane
            lane_type = road_map.band(road_id, lane_id, s).lane.type
            yield _Ground((lane_type,), f"lane {lane_id} of road {road_id}", "")
            continue
        lanes = road_map.world_to_lane(point.x, point.y, POSITION_TOLERANCE)
        if not lanes:
            yield _Ground((), point_text(point.x, point.y), "", _nearest(road_map, point))
            continue
        words = f" ({lane_words(lanes[0])})"
        yield _Ground(tuple(lane.lane_type for lane in lanes), point_text(point.x, point.y), words)


@constraint(
    "SCEML-R004",
    ERROR,
    ("WorldPosition", "LanePosition", "RoadPosition", "RoutePosition", *RELATIVE_KINDS),
    "a position lies on a lane that fits its actor: driving lanes (or a shoulder, stop or "
    "parking lane) for vehicles; the roadway, sidewalks and bike lanes for bicycles and "
    "pedestrians",
    source=SOURCE,
    through_modules=True,
    # A relative start reads the starts of the actors it is placed after.
    reads=Reads(VALUE, LEVEL | Aspect.CAST | Aspect.POSITIONS),
    judges_stated_values=True,
)
def position_fits_actor(position: EObject, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    actor = performer(position.eContainer())
    if road_map is None or actor is None:
        return
    usable, needs = usable_lanes(actor)
    if _is_vehicle(actor):
        usable = usable | VEHICLE_EDGE_LANE_TYPES  # SCEML-R009 warns there
    for ground in _grounds(position, road_map, context):
        if not ground.types:
            yield (
                position,
                f"{_what(position)}: {ground.place} is off the road network{ground.off_road}",
            )
            return
        if not any(lane_type in usable for lane_type in ground.types):
            yield (
                position,
                f"{_what(position)}: {ground.words(ground.types[0])}; a {_kind(actor)} needs "
                f"{needs}",
            )
            return


@constraint(
    "SCEML-R009",
    WARNING,
    ("WorldPosition", "LanePosition", "RoadPosition", "RoutePosition", *RELATIVE_KINDS),
    "a vehicle's position on a shoulder, stop, parking or restricted lane is meant: vehicles stand "
    "or pull over there but do not normally drive there",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, LEVEL | Aspect.CAST | Aspect.POSITIONS),
    judges_stated_values=True,
)
def vehicle_on_the_edge(position: EObject, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    actor = performer(position.eContainer())
    if road_map is None or actor is None or not _is_vehicle(actor):
        return
    for ground in _grounds(position, road_map, context):
        if ground.types and not any(t in VEHICLE_LANE_TYPES for t in ground.types):
            edge = next((t for t in ground.types if t in VEHICLE_EDGE_LANE_TYPES), None)
            if edge is not None:
                yield (
                    position,
                    f"{_what(position)}: {ground.words(edge)}, not a driving lane; a "
                    f"{_kind(actor)} may stand there, but does it drive there?",
                )
                return


def _relative_start(position: EObject, road_map: RoadMap, context: Context) -> list[Located]:
    """A relative start where the other starts put it (maps.resolve, as players read Init); []
    for any other position (a relative destination or condition moves with its entity)."""
    actor = position.eContainer()
    if not is_relative(position) or not isinstance(actor, scm.Actor):
        return []
    root = actor.eContainer()
    starts = context.memo(("start poses", root), lambda: start_poses(root.actors, road_map))
    pose = starts.get(actor)
    return [] if pose is None else [Located(pose.x, pose.y, pose.heading)]


def _nearest(road_map: RoadMap, point: Located) -> str:
    lanes = road_map.world_to_lane(point.x, point.y, 50.0)
    if not lanes:
        return " (no lane within 50 m)"
    lane = lanes[0]
    return f" (the nearest lane, {lane_words(lane)}, is {lane.outside:.1f} m away)"


@constraint(
    "SCEML-R005",
    WARNING,
    "WorldPosition",
    "a vehicle's heading roughly follows its lane's direction of traffic (within 45 degrees)",
    source=SOURCE,
    through_modules=True,
    reads=Reads(VALUE, LEVEL | Aspect.CAST),
    judges_stated_values=True,
)
def heading_follows_lane(position: scm.WorldPosition, context: Context) -> Iterator[Finding]:
    road_map = map_of(position, context)
    actor = performer(position.eContainer())
    if road_map is None or actor is None or not _is_vehicle(actor):
        return
    if position.h is None and not isinstance(position.eContainer(), scm.Actor):
        return  # a destination without a heading says nothing about direction
    for point in locate(position, road_map):
        heading = point.heading if point.heading is not None else 0.0
        lanes = [
            lane
            for lane in road_map.world_to_lane(point.x, point.y, POSITION_TOLERANCE)
            if lane.lane_type in VEHICLE_LANE_TYPES and lane.lane_type != "bidirectional"
        ]
        if not lanes:
            continue  # SCEML-R004's business
        deviations = [
            abs(wrap_angle(heading - road_map.traffic_heading(lane.road_id, lane.lane_id, lane.s)))
            for lane in lanes
        ]
        if min(deviations) > HEADING_LIMIT:
            lane = lanes[deviations.index(min(deviations))]
            traffic = road_map.traffic_heading(lane.road_id, lane.lane_id, lane.s)
            yield (
                position,
                (
                    f"{_what(position)}: heading {heading:.2f} rad differs by "
                    f"{math.degrees(min(deviations)):.0f} degrees from the traffic on "
                    f"{lane_words(lane)} ({traffic:.2f} rad)"
                    + ("; h is not set, so 0 is used" if position.h is None else "")
                ),
            )
            return

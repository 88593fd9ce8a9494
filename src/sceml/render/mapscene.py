"""What the map view draws, in metres on the map: actors, destinations, waypoints and radii.

The scene is plain data computed from the model and the OpenDRIVE map, with no plotting library;
`mapview` turns it into a picture. Module uses are flattened first, so a position inside a use is
placed with the values the use gives it. A logical position keeps every point `locate` finds for
it, and the area (or segment) those points span: the view shades it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from pyecore.ecore import EObject

import scemlmodel as scm

from ..errors import SceMLError
from ..maps import PositionError, RoadMap, WorldPose, load_map
from ..maps.positions import Located, centre, is_concrete, locate, nominal, spread
from ..maps.reference import map_reference
from ..maps.resolve import is_relative, start_poses
from ..model import catalog
from ..model.documents import allowed_roots_of
from ..model.graph import actors, level_text, root_node, topological_order
from ..model.towing import couplings
from ..modules import flatten
from . import style
from .flow import RenderError
from .labels import scenario_title

Point = tuple[float, float]
Box = tuple[float, float, float, float]  # xmin, ymin, xmax, ymax

#: Metres of map shown around what the scenario uses.
MARGIN = 15.0
#: Points along a lane stretch (a lane position whose s is a range or distribution).
_REGION_STEPS = 24


class MapViewError(RenderError):
    """The map view does not apply: the scenario names no OpenDRIVE file (a town, or nothing).

    Like asking for a library's module on a scenario, it is the input that does not fit the
    request, hence exit code 2.
    """

    exit_code = 2


@dataclass(frozen=True)
class Place:
    """Where a position puts something: its representative point, every point it allows, and
    (when it allows more than one) the polygon those points span, which may be a segment."""

    centre: Located
    points: tuple[Located, ...]
    region: tuple[Point, ...] | None = None

    @property
    def ranged(self) -> bool:
        return self.region is not None


@dataclass(frozen=True)
class ActorMark:
    """An actor at its start: kind, size (m) and place (None when it has no usable position);
    `ahead`: how far its box's centre lies ahead of the place (Actor.boxCenterX)."""

    name: str
    kind: str
    ego: bool
    length: float
    width: float
    place: Place | None
    ahead: float = 0.0

    def corners(self) -> np.ndarray:
        """The bounding box's four corners (4 x 2), rotated by the heading (0 when unknown)."""
        assert self.place is not None
        point = self.place.centre
        heading = point.heading or 0.0
        front, back = self.ahead + self.length / 2, self.ahead - self.length / 2
        half = np.array(
            [
                (front, self.width / 2),
                (back, self.width / 2),
                (back, -self.width / 2),
                (front, -self.width / 2),
            ]
        )
        cos, sin = math.cos(heading), math.sin(heading)
        rotation = np.array([[cos, -sin], [sin, cos]])
        return np.asarray(half @ rotation.T + np.array([point.x, point.y]))


@dataclass(frozen=True)
class TargetMark:
    """A destination (TurnLeft/TurnRight/Cross) or waypoint (FollowTrajectory) of an actor.

    `origin` is where the dashed line to it starts: the actor's start or its previous target.
    """

    node: str
    kind: str  # "destination" or "waypoint"
    actor: str | None
    place: Place
    origin: Point | None


@dataclass(frozen=True)
class CircleMark:
    """The radius of an InLocationRadius (around its position) or an InVehicleRadius (around
    the target actor's start). `radii` holds one radius, or every radius a logical value allows
    (min, middle, max): the view shades the ring between the smallest and the largest."""

    node: str
    kind: str  # "location" or "vehicle"
    actor: str | None
    centre: Point
    radii: tuple[float, ...]
    place: Place | None = None  # an InLocationRadius's position (its range, when logical)


@dataclass
class MapScene:
    """Everything the map view draws, and the notes it adds (what could not be placed, and why)."""

    road_map: RoadMap
    title: str
    level: str
    actors: list[ActorMark] = field(default_factory=list)
    targets: list[TargetMark] = field(default_factory=list)
    circles: list[CircleMark] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def placed_actors(self) -> list[ActorMark]:
        """The actors drawn on the map."""
        return [actor for actor in self.actors if actor.place is not None]

    def extent(self, kind: str = "scenario") -> Box:
        """The region shown: `map` is every road; `scenario` is what the scenario uses, with
        a margin, and at least the junctions."""
        if kind == "map":
            return self.road_map.bounds()
        used = _points_box(self._used_points())
        boxes = [_grow(box, MARGIN) for box in [used, *junction_boxes(self.road_map)] if box]
        return _union(boxes) if boxes else self.road_map.bounds()

    def _used_points(self) -> Iterator[Point]:
        for actor in self.placed_actors():
            yield from (tuple(corner) for corner in actor.corners())
        for target in self.targets:
            yield from ((p.x, p.y) for p in target.place.points)
        for circle in self.circles:
            radius = max(circle.radii)
            x, y = circle.centre
            yield from ((x - radius, y - radius), (x + radius, y + radius))


def build_scene(scenario: scm.Scenario, scenario_file: str | Path | None) -> MapScene:
    """The scene of a scenario on the OpenDRIVE map its root names (relative to `scenario_file`).

    MapViewError when the map is a simulator town or missing; MapError when the file cannot be
    read. Positions that do not fit the map are left out with a note, not raised: telling
    what is wrong with them is validation's job.
    """
    root = root_node(scenario)
    roots = allowed_roots_of(scenario)  # as the scenario was loaded: its folders and --allow
    reference = map_reference(root.map if root is not None else None, scenario_file, roots)
    where = str(scenario_file) if scenario_file is not None else None
    if reference is None:
        raise MapViewError(
            "the scenario names no map; the map view needs an OpenDRIVE (.xodr) file", file=where
        )
    if reference.path is None:
        what = (
            "a scene graph with no roads" if reference.scenery is not None else "a simulator town"
        )
        raise MapViewError(
            f"the scenario's map {reference.text!r} is {what}; the map view needs an "
            "OpenDRIVE (.xodr) file",
            file=where,
        )
    scene = MapScene(
        load_map(reference.path, reference.roots),
        scenario_title(scenario),
        level_text(scenario),
    )
    flat = _flattened(scenario, scene.notes)
    _add_actors(scene, flat)
    _add_nodes(scene, flat)
    unplaced = [a.name for a in scene.actors if a.place is None]
    if not scene.placed_actors():
        scene.notes.insert(0, "the actors have no positions: only the map is drawn")
    elif unplaced:
        scene.notes.insert(0, f"not on the map (no usable start position): {', '.join(unplaced)}")
    return scene


def _flattened(scenario: scm.Scenario, notes: list[str]) -> scm.Scenario:
    """The scenario with its module uses expanded, or as it is when a use cannot be expanded."""
    if not any(isinstance(node, scm.ModuleUse) for node in scenario.nodes):
        return scenario
    try:
        return flatten(scenario)
    except SceMLError as error:
        notes.append(f"module uses are not drawn: {error.message}")
        return scenario


def _add_actors(scene: MapScene, scenario: scm.Scenario) -> None:
    starts = start_poses(actors(scenario), scene.road_map)  # relative starts need the others'
    for actor in actors(scenario):
        name = str(actor.name or "?")
        dimensions = catalog.actor_dimensions(actor)
        if is_relative(actor.startPosition):
            place = _relative_start(actor, starts, scene, f"{name}'s start position")
        else:
            place = _place(actor.startPosition, scene, f"{name}'s start position")
        scene.actors.append(
            ActorMark(
                name,
                actor.eClass.name,
                bool(actor.isEgo),
                nominal(actor.length, dimensions.get("length", 1.0)) or 1.0,
                nominal(actor.width, dimensions.get("width", 1.0)) or 1.0,
                place,
                nominal(actor.boxCenterX, 0.0) or 0.0,
            )
        )
    _hitch_trailers(scene, scenario)


def _hitch_trailers(scene: MapScene, scenario: scm.Scenario) -> None:
    """Each towed actor in line behind its tower, its coupler at the hitch (Actor.trailer,
    release 1.4), as players and the preview place it whatever start it has."""
    marks = {mark.name: index for index, mark in enumerate(scene.actors)}
    for link in couplings(actors(scenario)):
        tower = scene.actors[marks[link.tower]]
        if tower.place is None:
            continue
        at = tower.place.centre
        heading = at.heading or 0.0
        back = link.hitch - link.coupler
        point = Located(at.x + back * math.cos(heading), at.y + back * math.sin(heading), heading)
        index = marks[link.trailer]
        scene.actors[index] = replace(scene.actors[index], place=Place(point, (point,)))


def _add_nodes(scene: MapScene, scenario: scm.Scenario) -> None:
    """Targets and radii, in flow order, so a route's lines join one target to the next."""
    order, cyclic = topological_order(scenario)
    last: dict[str, Point] = {
        actor.name: (actor.place.centre.x, actor.place.centre.y)
        for actor in scene.placed_actors()
        if actor.place is not None
    }
    for node in [*order, *[n for n in scenario.nodes if n in cyclic]]:
        if isinstance(node, scm.RoutedManeuver | scm.FollowTrajectory):
            _add_targets(scene, node, last)
        elif isinstance(node, scm.InLocationRadius):
            place = _place(node.position, scene, f"{node.name}'s position")
            if place is not None:
                _add_circle(scene, node, "location", (place.centre.x, place.centre.y), place)
        elif isinstance(node, scm.InVehicleRadius):
            target = _actor_mark(scene, node.targetActor)
            if target is not None and target.place is not None:
                point = target.place.centre
                _add_circle(scene, node, "vehicle", (point.x, point.y))


def _add_targets(
    scene: MapScene, node: scm.RoutedManeuver | scm.FollowTrajectory, last: dict[str, Point]
) -> None:
    actor = _actor_name(node.referenceActor)
    if isinstance(node, scm.FollowTrajectory):
        positions, kind = list(node.waypoints), "waypoint"
    else:
        positions, kind = [node.destination], "destination"
    for index, position in enumerate(positions):
        label = str(node.name) if len(positions) == 1 else f"{node.name} #{index + 1}"
        place = _place(position, scene, f"{label}'s {kind}")
        if place is None:
            continue
        origin = last.get(actor) if actor is not None else None
        scene.targets.append(TargetMark(label, kind, actor, place, origin))
        if actor is not None:
            last[actor] = (place.centre.x, place.centre.y)


def _add_circle(
    scene: MapScene, node: scm.ActionNode, kind: str, point: Point, place: Place | None = None
) -> None:
    default = catalog.parameter(node, "radius").default
    radii = spread(node.radius, default)
    if not radii:
        scene.notes.append(f"{node.name}: the radius has no value, so no circle is drawn")
        return
    positive = sorted({r for r in radii if r > 0})
    if positive:
        scene.circles.append(
            CircleMark(
                str(node.name),
                kind,
                _actor_name(node.referenceActor),
                point,
                tuple(positive),
                place,
            )
        )


def _actor_name(participant: EObject | None) -> str | None:
    return str(participant.name) if participant is not None and participant.name else None


def _actor_mark(scene: MapScene, participant: EObject | None) -> ActorMark | None:
    name = _actor_name(participant)
    return next((actor for actor in scene.actors if actor.name == name), None)


def _relative_start(
    actor: scm.Actor, starts: dict[EObject, WorldPose], scene: MapScene, what: str
) -> Place | None:
    """A start relative to another actor, where that actor's start puts it."""
    pose = starts.get(actor)
    if pose is None:
        other = getattr(actor.startPosition.entity, "name", None)
        scene.notes.append(f"{what} is not drawn: it is relative to {other!r}, not placed")
        return None
    point = Located(pose.x, pose.y, pose.heading)
    return Place(point, (point,))


def _place(position: EObject | None, scene: MapScene, what: str) -> Place | None:
    """The place of a position on the map; None (with a note) when it does not fit the map."""
    if position is None:
        return None
    if is_relative(position):
        # A destination or condition relative to an actor moves with it: the run tells where.
        scene.notes.append(f"{what} is not drawn: it is relative to where an actor is then")
        return None
    try:
        points = tuple(locate(position, scene.road_map))
    except PositionError as error:
        scene.notes.append(f"{what} is not drawn: {error}")
        return None
    middle = centre(position, scene.road_map)
    if not points or middle is None:
        scene.notes.append(f"{what} is not drawn: it has no values")
        return None
    if is_concrete(position) or len(points) == 1:
        return Place(middle, points)
    return Place(middle, points, tuple(_region(position, points, scene.road_map)))


def _region(position: EObject, points: Sequence[Located], road_map: RoadMap) -> list[Point]:
    """What a logical position spans: a stretch of its lane, or the hull of its world points."""
    if isinstance(position, scm.LanePosition) and isinstance(
        position.s, scm.Range | scm.Distribution
    ):
        stretch = _lane_stretch(position, points, road_map)
        if stretch:
            return stretch
    return convex_hull([(p.x, p.y) for p in points])


def _lane_stretch(
    position: scm.LanePosition, points: Sequence[Located], road_map: RoadMap
) -> list[Point]:
    """The lane between the smallest and largest s, across the lane (or across the offsets
    the position allows, when its offset is a range too)."""
    lanes = [p.lane for p in points if p.lane is not None]
    if not lanes:
        return []
    road_id, lane_id = lanes[0][0], lanes[0][1]
    s_low, s_high = min(lane[2] for lane in lanes), max(lane[2] for lane in lanes)
    offsets = sorted({lane[3] for lane in lanes})
    edges: tuple[list[Point], list[Point]] = ([], [])
    try:
        for s in np.linspace(s_low, s_high, _REGION_STEPS):
            if len(offsets) > 1:
                sides = (offsets[0], offsets[-1])
            else:
                half = road_map.band(road_id, lane_id, float(s)).width / 2
                sides = (offsets[0] - half, offsets[0] + half)
            for edge, offset in zip(edges, sides, strict=True):
                pose = road_map.lane_to_world(road_id, lane_id, float(s), offset)
                edge.append((pose.x, pose.y))
    except PositionError:
        return []
    return edges[0] + edges[1][::-1]


def convex_hull(points: Iterable[Point]) -> list[Point]:
    """The convex hull (scipy's Qhull), counter-clockwise from the lowest point in x then y;
    points that span no area (fewer than three, or all on a line) give their two ends."""
    from scipy.spatial import ConvexHull, QhullError  # only a logical map view needs it

    unique = sorted(set(points))
    if len(unique) < 3:
        return unique
    try:
        order = ConvexHull(np.array(unique)).vertices
    except QhullError:  # collinear: the segment between the extreme points
        return [unique[0], unique[-1]]
    hull = [unique[i] for i in order]
    first = hull.index(min(hull))
    return hull[first:] + hull[:first]


def junction_boxes(road_map: RoadMap) -> list[Box]:
    """One box per junction around its connecting roads' lanes."""
    outlines: dict[str, list[np.ndarray]] = {}
    for road in road_map.roads.values():
        if road.junction in ("-1", ""):
            continue
        for section in road.sections:
            by_lane = road_map.section_outlines(road, section)
            for lane in section.lanes():
                outlines.setdefault(road.junction, []).append(by_lane[lane.id])
    boxes = []
    for arrays in outlines.values():
        stacked = np.vstack(arrays)
        low, high = stacked.min(axis=0), stacked.max(axis=0)
        boxes.append((float(low[0]), float(low[1]), float(high[0]), float(high[1])))
    return boxes


def _points_box(points: Iterable[Point]) -> Box | None:
    listed = list(points)
    if not listed:
        return None
    xs, ys = [p[0] for p in listed], [p[1] for p in listed]
    return (min(xs), min(ys), max(xs), max(ys))


def _grow(box: Box, margin: float) -> Box:
    return (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)


def _union(boxes: Sequence[Box]) -> Box:
    return (
        min(b[0] for b in boxes),
        min(b[1] for b in boxes),
        max(b[2] for b in boxes),
        max(b[3] for b in boxes),
    )


def actor_colours(scene: MapScene) -> dict[str, str]:
    """One colour per actor, the same everywhere in the picture: the ego blue, others in turn."""
    colours, others = {}, iter(_cycle(style.MAP_ACTOR_COLOURS))
    for actor in scene.actors:
        colours[actor.name] = style.MAP_EGO_COLOUR if actor.ego else next(others)
    return colours


def _cycle(values: tuple[str, ...]) -> Iterator[str]:
    while True:
        yield from values


def thin(points: np.ndarray, tolerance: float = 0.02) -> np.ndarray:
    """The points of a line less those within `tolerance` m of the chord between their
    neighbours: a straight arm needs its two ends, not a point every few decimetres."""
    if len(points) < 3:
        return points
    # Python floats: the same arithmetic as on the array's rows, without a numpy scalar per step.
    rows = points.tolist()
    kept = [rows[0]]
    for point, following in zip(rows[1:-1], rows[2:], strict=True):
        last = kept[-1]
        chord = (following[0] - last[0], following[1] - last[1])
        length = float(np.hypot(*chord))
        offset = (point[0] - last[0], point[1] - last[1])
        distance = abs(chord[0] * offset[1] - chord[1] * offset[0]) / length if length else 0.0
        if distance > tolerance:
            kept.append(point)
    kept.append(rows[-1])
    return np.array(kept)

"""What SceML reads of an OpenDRIVE file: roads, lanes, links and junctions, as plain values.

Only what positions, routes and the map view need is kept; elevation, superelevation, objects and
signals are not read (positions are checked in the plane). Each element keeps the line it came
from, so a finding about the map can point into the .xodr file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

#: Lane types a car, van, truck, bus or motorcycle may be placed on or routed over.
VEHICLE_LANE_TYPES = frozenset(
    {
        "driving",
        "entry",
        "exit",
        "onRamp",
        "offRamp",
        "connectingRamp",
        "bidirectional",
        "bus",
        "taxi",
        "HOV",
        "mwyEntry",
        "mwyExit",
        "onramp",
        "offramp",
        "connectingramp",
    }
)
#: Lane types at the edge of the roadway where a vehicle may stand or pull over (a breakdown on
#: the shoulder, a parked car, a motorcycle on a hard shoulder) but does not normally drive.
VEHICLE_EDGE_LANE_TYPES = frozenset({"shoulder", "stop", "parking", "restricted"})
#: Lane types a bicycle may use: the roadway and the lanes beside it meant for people.
BICYCLE_LANE_TYPES = VEHICLE_LANE_TYPES | {"biking", "sidewalk", "walking", "shoulder"}
#: Lane types a pedestrian may use: sidewalks, and the roadway (pedestrians cross it).
PEDESTRIAN_LANE_TYPES = BICYCLE_LANE_TYPES | {"border", "curb", "median"}


@dataclass(frozen=True)
class Poly3:
    """`a + b*ds + c*ds^2 + d*ds^3` from `s_offset` on (a lane width or the lane offset)."""

    s_offset: float
    a: float
    b: float
    c: float
    d: float

    def at(self, ds: float) -> float:
        """The value `ds` metres after the record's own start."""
        return self.a + ds * (self.b + ds * (self.c + ds * self.d))


def piecewise(records: tuple[Poly3, ...], ds: float) -> float:
    """A piecewise cubic (widths, lane offset): the last record starting at or before `ds`."""
    current = None
    for record in records:
        if record.s_offset <= ds + 1e-9:
            current = record
        else:
            break
    if current is None:
        return 0.0 if not records else records[0].at(ds - records[0].s_offset)
    return current.at(ds - current.s_offset)


@dataclass(frozen=True)
class Geometry:
    """One piece of a road's plan view.

    `kind` is line, arc, spiral, poly3 or paramPoly3; `params` holds that element's attributes
    as numbers (curvature; curvStart/curvEnd; a..d; aU..dV with pRange), by their XML names.
    """

    s: float
    x: float
    y: float
    hdg: float
    length: float
    kind: str
    params: dict[str, float | str] = field(default_factory=dict)
    line: int | None = None


@dataclass(frozen=True)
class Lane:
    """One lane of a lane section: id (positive left of the reference line), type and width."""

    id: int
    type: str
    widths: tuple[Poly3, ...]
    predecessor: int | None = None
    successor: int | None = None
    line: int | None = None

    def width(self, ds: float) -> float:
        """Width `ds` metres after the start of the lane section."""
        return piecewise(self.widths, ds)


@dataclass(frozen=True)
class LaneSection:
    """Lanes from `s` to the next section; left lanes ordered 1, 2, ... and right -1, -2, ..."""

    s: float
    left: tuple[Lane, ...]
    right: tuple[Lane, ...]
    line: int | None = None

    def lanes(self) -> tuple[Lane, ...]:
        """Every lane but the centre lane, left then right."""
        return self.left + self.right

    def lane(self, lane_id: int) -> Lane | None:
        """The lane with this id, or None (0, the centre lane, has no width and is not a lane)."""
        side = self.left if lane_id > 0 else self.right
        index = abs(lane_id) - 1
        if lane_id == 0 or index >= len(side) or side[index].id != lane_id:
            return next((lane for lane in side if lane.id == lane_id), None)
        return side[index]


@dataclass(frozen=True)
class RoadLink:
    """A road's predecessor or successor: a road (with the end it meets) or a junction."""

    element_type: str  # "road" or "junction"
    element_id: str
    contact_point: str | None = None  # "start" or "end", for roads


@dataclass(frozen=True)
class Road:
    """A road: plan view, lane sections, links; `junction` is "-1" outside junctions."""

    id: str
    name: str
    length: float
    junction: str
    rule: str  # "RHT" or "LHT"
    geometries: tuple[Geometry, ...]
    lane_offset: tuple[Poly3, ...]
    sections: tuple[LaneSection, ...]
    predecessor: RoadLink | None = None
    successor: RoadLink | None = None
    line: int | None = None

    def section_at(self, s: float) -> LaneSection:
        """The lane section in force at `s`."""
        current = self.sections[0]
        for section in self.sections:
            if section.s <= s + 1e-9:
                current = section
        return current


@dataclass(frozen=True)
class LaneLink:
    """In a junction connection: lane `source` of the incoming road continues in lane `target`."""

    source: int
    target: int


@dataclass(frozen=True)
class Connection:
    """Traffic from `incoming_road` enters `connecting_road` at its `contact_point` end."""

    id: str
    incoming_road: str
    connecting_road: str
    contact_point: str
    lane_links: tuple[LaneLink, ...]
    line: int | None = None


@dataclass(frozen=True)
class Junction:
    """A junction and its connections."""

    id: str
    name: str
    connections: tuple[Connection, ...]
    line: int | None = None


# --- values of the coordinate conversions (sceml.maps.roadmap) ------------------------------


class PositionError(ValueError):
    """A lane coordinate that names no lane of the map; the message says which part is wrong."""


@dataclass(frozen=True)
class WorldPose:
    """A point of the plane and a heading (rad)."""

    x: float
    y: float
    heading: float


@dataclass(frozen=True)
class LaneCoordinate:
    """Where a world point lies on the map: road, lane, s, offset from the lane centre.

    `outside` is how far the point lies outside the lane's edges (0 inside it).
    """

    road_id: str
    lane_id: int
    s: float
    offset: float
    lane_type: str
    outside: float = 0.0


@dataclass(frozen=True)
class LaneBand:
    """A lane at one s: its inner and outer edge (t) and its type."""

    lane: Lane
    inner: float
    outer: float

    @property
    def centre(self) -> float:
        return (self.inner + self.outer) / 2

    @property
    def width(self) -> float:
        return abs(self.outer - self.inner)


def wrap_angle(angle: float) -> float:
    """`angle` in (-pi, pi]."""
    wrapped = math.remainder(angle, 2 * math.pi)
    return math.pi if wrapped == -math.pi else wrapped

"""The road network of one OpenDRIVE file: lanes in lane coordinates and in the world.

Conventions (those of OpenDRIVE and OpenSCENARIO): s runs along a road's reference line from 0 to
its length; t is the lateral distance from the reference line, positive to the left; a lane
position's offset is measured from the lane's centre line in the same direction as t. Positive
lane ids lie left of the reference line. Headings are in rad, counter-clockwise from the world x
axis. A lane's traffic runs along s for negative ids on a right-hand-traffic road (`rule="RHT"`,
the default) and against s for positive ids; the other way round on left-hand-traffic roads.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

from ..files.safefiles import check_inside
from .model import (
    Junction,
    LaneBand,
    LaneCoordinate,
    LaneSection,
    PositionError,
    Road,
    WorldPose,
    piecewise,
    wrap_angle,
)
from .planview import SAMPLE_STEP, ReferenceLine
from .reader import MapError, parse_opendrive
from .roadindex import RoadIndex

if TYPE_CHECKING:
    import numpy as np

#: Slack of the road index (m) beyond a road's reach and twice the tolerance: half the sample
#: step between the sampled polyline and the curve, and lanes that widen between two samples.
_INDEX_MARGIN = 1.0
#: How many points a map is asked about before the index is built.
_UNINDEXED = 64
#: How many answers of `world_to_lane` (and of `lane_to_world`) a map keeps (the oldest goes first).
_ANSWERS_KEPT = 65536


class RoadMap:
    """Roads and junctions of an OpenDRIVE file, with coordinate conversions.

    Build it with `load_map`; reference lines are evaluated when first needed.
    """

    def __init__(
        self, path: Path, version: str, roads: list[Road], junctions: list[Junction]
    ) -> None:
        self.path = path
        self.version = version
        self.roads = {road.id: road for road in roads}
        self.junctions = {junction.id: junction for junction in junctions}
        self._lines: dict[str, ReferenceLine] = {}
        self._answers: dict[tuple[float, float, float], tuple[LaneCoordinate, ...]] = {}
        self._poses: dict[tuple[str, int, float, float], WorldPose] = {}
        self._bands: dict[tuple[str, int, float], LaneBand] = {}

    # --- lanes -------------------------------------------------------------------------------

    def road(self, road_id: str) -> Road:
        """The road with this id, or PositionError."""
        road = self.roads.get(str(road_id))
        if road is None:
            ids = sorted(self.roads, key=_id_order)
            known = ", ".join(ids[:12]) + (f" and {len(ids) - 12} more" if len(ids) > 12 else "")
            raise PositionError(f"the map has no road {road_id!r} (roads: {known})")
        return road

    def reference_line(self, road_id: str) -> ReferenceLine:
        """The reference line of a road (evaluated once)."""
        line = self._lines.get(road_id)
        if line is None:
            road = self.road(road_id)
            line = self._lines[road_id] = ReferenceLine(road.geometries, road.length)
        return line

    def bands(self, road: Road, s: float, section: LaneSection | None = None) -> list[LaneBand]:
        """Every lane of the section in force at `s` (or of `section`, which drawing a section
        up to its end needs: at the end the next section is in force), with its edges at `s`."""
        if section is None:
            section = road.section_at(s)
        ds = s - section.s
        base = piecewise(road.lane_offset, s) if road.lane_offset else 0.0
        bands = []
        for side, sign in ((section.left, 1.0), (section.right, -1.0)):
            edge = base
            for lane in side:
                width = max(lane.width(ds), 0.0)
                bands.append(LaneBand(lane, edge, edge + sign * width))
                edge += sign * width
        return bands

    def band(self, road_id: str, lane_id: int, s: float) -> LaneBand:
        """The lane `lane_id` of road `road_id` at `s`, or PositionError naming what is wrong."""
        # Kept like `lane_to_world`'s answers: the map rules ask for the type of the lane each
        # start position and destination lies on, once per rule and node naming it.
        key = (road_id, lane_id, s)
        known = self._bands.get(key)
        if known is None:
            known = self._bands[key] = self._band(road_id, lane_id, s)
            if len(self._bands) > _ANSWERS_KEPT:
                self._bands.pop(next(iter(self._bands)), None)
        return known

    def _band(self, road_id: str, lane_id: int, s: float) -> LaneBand:
        road = self.road(road_id)
        if not -1e-6 <= s <= road.length + 1e-6:
            raise PositionError(
                f"s={s:g} m is outside road {road.id!r}, which is {road.length:g} m long"
            )
        for band in self.bands(road, s):
            if band.lane.id == lane_id:
                return band
        lanes = ", ".join(str(b.lane.id) for b in self.bands(road, s))
        raise PositionError(f"road {road.id!r} has no lane {lane_id} at s={s:g} (lanes: {lanes})")

    def lane_problem(self, road_id: str, lane_id: int, s: float, offset: float) -> str | None:
        """What is wrong with a lane position (unknown road or lane, s off the road, offset
        outside the lane), in words; None when it lies on the lane."""
        try:
            band = self.band(road_id, lane_id, s)
        except PositionError as error:
            return str(error)
        if abs(offset) > band.width / 2 + 1e-6:
            return (
                f"offset {offset:g} m leaves lane {lane_id} of road {road_id}, "
                f"which is {band.width:g} m wide at s={s:g}"
            )
        return None

    def drives_along_s(self, road: Road, lane_id: int) -> bool:
        """Whether traffic on the lane runs in the direction of increasing s."""
        right_hand = road.rule.upper() != "LHT"
        return (lane_id < 0) == right_hand

    # --- conversions -------------------------------------------------------------------------

    def lane_to_world(self, road_id: str, lane_id: int, s: float, offset: float = 0.0) -> WorldPose:
        """World point of a lane position, heading in the lane's direction of traffic."""
        # Kept like `world_to_lane`'s answers: the map rules ask where the same few lane
        # positions lie (start positions, a Cross's destination) once per node naming them.
        key = (str(road_id), lane_id, s, offset)
        known = self._poses.get(key)
        if known is None:
            known = self._poses[key] = self._lane_to_world(road_id, lane_id, s, offset)
            if len(self._poses) > _ANSWERS_KEPT:
                self._poses.pop(next(iter(self._poses)), None)
        return known

    def _lane_to_world(self, road_id: str, lane_id: int, s: float, offset: float) -> WorldPose:
        road = self.road(road_id)
        band = self.band(road.id, lane_id, s)
        x, y, h = self.reference_line(road.id).pose(s)
        t = band.centre + offset
        heading = h if self.drives_along_s(road, lane_id) else h + math.pi
        return WorldPose(x - t * math.sin(h), y + t * math.cos(h), wrap_angle(heading))

    def world_to_lane(self, x: float, y: float, tolerance: float = 0.0) -> list[LaneCoordinate]:
        """Every lane within `tolerance` m of (x, y), nearest lane centre first.

        Inside a junction several connecting roads overlap, so a point may lie on several lanes.
        """
        # Rules ask about the same points again and again (a Cross's path, a start position
        # named by many nodes): the answers are kept, a fresh list each time.
        key = (x, y, tolerance)
        known = self._answers.get(key)
        if known is None:
            known = self._answers[key] = tuple(self._lanes_at(x, y, tolerance))
            if len(self._answers) > _ANSWERS_KEPT:
                self._answers.pop(next(iter(self._answers)), None)
        return list(known)

    def _lanes_at(self, x: float, y: float, tolerance: float) -> list[LaneCoordinate]:
        found = []
        # A few questions are answered sooner by trying every road than by building the index
        # (UIS1's validation asks a few dozen).
        roads = (
            self._near(x, y, tolerance) if len(self._answers) > _UNINDEXED else self.roads.values()
        )
        for road in roads:
            box = self._boxes.get(road.id)
            if box is None or not (
                box[0] - tolerance <= x <= box[2] + tolerance
                and box[1] - tolerance <= y <= box[3] + tolerance
            ):
                continue
            where = self.reference_line(road.id).project(x, y)
            if where.beyond > tolerance + 1e-6:
                continue
            for band in self.bands(road, where.s):
                low, high = sorted((band.inner, band.outer))
                outside = max(low - where.t, where.t - high, 0.0)
                if band.width > 0 and outside <= tolerance:
                    found.append(
                        LaneCoordinate(
                            road.id,
                            band.lane.id,
                            where.s,
                            where.t - band.centre,
                            band.lane.type,
                            max(outside, where.beyond),
                        )
                    )
        return sorted(found, key=lambda c: (c.outside, abs(c.offset)))

    def _near(self, x: float, y: float, tolerance: float) -> list[Road]:
        """The roads that may have a lane within `tolerance` m of (x, y), in the map's order.

        A road qualifies when its reference line may pass within its lanes' reach plus the
        tolerance (twice: across and beyond either end) of the point; the index below finds
        those lines without projecting onto each road. The margin covers the half sample step
        between the polyline and the curve and lanes that widen between two samples.
        """
        if not (math.isfinite(x) and math.isfinite(y)):
            return []  # no road's box holds such a point
        roads, index = self._index
        return [roads[i] for i in index.near(x, y, 2 * tolerance + _INDEX_MARGIN)]

    @cached_property
    def _index(self) -> tuple[list[Road], RoadIndex]:
        """The roads, and a grid of the cells their reference lines (and lanes) reach."""
        roads = list(self.roads.values())
        lines = [self.reference_line(road.id).xy for road in roads]
        return roads, RoadIndex(lines, [self._farthest_edge(road) for road in roads])

    def _farthest_edge(self, road: Road) -> float:
        """How far the road's farthest lane edge lies from its reference line, at the sampled
        s, either side: a lane position's |t| never exceeds it (plus the margin)."""
        return max(
            (
                max((max(abs(b.inner), abs(b.outer)) for b in self.bands(road, s)), default=0.0)
                for s in self.reference_line(road.id).s
            ),
            default=0.0,
        )

    def traffic_heading(self, road_id: str, lane_id: int, s: float) -> float:
        """The direction of traffic on a lane at `s`."""
        return self.lane_to_world(road_id, lane_id, s).heading

    # --- drawing -----------------------------------------------------------------------------

    def lane_outline(self, road: Road, section: LaneSection, lane_id: int) -> np.ndarray:
        """The lane's outline as a closed polygon (N x 2), inner edge out and outer edge back."""
        return self.section_outlines(road, section, (lane_id,))[lane_id]

    def section_outlines(
        self, road: Road, section: LaneSection, lane_ids: Iterable[int] | None = None
    ) -> dict[int, np.ndarray]:
        """The outline of each lane of a section (`lane_outline`'s polygon), by lane id.

        A whole road drawn lane by lane evaluated the reference line and every lane's width
        once per lane at each sample; here each sample is evaluated once for all the lanes.
        """
        import numpy as np  # the drawings' arrays; reading a map and its positions need none

        wanted = [lane.id for lane in section.lanes()] if lane_ids is None else list(lane_ids)
        end = _section_end(road, section)
        count = max(2, math.ceil((end - section.s) / SAMPLE_STEP) + 1)
        line = self.reference_line(road.id)
        edges: dict[int, tuple[list[tuple[float, float]], list[tuple[float, float]]]] = {}
        for s in np.linspace(section.s, end, count):
            x, y, h = line.pose(float(s))
            normal = (-math.sin(h), math.cos(h))
            found: dict[int, LaneBand] = {}
            for b in self.bands(road, float(s), section):
                found.setdefault(b.lane.id, b)  # the first band of an id, as a search finds it
            for lane_id in wanted:
                band = found[lane_id]
                inner, outer = edges.setdefault(lane_id, ([], []))
                inner.append((x + band.inner * normal[0], y + band.inner * normal[1]))
                outer.append((x + band.outer * normal[0], y + band.outer * normal[1]))
        return {lane_id: np.array(inner + outer[::-1]) for lane_id, (inner, outer) in edges.items()}

    def lane_centre_line(self, road: Road, section: LaneSection, lane_id: int) -> np.ndarray:
        """The lane's centre line (N x 2) in the direction of increasing s."""
        import numpy as np

        end = _section_end(road, section)
        count = max(2, math.ceil((end - section.s) / SAMPLE_STEP) + 1)
        points = []
        for s in np.linspace(section.s, end, count):
            x, y, h = self.reference_line(road.id).pose(float(s))
            band = next(b for b in self.bands(road, float(s), section) if b.lane.id == lane_id)
            points.append((x - band.centre * math.sin(h), y + band.centre * math.cos(h)))
        return np.array(points)

    @cached_property
    def _reach(self) -> dict[str, float]:
        """How far each road's lanes reach from its reference line: its widest lane section
        and its lane offset, at the sampled s."""
        # The offset counts by its size wherever it is largest: a negative one moves the right
        # lanes further out, and it may grow along the road. Every sample's lane edges are worked
        # out as `bands` works them out, float for float, without making a LaneBand of each: this
        # runs at every sample of every road (1,300 for UIS1's map, about 2 of the 3 ms it took
        # with `bands`, in every command that asks where a point lies). A test holds the two to
        # the same floats on every map of the repository.
        reaches = {}
        for road in self.roads.values():
            per_sample = []
            for s in self.reference_line(road.id).s:
                section = road.section_at(s)
                ds = s - section.s
                offset = piecewise(road.lane_offset, s) if road.lane_offset else 0.0
                widths = []
                for side, sign in ((section.left, 1.0), (section.right, -1.0)):
                    edge = offset
                    for lane in side:
                        outer = edge + sign * max(lane.width(ds), 0.0)
                        widths.append(abs(outer - edge))
                        edge = outer
                per_sample.append(sum(widths) + abs(offset))
            reaches[road.id] = max(per_sample, default=0.0)
        return reaches

    @cached_property
    def _boxes(self) -> dict[str, tuple[float, float, float, float]]:
        """Each road's bounding box, grown by its widest lane section and its lane offset."""
        boxes = {}
        for road in self.roads.values():
            line = self.reference_line(road.id)
            reach = self._reach[road.id]
            xs = [x for x, _ in line.xy]
            ys = [y for _, y in line.xy]
            boxes[road.id] = (min(xs) - reach, min(ys) - reach, max(xs) + reach, max(ys) + reach)
        return boxes

    def bounds(self) -> tuple[float, float, float, float]:
        """The box around every road: xmin, ymin, xmax, ymax."""
        boxes = list(self._boxes.values()) or [(0.0, 0.0, 0.0, 0.0)]
        return (
            min(b[0] for b in boxes),
            min(b[1] for b in boxes),
            max(b[2] for b in boxes),
            max(b[3] for b in boxes),
        )


def _section_end(road: Road, section: LaneSection) -> float:
    later = [other.s for other in road.sections if other.s > section.s]
    return min(later) if later else road.length


def _id_order(road_id: str) -> tuple[int, str]:
    return (int(road_id), "") if road_id.lstrip("-").isdigit() else (1 << 62, road_id)


_cache: dict[tuple[str, int, int], RoadMap] = {}


def load_map(
    path: str | os.PathLike[str], roots: Iterable[str | os.PathLike[str]] | None = None
) -> RoadMap:
    """The map in an OpenDRIVE file; read once per process while the file is unchanged.

    When `roots` are given, a file outside them is refused (MapError), cached or not.
    """
    if roots is not None:
        check_inside(path, roots, what="map", error=MapError)
    resolved = Path(path).resolve()
    try:
        stat = resolved.stat()
        key: tuple[str, int, int] | None = (str(resolved), stat.st_mtime_ns, stat.st_size)
    except OSError:
        key = None  # the reader says what is wrong with the path
    if key is not None and key in _cache:
        return _cache[key]
    version, roads, junctions = parse_opendrive(path, roots)
    road_map = RoadMap(resolved, version, roads, junctions)
    if key is not None:
        if len(_cache) >= 8:
            _cache.pop(next(iter(_cache)))
        _cache[key] = road_map
    return road_map

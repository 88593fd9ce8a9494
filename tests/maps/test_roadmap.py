"""Tests of `sceml.maps`: lane <-> world conversions, the reader's refusals, routes and positions.

Three sources of truth: our map (`maps/intersection.xodr`, docs/map.md), the independent
evaluator of `test_intersection_map.py` (numerical integration, no pyclothoids), and maps that
scenariogeneration builds here, whose geometry starts it computes itself.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from numpy.polynomial import Polynomial

import scemlmodel as scm
from maps import sg_networks as sg
from maps import test_intersection_map as evaluator
from sceml.maps import MapError, PositionError, RoadMap, load_map, wrap_angle
from sceml.maps.positions import centre, is_concrete, locate, nominal, spread
from sceml.maps.reader import parse_opendrive
from sceml.maps.routes import routes_from, way_to
from sceml.model.build import lane, world
from sceml.model.params import discrete, normal, span, uniform, value

CM = 0.01  # m: the agreement every conversion must reach
IMPORT_FILES = Path(__file__).resolve().parents[1] / "importer" / "files"


@pytest.fixture(scope="module")
def our_map() -> RoadMap:
    return load_map(evaluator.XODR)


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> dict[str, RoadMap]:
    folder = tmp_path_factory.mktemp("scenariogeneration")
    return {
        "curvy": load_map(sg.curvy_network(folder)),
        "tee": load_map(sg.tee_network(folder)),
        "two tees": load_map(sg.two_tees_network(folder)),
    }


# --- helpers -----------------------------------------------------------------------------------


def _section_samples(road_map: RoadMap, road_id: str, count: int) -> list[tuple[int, float]]:
    """(section index, s) from the start to the end of every lane section.

    A section ends where the next one starts, and there the next one is in force; its last
    sample is taken a micrometre before.
    """
    road = road_map.roads[road_id]
    samples = []
    for index, section in enumerate(road.sections):
        last = index == len(road.sections) - 1
        end = road.length if last else road.sections[index + 1].s - 1e-6
        samples += [(index, float(s)) for s in np.linspace(section.s, end, count)]
    return samples


def _round_trip_worst(road_map: RoadMap, count: int = 7) -> tuple[float, int]:
    """lane -> world -> lane on every lane at `count` s per section and three offsets.

    Returns the worst error (m) and the number of positions tried; asserts each comes back.
    """
    worst, tried = 0.0, 0
    for road_id, road in road_map.roads.items():
        for index, s in _section_samples(road_map, road_id, count):
            for lane_ in road.sections[index].lanes():
                band = road_map.band(road_id, lane_.id, s)
                if band.width < CM:
                    continue  # a lane that opens or closes here has no inside to come back to
                for offset in (-0.4 * band.width, 0.0, 0.4 * band.width):
                    pose = road_map.lane_to_world(road_id, lane_.id, s, offset)
                    found = [
                        c
                        for c in road_map.world_to_lane(pose.x, pose.y)
                        if (c.road_id, c.lane_id) == (road_id, lane_.id)
                    ]
                    where = (road_id, lane_.id, s, offset)
                    assert found, f"{where} -> {pose} is not found on its lane"
                    error = min(max(abs(c.s - s), abs(c.offset - offset)) for c in found)
                    assert error < CM, where
                    worst, tried = max(worst, error), tried + 1
    return worst, tried


def _world_round_trip(road_map: RoadMap, xs: np.ndarray, ys: np.ndarray) -> int:
    """world -> lane -> world for the grid points that lie on a lane; returns how many did."""
    on_lanes = 0
    for x in xs:
        for y in ys:
            found = road_map.world_to_lane(float(x), float(y))
            on_lanes += bool(found)
            for c in found:
                assert c.outside < 1e-6
                pose = road_map.lane_to_world(c.road_id, c.lane_id, c.s, c.offset)
                assert math.dist((pose.x, pose.y), (x, y)) < CM, (x, y, c)
    return on_lanes


# --- (1) our map: round trips ------------------------------------------------------------------


def test_lane_world_lane_round_trip_on_every_lane_of_our_map(our_map: RoadMap) -> None:
    worst, tried = _round_trip_worst(our_map)
    assert tried == 20 * 7 * 3 + 4 * 3 * 7 * 3  # 20 roads with lane -1, the 4 arms 3 more
    assert worst < 1e-6  # far inside the 1 cm asked for: projection converges, not just nears


def test_world_lane_world_round_trip_on_a_grid_over_our_map(our_map: RoadMap) -> None:
    centre_grid = np.arange(-14.0, 14.01, 0.7)  # the junction, where connecting roads overlap
    assert _world_round_trip(our_map, centre_grid, centre_grid) > 300
    along = np.arange(-118.0, 118.1, 4.3)
    across = np.arange(-6.0, 6.01, 1.1)
    assert _world_round_trip(our_map, along, across) > 50  # the east and west arms
    assert _world_round_trip(our_map, across, along) > 50  # the north and south arms


def test_world_to_lane_finds_nothing_off_the_roads(our_map: RoadMap) -> None:
    assert our_map.world_to_lane(30.0, 30.0) == []  # between two arms
    assert our_map.world_to_lane(0.0, 130.0) == []  # past the north arm's end
    near = our_map.world_to_lane(0.0, 130.0, tolerance=25.0)
    assert {(c.road_id, c.lane_id) for c in near} >= {("1", 1), ("1", -1)}
    assert all(c.outside > 19.0 for c in near)


def test_lane_to_world_refuses_what_the_map_lacks(our_map: RoadMap) -> None:
    with pytest.raises(PositionError, match="no road '99'"):
        our_map.lane_to_world("99", 1, 10.0)
    with pytest.raises(PositionError, match="no lane 3"):
        our_map.lane_to_world("3", 3, 10.0)
    with pytest.raises(PositionError, match="outside road '3'"):
        our_map.lane_to_world("3", 1, 100.5)


def test_lane_headings_follow_right_hand_traffic(our_map: RoadMap) -> None:
    south_inbound = our_map.lane_to_world("3", 1, 30.0)  # UIS1's ego start, docs/map.md
    assert (south_inbound.x, south_inbound.y) == pytest.approx((1.75, -39.0), abs=1e-9)
    assert wrap_angle(south_inbound.heading - math.pi / 2) == pytest.approx(0.0, abs=1e-9)
    south_outbound = our_map.lane_to_world("3", -1, 30.0)
    assert (south_outbound.x, south_outbound.y) == pytest.approx((-1.75, -39.0), abs=1e-9)
    assert wrap_angle(south_outbound.heading + math.pi / 2) == pytest.approx(0.0, abs=1e-9)


# --- (2) against the independent evaluator of test_intersection_map.py -------------------------


def test_agrees_with_the_independent_evaluator_on_every_road(our_map: RoadMap) -> None:
    worst = 0.0
    checked_spirals = 0
    for road_id, reference in evaluator.roads().items():
        road = our_map.roads[road_id]
        checked_spirals += any(g.kind == "spiral" for g in road.geometries)
        for s in np.linspace(0.0, reference.length, 31):
            s = float(s)
            x, y, h = our_map.reference_line(road_id).pose(s)
            ex, ey, eh = reference.reference(s)
            assert abs(wrap_angle(h - eh)) < 1e-4, (road_id, s)
            worst = max(worst, math.dist((x, y), (ex, ey)))
            for lane_id in (i for i in reference.lanes if i != 0):
                band = our_map.band(road_id, lane_id, s)
                inner, outer = reference.lane_bounds(lane_id, s)
                sign = math.copysign(1.0, lane_id)
                assert (band.inner, band.outer) == pytest.approx((sign * inner, sign * outer))
                pose = our_map.lane_to_world(road_id, lane_id, s)
                ex, ey, _ = reference.lane_centre(lane_id, s)
                worst = max(worst, math.dist((pose.x, pose.y), (ex, ey)))
                if 0.0 < s < reference.length:  # back from the evaluator's world point
                    back = [
                        c
                        for c in our_map.world_to_lane(ex, ey)
                        if (c.road_id, c.lane_id) == (road_id, lane_id)
                    ]
                    assert back, (road_id, lane_id, s)
                    assert abs(back[0].s - s) < CM and abs(back[0].offset) < CM
    assert checked_spirals == 16
    assert worst < CM


# --- (3) maps that scenariogeneration builds ---------------------------------------------------


def test_the_built_maps_have_every_geometry_kind(built: dict[str, RoadMap]) -> None:
    mixed = built["curvy"].roads[sg.MIXED]
    kinds = [(g.kind, g.params.get("pRange")) for g in mixed.geometries]
    assert kinds == [
        ("line", None),
        ("arc", None),
        ("spiral", None),
        ("paramPoly3", "normalized"),
        ("paramPoly3", "arcLength"),
        ("line", None),
    ]
    assert len(built["tee"].junctions[sg.TEE].connections) == 6


@pytest.mark.parametrize("network", ["curvy", "tee"])
def test_each_geometry_ends_where_scenariogeneration_starts_the_next(
    built: dict[str, RoadMap], network: str
) -> None:
    road_map = built[network]
    pairs = 0
    for road_id, road in road_map.roads.items():
        line = road_map.reference_line(road_id)
        for before, after in zip(road.geometries, road.geometries[1:], strict=False):
            assert before.s + before.length == pytest.approx(after.s)
            x, y, h = line.pose(after.s - 1e-9)  # the end of `before`, evaluated by sceml
            assert math.dist((x, y), (after.x, after.y)) < CM, (road_id, before.kind)
            assert abs(wrap_angle(h - after.hdg)) < 1e-3, (road_id, before.kind)
            pairs += 1
    assert pairs == {"curvy": 5, "tee": 6}[network]


def test_param_poly3_points_lie_on_the_reference_line_at_their_arc_length(
    built: dict[str, RoadMap],
) -> None:
    """Points of the polynomials, evaluated here directly, against sceml's arc-length table."""
    road_map = built["curvy"]
    line = road_map.reference_line(sg.MIXED)
    cubics = [g for g in road_map.roads[sg.MIXED].geometries if g.kind == "paramPoly3"]
    for piece in cubics:
        u = Polynomial([float(piece.params[f"{c}U"]) for c in "abcd"])
        v = Polynomial([float(piece.params[f"{c}V"]) for c in "abcd"])
        end = piece.length if piece.params["pRange"] == "arcLength" else 1.0
        params = np.linspace(0.0, end, 2001)
        middles = (params[1:] + params[:-1]) / 2  # the midpoint rule for the arc length
        speed = np.hypot(u.deriv()(middles), v.deriv()(middles))
        arcs = np.concatenate(([0.0], np.cumsum(np.diff(params) * speed)))
        for index in range(0, 2001, 250):
            p = params[index]
            x = piece.x + u(p) * math.cos(piece.hdg) - v(p) * math.sin(piece.hdg)
            y = piece.y + u(p) * math.sin(piece.hdg) + v(p) * math.cos(piece.hdg)
            where = line.project(x, y)
            assert abs(where.t) < 1e-3 and where.beyond < 1e-6, (piece.params["pRange"], p)
            assert where.s == pytest.approx(piece.s + arcs[index], abs=CM), (
                piece.params["pRange"],
                p,
            )


def test_lane_edges_are_continuous_across_lane_sections(built: dict[str, RoadMap]) -> None:
    road_map = built["curvy"]
    boundaries = 0
    for road_id in (sg.MIXED, sg.VARYING):
        road = road_map.roads[road_id]
        for before, after in zip(road.sections, road.sections[1:], strict=False):
            s = after.s
            ending = {b.lane.id: b for b in road_map.bands(road, s - 1e-7)}
            starting = {b.lane.id: b for b in road_map.bands(road, s)}
            assert [b.lane for b in ending.values()] == list(before.lanes())
            assert [b.lane for b in starting.values()] == list(after.lanes())
            for lane_id, band in starting.items():
                source = band.lane.predecessor
                if source is None and lane_id in ending and road_id == sg.VARYING:
                    source = lane_id  # no lane links written: the lanes keep their ids
                if source is None:
                    assert band.width < 1e-6, (road_id, s, lane_id)  # a lane opening here
                    continue
                assert ending[source].inner == pytest.approx(band.inner, abs=1e-5)
                assert ending[source].outer == pytest.approx(band.outer, abs=1e-5)
            for lane_id, band in ending.items():
                if band.lane.successor is None and lane_id not in starting:
                    assert band.width < 1e-5, (road_id, s, lane_id)  # a lane closing here
            boundaries += 1
    assert boundaries == 4


def test_widths_and_lane_offset_are_the_written_polynomials(built: dict[str, RoadMap]) -> None:
    road_map = built["curvy"]
    varying = road_map.roads[sg.VARYING]
    widths = sg.varying_widths()
    starts = sg.VARYING_SECTIONS
    for s in np.linspace(0.0, varying.length, 19):
        index = max(i for i, start in enumerate(starts) if start <= s)
        ds = float(s) - starts[index]
        edge = sg.VARYING_LANE_OFFSET[0]
        for lane_id in (-1, -2):
            a, b, c, d = widths[lane_id][index]
            width = a + b * ds + c * ds**2 + d * ds**3
            band = road_map.band(sg.VARYING, lane_id, float(s))
            assert (band.inner, band.outer) == pytest.approx((edge, edge - width), abs=1e-9)
            edge -= width
    a, b, c, d = sg.MIXED_LANE_OFFSET
    for s in (0.0, 40.0, 100.0):
        band = road_map.band(sg.MIXED, -1, s)
        assert band.inner == pytest.approx(a + b * s + c * s**2 + d * s**3, abs=1e-9)


def test_round_trip_on_every_lane_of_the_built_maps(built: dict[str, RoadMap]) -> None:
    for road_map in built.values():
        worst, tried = _round_trip_worst(road_map)
        assert tried > 100
        assert worst < 1e-4
    box = built["curvy"].bounds()
    xs, ys = np.linspace(box[0], box[2], 50), np.linspace(box[1], box[3], 50)
    assert _world_round_trip(built["curvy"], xs, ys) > 50


def test_left_hand_traffic_drives_along_s_on_the_left(built: dict[str, RoadMap]) -> None:
    road_map = built["curvy"]
    road = road_map.roads[sg.LEFT_HAND]
    assert road.rule == "LHT"
    _, _, h = road_map.reference_line(sg.LEFT_HAND).pose(10.0)
    left = road_map.lane_to_world(sg.LEFT_HAND, 1, 10.0)
    right = road_map.lane_to_world(sg.LEFT_HAND, -1, 10.0)
    assert wrap_angle(left.heading - h) == pytest.approx(0.0, abs=1e-9)
    assert wrap_angle(right.heading - h - math.pi) == pytest.approx(0.0, abs=1e-9)


@pytest.mark.parametrize(
    "entry, expected",
    [
        ((sg.WEST, -1), {(sg.EAST, -1, "straight"), (sg.SOUTH, -1, "right")}),
        ((sg.EAST, 1), {(sg.WEST, 1, "straight"), (sg.SOUTH, -1, "left")}),
        ((sg.SOUTH, 1), {(sg.WEST, 1, "left"), (sg.EAST, -1, "right")}),
        ((sg.WEST, 1), set()),  # these lanes lead away from the junction
        ((sg.EAST, -1), set()),
        ((sg.SOUTH, -1), set()),
    ],
)
def test_routes_through_the_built_junction(
    built: dict[str, RoadMap], entry: tuple[str, int], expected: set[tuple[str, int, str]]
) -> None:
    road_map = built["tee"]
    routes = routes_from(road_map, *entry)
    assert {(r.exit_road, r.exit_lane, r.turn) for r in routes} == expected
    for route in routes:
        assert route.junction == sg.TEE
        assert road_map.roads[route.connecting_road].junction == sg.TEE


# --- (4) the reader's refusals ------------------------------------------------------------------

_HEADER = (
    '<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE>\n<header revMajor="1" revMinor="7"/>\n'
)
_PLAN_VIEW = (
    '<planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>\n'
)
_LANES = (
    '<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>'
    '<lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane>'
    "</right></laneSection></lanes>\n"
)


def _road(length: str = "10", plan_view: str = _PLAN_VIEW, road_id: str = "7") -> str:
    return f'<road id="{road_id}" junction="-1" length="{length}">\n{plan_view}{_LANES}</road>\n'


@pytest.mark.parametrize(
    "text, line, message",
    [
        (_HEADER + '<road id="7" length="10">\n</OpenDRIVE>\n', 5, "not well-formed XML"),
        ('<?xml version="1.0"?>\n<OpenSCENARIO/>\n', 2, "root element is <OpenSCENARIO>"),
        (
            '<?xml version="1.0"?>\n<!DOCTYPE OpenDRIVE [<!ENTITY a "b">]>\n<OpenDRIVE/>\n',
            2,
            "declares a DTD",
        ),
        (_HEADER + _road() + _road(plan_view="", road_id="8") + "</OpenDRIVE>\n", 8, "no planView"),
        (
            _HEADER + "\n" + _road(length="abc") + "</OpenDRIVE>\n",
            5,
            "length='abc' is not a number",
        ),
    ],
    ids=["malformed", "not-opendrive", "dtd", "no-planview", "not-a-number"],
)
def test_reader_refuses_with_file_and_line(
    tmp_path: Path, text: str, line: int, message: str
) -> None:
    path = tmp_path / "bad.xodr"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(MapError) as caught:
        load_map(path)
    assert message in caught.value.message
    assert caught.value.file == str(path)
    assert caught.value.line == line
    assert str(caught.value).startswith(f"{path}:{line}: ")


def test_reader_reads_a_good_file_of_the_same_shape(tmp_path: Path) -> None:
    """The refusals above come from the one broken part: the same file without it reads."""
    path = tmp_path / "good.xodr"
    path.write_text(_HEADER + _road() + "</OpenDRIVE>\n", encoding="utf-8")
    version, roads, junctions = parse_opendrive(path)
    assert (version, [r.id for r in roads], junctions) == ("1.7", ["7"], [])
    assert roads[0].line == 4 and roads[0].sections[0].right[0].width(5.0) == 3.0


def test_reader_refuses_a_missing_file_and_a_folder(tmp_path: Path) -> None:
    for path, message in (
        (tmp_path / "nowhere.xodr", "does not exist"),
        (tmp_path, "is a folder"),
    ):
        with pytest.raises(MapError, match=message) as caught:
            load_map(path)
        assert caught.value.file == str(path) and caught.value.line is None


# --- (5) routes on our map ---------------------------------------------------------------------

ARMS = {"north": "1", "east": "2", "south": "3", "west": "4"}
#: From each arm's inbound lane: the arm it leads to, the connecting road, the turn (docs/map.md).
TURNS = {
    "north": {"east": ("100", "left"), "south": ("101", "straight"), "west": ("102", "right")},
    "east": {"north": ("103", "right"), "south": ("104", "left"), "west": ("105", "straight")},
    "south": {"north": ("106", "straight"), "east": ("107", "right"), "west": ("108", "left")},
    "west": {"north": ("109", "left"), "east": ("110", "straight"), "south": ("111", "right")},
}


@pytest.mark.parametrize("arm", list(ARMS))
def test_routes_from_each_arm_of_our_map(our_map: RoadMap, arm: str) -> None:
    routes = routes_from(our_map, ARMS[arm], 1)
    found = {(r.connecting_road, r.exit_road, r.exit_lane, r.turn) for r in routes}
    expected = {(road, ARMS[to], -1, turn) for to, (road, turn) in TURNS[arm].items()}
    assert found == expected
    assert all(r.junction == "10" and r.entry_lane == 1 and not r.roads_before for r in routes)
    assert routes_from(our_map, ARMS[arm], -1) == []  # outbound: it leads to the map's edge


# --- (6) positions of a model on the map -------------------------------------------------------


@pytest.mark.parametrize(
    "parameter, numbers, middle",
    [
        (value(3.5), [3.5], 3.5),
        (span(2, 6), [2.0, 4.0, 6.0], 4.0),
        (uniform(-1, 3), [-1.0, 1.0, 3.0], 1.0),
        (normal(10, 2), [4.0, 10.0, 16.0], 10.0),
        (normal(10, 2, lower=9, upper=11), [9.0, 10.0, 11.0], 10.0),
        (normal(10, 2, lower=9), [9.0, 10.0, 16.0], 10.0),
        (discrete([10, 0, 5]), [10.0, 0.0, 5.0], 5.0),
        (discrete([0, 10]), [0.0, 10.0], 5.0),
    ],
    ids=["value", "range", "uniform", "normal", "normal-bounded", "normal-low", "discrete", "two"],
)
def test_spread_and_nominal(parameter: scm.ParameterValue, numbers: list, middle: float) -> None:
    assert spread(parameter) == pytest.approx(numbers)
    assert nominal(parameter) == pytest.approx(middle)


def test_spread_of_what_has_no_number() -> None:
    reference = scm.ParameterRef(parameter=scm.ModuleParameter(name="gap"))
    assert spread(reference) is None and nominal(reference) is None
    assert spread(None) is None and spread(None, 0.0) == [0.0]


def test_locate_world_positions() -> None:
    concrete = world(3, 4, h=value(1.0))
    assert is_concrete(concrete)
    assert [(p.x, p.y, p.heading, p.lane) for p in locate(concrete, None)] == [
        (3.0, 4.0, 1.0, None)
    ]
    logical = world(span(0, 10), 5, h=value(4.0))
    assert not is_concrete(logical)
    points = locate(logical, None)
    assert [(p.x, p.y) for p in points] == [(0.0, 5.0), (5.0, 5.0), (10.0, 5.0)]
    assert all(p.heading == pytest.approx(4.0 - 2 * math.pi) for p in points)
    assert locate(scm.WorldPosition(x=value(1), y=value(2)), None)[0].heading is None
    gap = scm.ParameterRef(parameter=scm.ModuleParameter(name="gap"))
    assert locate(world(gap, 5), None) == []


def test_locate_lane_positions_on_our_map(our_map: RoadMap) -> None:
    points = locate(lane("3", 1, span(20, 40), 0.5), our_map)
    assert [p.lane for p in points] == [("3", 1, s, 0.5) for s in (20.0, 30.0, 40.0)]
    for point, s in zip(points, (20.0, 30.0, 40.0), strict=True):
        # the offset runs with t, to the left of the reference line (which points south here)
        assert (point.x, point.y) == pytest.approx((1.75 + 0.5, -9.0 - s))
        assert point.heading == pytest.approx(math.pi / 2)
    middle = centre(lane("3", 1, span(20, 40), 0.5), our_map)
    assert middle is not None and middle.lane == ("3", 1, 30.0, 0.5)
    assert (middle.x, middle.y) == pytest.approx((2.25, -39.0))
    assert locate(lane("3", 1, 30.0), None) == []  # a lane position needs the map
    gap = scm.ParameterRef(parameter=scm.ModuleParameter(name="gap"))
    assert locate(lane("3", 1, gap), our_map) == []
    with pytest.raises(PositionError, match="no road '99'"):
        locate(lane("99", 1, 30.0), our_map)
    assert centre(lane("99", 1, 30.0), our_map) is None


def test_lane_sections_listed_out_of_order_are_read_by_s(tmp_path: Path) -> None:
    text = evaluator.XODR.read_text(encoding="utf-8")
    # Road 1 gets a second lane section at s=50, written before the first one.
    start = text.index('<road rule="RHT" id="1"')
    first = text.index("<laneSection", start)
    end = text.index("</laneSection>", first) + len("</laneSection>")
    section = text[first:end]
    later = section.replace('<laneSection s="0"', '<laneSection s="50"').replace(
        'type="sidewalk"', 'type="biking"'
    )
    changed = text[:first] + later + section + text[end:]
    path = tmp_path / "sections.xodr"
    path.write_text(changed, encoding="utf-8")
    road = load_map(path).road("1")
    assert [section.s for section in road.sections] == [0.0, 50.0]
    assert road.section_at(20.0).lane(2).type == "sidewalk"
    assert road.section_at(70.0).lane(2).type == "biking"


def _linked_road(road_id: str, x: float, successor: str = "") -> str:
    plan = (
        f'<planView><geometry s="0" x="{x}" y="0" hdg="0" length="10"><line/></geometry>'
        "</planView>\n"
    )
    link = f"<link>{successor}</link>\n" if successor else ""
    return f'<road id="{road_id}" junction="-1" length="10">\n{link}{plan}{_LANES}</road>\n'


def test_a_direct_junction_leads_into_its_linked_road(tmp_path: Path) -> None:
    """OpenDRIVE 1.7's direct junction names `linkedRoad`, not `connectingRoad` (esmini's
    soderleden.xodr): it reads, and traffic from the incoming road goes on into that road."""
    junction = (
        '<junction id="9" name="" type="direct">\n'
        '<connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start">'
        '<laneLink from="-1" to="-1"/></connection>\n</junction>\n'
    )
    successor = '<successor elementType="junction" elementId="9"/>'
    path = tmp_path / "direct.xodr"
    text = _HEADER + _linked_road("1", 0.0, successor) + _linked_road("2", 10.0) + junction
    path.write_text(text + "</OpenDRIVE>\n", encoding="utf-8")
    road_map = load_map(path)
    (connection,) = road_map.junctions["9"].connections
    assert (connection.incoming_road, connection.connecting_road) == ("1", "2")
    (route,) = routes_from(road_map, "1", -1)
    assert (route.connecting_road, route.turn) == ("2", "straight")
    assert route.reaches("2", -1)


def test_a_way_through_several_junctions(built: dict[str, RoadMap]) -> None:
    """Junction by junction, through the fewest: the north arm of the second T is straight on
    at the first and left at the second from the first's west arm (eastbound, lane -1)."""
    road_map = built["two tees"]
    way = way_to(road_map, sg.FIRST_WEST, -1, sg.SECOND_NORTH)
    assert [(r.junction, r.exit_road, r.turn) for r in way or []] == [
        (sg.FIRST_TEE, sg.BETWEEN, "straight"),
        (sg.SECOND_TEE, sg.SECOND_NORTH, "left"),
    ]
    # Back from the north arm (southbound, lane 1) to the first T's south arm: right, then left.
    back = way_to(road_map, sg.SECOND_NORTH, 1, sg.FIRST_SOUTH, -1)
    assert [(r.junction, r.turn) for r in back or []] == [
        (sg.SECOND_TEE, "right"),
        (sg.FIRST_TEE, "left"),
    ]
    # The next junction is enough for the road between them.
    assert len(way_to(road_map, sg.FIRST_WEST, -1, sg.BETWEEN) or []) == 1
    # No connection turns back: the west arm's own westbound lane is out of reach from it.
    assert way_to(road_map, sg.FIRST_WEST, -1, sg.FIRST_WEST, 1) is None


def test_the_import_tests_two_tees_map_is_the_builders(tmp_path: Path) -> None:
    """tests/importer/files/two-tees.xodr is `two_tees_network`'s output (all but its date)."""
    built, kept = sg.two_tees_network(tmp_path), IMPORT_FILES / "two-tees.xodr"
    roots = [etree.parse(str(path)).getroot() for path in (built, kept)]
    for root in roots:
        root.find("header").attrib.pop("date", None)
    assert etree.tostring(roots[0]) == etree.tostring(roots[1])

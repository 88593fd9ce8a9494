"""OpenDRIVE maps built by scenariogeneration for the tests of `sceml.maps`.

Each builder writes one .xodr file and returns its path. scenariogeneration computes the start
of every geometry from the end of the one before (`adjust_roads_and_lanes`), so the files carry
its own reference values for the tests to compare against.
"""

from __future__ import annotations

import math
from pathlib import Path

from scenariogeneration import xodr
from scipy.integrate import quad
from scipy.optimize import brentq

#: Roads of `curvy_network`.
MIXED, VARYING, LEFT_HAND = "1", "2", "3"
#: Roads of `tee_network`: the junction's arms (west, east, south) and the junction id.
WEST, EAST, SOUTH, TEE = "10", "11", "12", "5"

#: laneOffset of the mixed road, a + b*s + c*s^2 + d*s^3.
MIXED_LANE_OFFSET = (0.5, 0.01, -1e-4, 4e-7)
#: laneOffset of the varying road (its lanes all lie right of the reference line).
VARYING_LANE_OFFSET = (-1.5, 0.0, 0.0, 0.0)
#: Where the varying road's lane sections start.
VARYING_SECTIONS = (0.0, 35.0, 70.0)


#: The arcLength paramPoly3: v(p) = c*p^2 + d*p^3 over p in [0, length].
_ARC_V, _ARC_LENGTH = (0.004, -0.0001), 20.0


def _arc_length_bu() -> float:
    """The u slope that makes the curve exactly `_ARC_LENGTH` long over p in [0, _ARC_LENGTH].

    With pRange="arcLength" p runs to the declared length, so the curve must be that long
    (ASAM's checker rule parampoly3_length_match); with u = p it would be 1.8 cm longer.
    """
    c, d = _ARC_V

    def excess(bu: float) -> float:
        speed = lambda p: math.hypot(bu, 2 * c * p + 3 * d * p * p)  # noqa: E731
        return float(quad(speed, 0.0, _ARC_LENGTH)[0]) - _ARC_LENGTH

    return float(brentq(excess, 0.9, 1.0, xtol=1e-14))


_ARC_BU = _arc_length_bu()


def _opendrive() -> xodr.OpenDrive:
    return xodr.OpenDrive("sceml_test", revMajor="1", revMinor="7")


def _mixed_road() -> xodr.Road:
    """Line, arc, clothoid, paramPoly3 (normalized and arcLength), line; a lane split and merge."""
    geometries = [
        xodr.Line(20),
        xodr.Arc(0.02, length=30),
        xodr.Spiral(0.02, -0.01, length=25),
        xodr.ParamPoly3(0, 30, 0.5, -0.2, 0, 0, 3, -1, prange="normalized"),
        xodr.ParamPoly3(0, _ARC_BU, 0, 0, 0, 0, *_ARC_V, prange="arcLength", length=_ARC_LENGTH),
        xodr.Line(10),
    ]
    road = xodr.create_road(
        geometries,
        int(MIXED),
        left_lanes=[xodr.LaneDef(30, 60, 1, 2, 2)],  # lane 2 grows from nothing
        right_lanes=[xodr.LaneDef(30, 60, 2, 1, -2)],  # lane -2 narrows to nothing
        lane_width=3.5,
    )
    road.lanes.add_laneoffset(xodr.LaneOffset(0, *MIXED_LANE_OFFSET))
    road.planview.set_start_point(100.0, 200.0, 0.3)
    return road


def _continued(coefficients: tuple[float, ...], length: float, c: float, d: float) -> tuple:
    """A width polynomial that starts where `coefficients` ends, with the same slope."""
    a0, b0, c0, d0 = coefficients
    a = a0 + length * (b0 + length * (c0 + length * d0))
    b = b0 + length * (2 * c0 + length * 3 * d0)
    return (a, b, c, d)


def varying_widths() -> dict[int, list[tuple[float, ...]]]:
    """Width polynomials (a, b, c, d) of the varying road's lanes, one per lane section."""
    widths: dict[int, list[tuple[float, ...]]] = {
        -1: [(3.0, 0.02, -4e-4, 5e-6)],
        -2: [(2.5, -0.01, 3e-4, -2e-6)],
    }
    curvature = {-1: (2e-4, -3e-6), -2: (-1e-4, 1e-6)}
    for start, end in zip(VARYING_SECTIONS, VARYING_SECTIONS[1:], strict=False):
        for lane_id, records in widths.items():
            records.append(_continued(records[-1], end - start, *curvature[lane_id]))
    return widths


def _varying_road() -> xodr.Road:
    """Straight; three lane sections with cubic widths (b, c, d != 0), right lanes offset right."""
    planview = xodr.PlanView(-40.0, 30.0, 0.0)  # along the x axis: its box is only its lanes
    planview.add_geometry(xodr.Line(90))
    lanes = xodr.Lanes()
    widths = varying_widths()
    for index, start in enumerate(VARYING_SECTIONS):
        section = xodr.LaneSection(start, xodr.standard_lane())
        for lane_id in (-1, -2):
            a, b, c, d = widths[lane_id][index]
            section.add_right_lane(xodr.Lane(a=a, b=b, c=c, d=d))
        lanes.add_lanesection(section)
    lanes.add_laneoffset(xodr.LaneOffset(0, *VARYING_LANE_OFFSET))
    return xodr.Road(int(VARYING), planview, lanes)


def _left_hand_road() -> xodr.Road:
    road = xodr.create_road(
        [xodr.Arc(-0.01, length=40)], int(LEFT_HAND), left_lanes=1, right_lanes=2, lane_width=3
    )
    road.rule = xodr.TrafficRule.LHT
    road.planview.set_start_point(0.0, -80.0, 2.0)
    return road


def curvy_network(folder: Path) -> Path:
    """Three unconnected roads: every geometry kind, varying widths, laneOffset, left-hand traffic."""
    odr = _opendrive()
    for road in (_mixed_road(), _varying_road(), _left_hand_road()):
        odr.add_road(road)
    odr.adjust_roads_and_lanes()
    path = folder / "curvy.xodr"
    odr.write_xml(str(path))
    return path


def tee_network(folder: Path) -> Path:
    """A T junction by scenariogeneration's CommonJunctionCreator, one lane each way.

    The west arm ends at the junction (its successor), the east and south arms start there (their
    predecessor), so traffic enters along s on one arm and against s on the others.
    """
    odr = _opendrive()
    creator = xodr.CommonJunctionCreator(int(TEE), "tee", startnum=100)
    arms = {
        WEST: (-15.0, 0.0, 0.0, "successor"),
        EAST: (15.0, 0.0, math.pi, "predecessor"),
        SOUTH: (0.0, -15.0, math.pi / 2, "predecessor"),
    }
    for road_id, (x, y, heading, end) in arms.items():
        road = xodr.create_road(xodr.Line(60), int(road_id), 1, 1, lane_width=3.5)
        odr.add_road(road)
        creator.add_incoming_road_cartesian_geometry(road, x, y, heading, road_connection=end)
    for one, two in ((WEST, EAST), (WEST, SOUTH), (EAST, SOUTH)):
        creator.add_connection(int(one), int(two))
    odr.add_junction_creator(creator)
    odr.adjust_roads_and_lanes()
    path = folder / "tee.xodr"
    odr.write_xml(str(path))
    return path


#: Roads of `two_tees_network`: the first junction's west and south arms, the road between the
#: junctions, the second junction's east and north arms; and the two junction ids.
FIRST_WEST, FIRST_SOUTH, BETWEEN, SECOND_EAST, SECOND_NORTH = "30", "31", "32", "33", "34"
FIRST_TEE, SECOND_TEE = "7", "8"


def two_tees_network(folder: Path) -> Path:
    """Two T junctions 130 m apart on one east-west street, one lane each way: the first has a
    south arm, the second a north arm. Driving east from the west arm, the north arm is reached
    only through both junctions: straight on at the first, left at the second."""
    odr = _opendrive()
    first = xodr.CommonJunctionCreator(int(FIRST_TEE), "first", startnum=200)
    second = xodr.CommonJunctionCreator(int(SECOND_TEE), "second", startnum=300)
    between = xodr.create_road(xodr.Line(100), int(BETWEEN), 1, 1, lane_width=3.5)
    odr.add_road(between)
    first.add_incoming_road_cartesian_geometry(between, 15.0, 0.0, math.pi, "predecessor")
    second.add_incoming_road_cartesian_geometry(between, 115.0, 0.0, 0.0, "successor")
    arms = {
        FIRST_WEST: (first, -15.0, 0.0, 0.0, "successor"),
        FIRST_SOUTH: (first, 0.0, -15.0, math.pi / 2, "predecessor"),
        SECOND_EAST: (second, 145.0, 0.0, math.pi, "predecessor"),
        SECOND_NORTH: (second, 130.0, 15.0, -math.pi / 2, "predecessor"),
    }
    for road_id, (creator, x, y, heading, end) in arms.items():
        road = xodr.create_road(xodr.Line(60), int(road_id), 1, 1, lane_width=3.5)
        odr.add_road(road)
        creator.add_incoming_road_cartesian_geometry(road, x, y, heading, road_connection=end)
    for creator, roads in (
        (first, (FIRST_WEST, BETWEEN, FIRST_SOUTH)),
        (second, (BETWEEN, SECOND_EAST, SECOND_NORTH)),
    ):
        for one, two in ((roads[0], roads[1]), (roads[0], roads[2]), (roads[1], roads[2])):
            creator.add_connection(int(one), int(two))
        odr.add_junction_creator(creator)
    odr.adjust_roads_and_lanes()
    path = folder / "two-tees.xodr"
    odr.write_xml(str(path))
    return path

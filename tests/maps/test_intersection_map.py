"""Tests for the four-way intersection map (maps/intersection.xodr) and its positions.

The geometry is evaluated here with a small, independent OpenDRIVE evaluator (line, arc and
spiral by numerical integration of the heading); the build script uses pyclothoids instead.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

REPO = Path(__file__).resolve().parents[2]
MAPS = REPO / "maps"
SCRIPT = MAPS / "build_intersection.py"
XODR = MAPS / "intersection.xodr"
POSITIONS = MAPS / "positions.json"

# Gauss-Legendre nodes on [0, 1] for integrating cos/sin of the heading along a geometry.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(40)
_GL_X, _GL_W = (_GL_X + 1) / 2, _GL_W / 2


def wrap(angle: float) -> float:
    """Wrap to (-pi, pi]."""
    return -((-angle + math.pi) % (2 * math.pi) - math.pi)


class Road:
    """Reference line and lanes of one <road> (single lane section, no laneOffset)."""

    def __init__(self, element: etree._Element) -> None:
        self.id = element.get("id")
        self.junction = element.get("junction")
        self.length = float(element.get("length"))
        self.element = element
        self.geometries = []
        for geom in element.find("planView").findall("geometry"):
            (shape,) = list(geom)
            if shape.tag == "line":
                k0 = k1 = 0.0
            elif shape.tag == "arc":
                k0 = k1 = float(shape.get("curvature"))
            elif shape.tag == "spiral":
                k0, k1 = float(shape.get("curvStart")), float(shape.get("curvEnd"))
            else:
                raise NotImplementedError(shape.tag)
            values = [float(geom.get(k)) for k in ("s", "x", "y", "hdg", "length")]
            self.geometries.append((*values, k0, k1))
        sections = element.find("lanes").findall("laneSection")
        assert len(sections) == 1, "evaluator supports one lane section per road"
        assert element.find("lanes").find("laneOffset") is None
        self.lanes = {}
        for lane in sections[0].iter("lane"):
            widths = lane.findall("width")
            if widths:
                assert len(widths) == 1
                coeffs = [float(widths[0].get(k)) for k in "abcd"]
            else:
                coeffs = [0.0] * 4
            self.lanes[int(lane.get("id"))] = (lane.get("type"), coeffs)

    def reference(self, s: float) -> tuple[float, float, float]:
        """x, y, heading of the reference line at s."""
        geom = self.geometries[-1]
        for candidate in self.geometries:
            if s <= candidate[0] + candidate[4] + 1e-9:
                geom = candidate
                break
        s0, x0, y0, h0, length, k0, k1 = geom
        ds = s - s0
        dk = (k1 - k0) / length

        def heading(u):
            return h0 + k0 * u + dk * u * u / 2

        u = _GL_X * ds
        x = x0 + ds * np.sum(_GL_W * np.cos(heading(u)))
        y = y0 + ds * np.sum(_GL_W * np.sin(heading(u)))
        return float(x), float(y), float(heading(ds))

    def width(self, lane_id: int, s: float) -> float:
        a, b, c, d = self.lanes[lane_id][1]
        return a + b * s + c * s**2 + d * s**3

    def lane_bounds(self, lane_id: int, s: float) -> tuple[float, float]:
        """Inner and outer |t| of a lane."""
        sign = 1 if lane_id > 0 else -1
        inner = sum(self.width(sign * i, s) for i in range(1, abs(lane_id)))
        return inner, inner + self.width(lane_id, s)

    def lane_centre(self, lane_id: int, s: float) -> tuple[float, float, float]:
        inner, outer = self.lane_bounds(lane_id, s)
        t = math.copysign((inner + outer) / 2, lane_id)
        x, y, h = self.reference(s)
        return x - t * math.sin(h), y + t * math.cos(h), h

    def project(self, x: float, y: float) -> tuple[float, float]:
        """(s, t) of the point closest to (x, y) on the reference line (by sampling + refining)."""
        samples = np.linspace(0.0, self.length, int(self.length * 10) + 1)
        points = np.array([self.reference(s)[:2] for s in samples])
        best = float(samples[np.argmin(np.hypot(points[:, 0] - x, points[:, 1] - y))])
        lo, hi = max(0.0, best - 0.1), min(self.length, best + 0.1)
        for _ in range(60):  # golden-section search on the distance
            m1, m2 = lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618
            d1 = math.dist(self.reference(m1)[:2], (x, y))
            d2 = math.dist(self.reference(m2)[:2], (x, y))
            lo, hi = (lo, m2) if d1 < d2 else (m1, hi)
        s = (lo + hi) / 2
        rx, ry, h = self.reference(s)
        t = -(x - rx) * math.sin(h) + (y - ry) * math.cos(h)
        return s, t


@cache
def tree() -> etree._ElementTree:
    return etree.parse(str(XODR))


@cache
def roads() -> dict[str, Road]:
    return {r.get("id"): Road(r) for r in tree().getroot().findall("road")}


@cache
def positions() -> dict:
    return json.loads(POSITIONS.read_text(encoding="utf-8"))


def all_positions() -> list[tuple[str, str, dict]]:
    data = positions()
    return [(sc, name, pos) for sc in ("uis1", "uis2") for name, pos in data[sc].items()]


# --- (1) determinism -----------------------------------------------------------------------


def test_script_regenerates_committed_files(tmp_path: Path) -> None:
    out = tmp_path / "out" / "intersection.xodr"
    for _ in range(2):  # twice: the second run must not differ from the first either
        subprocess.run(
            [sys.executable, str(SCRIPT), "-o", str(out)],
            cwd=tmp_path,
            check=True,
            capture_output=True,
        )
        assert out.read_bytes() == XODR.read_bytes()
        assert (out.parent / "positions.json").read_bytes() == POSITIONS.read_bytes()


# --- (2) structure ---------------------------------------------------------------------------


def test_well_formed_opendrive() -> None:
    root = tree().getroot()
    assert root.tag == "OpenDRIVE"
    header = root.find("header")
    assert (header.get("revMajor"), header.get("revMinor")) == ("1", "7")
    assert header.get("date") == "2024-01-01T00:00:00"
    junctions = root.findall("junction")
    assert len(junctions) == 1
    ids = [r.get("id") for r in root.findall("road")]
    assert len(ids) == len(set(ids))


def test_arms_match_description() -> None:
    desc = positions()["map"]
    assert set(desc["arms"]) == {"north", "east", "south", "west"}
    for name, arm in desc["arms"].items():
        road = roads()[arm["roadId"]]
        assert road.junction == "-1"
        assert road.length == pytest.approx(100.0)
        pred = road.element.find("link/predecessor")
        assert pred.get("elementType") == "junction"
        assert pred.get("elementId") == desc["junctionId"]
        # the arm starts at the junction boundary and points away from the centre
        x, y, h = road.reference(0.0)
        assert math.atan2(y, x) == pytest.approx(wrap(h), abs=1e-6), name
        assert math.hypot(x, y) == pytest.approx(desc["junction_radius"])
        for lane_id in arm["driving"].values():
            assert road.lanes[lane_id][0] == "driving"
            assert road.width(lane_id, 0) == pytest.approx(3.5)
        for lane_id in arm["sidewalk"].values():
            assert road.lanes[lane_id][0] == "sidewalk"
            assert road.width(lane_id, 0) == pytest.approx(2.0)
        assert sorted(road.lanes) == [-2, -1, 0, 1, 2]


def _movement(in_heading: float, out_heading: float) -> str:
    turn = wrap(out_heading - in_heading)
    if abs(turn) < 0.1:
        return "straight"
    if abs(turn - math.pi / 2) < 0.1:
        return "left"
    if abs(turn + math.pi / 2) < 0.1:
        return "right"
    return f"other({turn:.2f})"


def test_junction_connects_all_movements() -> None:
    desc = positions()["map"]
    arm_of = {arm["roadId"]: name for name, arm in desc["arms"].items()}
    outward = {rid: roads()[rid].reference(0.0)[2] for rid in arm_of}
    (junction,) = tree().getroot().findall("junction")
    found: dict[str, set[str]] = {name: set() for name in desc["arms"]}
    for conn in junction.findall("connection"):
        incoming, connecting = conn.get("incomingRoad"), conn.get("connectingRoad")
        croad = roads()[connecting]
        assert croad.junction == junction.get("id")
        pred = croad.element.find("link/predecessor").get("elementId")
        succ = croad.element.find("link/successor").get("elementId")
        for link in conn.findall("laneLink"):
            lane_from, lane_to = int(link.get("from")), int(link.get("to"))
            assert lane_from in roads()[incoming].lanes
            assert lane_to in croad.lanes
            if croad.lanes[lane_to][0] != "driving":
                continue
            assert roads()[incoming].lanes[lane_from][0] == "driving"
            # lane -1 of a connecting road runs from its predecessor to its successor
            src, dst = (pred, succ) if lane_to < 0 else (succ, pred)
            if incoming != src:
                continue
            found[arm_of[src]].add(_movement(outward[src] + math.pi, outward[dst]))
    for name, movements in found.items():
        assert movements == {"straight", "left", "right"}, name


def test_connecting_lanes_join_arm_lanes() -> None:
    """Every connecting lane starts and ends on the centre of the lane it is linked to."""
    for road in roads().values():
        if road.junction == "-1":
            continue
        lane_el = road.element.find("lanes/laneSection/right/lane")
        lane_id = int(lane_el.get("id"))
        for end, s in (("predecessor", 0.0), ("successor", road.length)):
            link = road.element.find(f"link/{end}")
            assert link.get("contactPoint") == "start"
            other = roads()[link.get("elementId")]
            other_lane = int(lane_el.find(f"link/{end}").get("id"))
            assert other.lanes[other_lane][0] == road.lanes[lane_id][0]
            here = road.lane_centre(lane_id, s)
            there = other.lane_centre(other_lane, 0.0)
            assert math.dist(here[:2], there[:2]) < 0.01, (road.id, end)
            # tangent continuity (direction may be reversed)
            assert abs(math.sin(here[2] - there[2])) < 1e-3, (road.id, end)
            assert road.width(lane_id, s) == pytest.approx(other.width(other_lane, 0.0))


# --- (3) positions -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    "scenario, name, pos", all_positions(), ids=[f"{a}-{b}" for a, b, _ in all_positions()]
)
def test_position_lies_in_claimed_lane(scenario: str, name: str, pos: dict) -> None:
    assert set(pos) >= {"x", "y", "z", "h", "roadId", "laneId", "s", "offset"}
    assert isinstance(pos["roadId"], str) and isinstance(pos["laneId"], int)
    assert pos["z"] == 0.0
    road = roads()[pos["roadId"]]
    lane_id = pos["laneId"]
    assert lane_id != 0 and lane_id in road.lanes
    # world -> lane: project the world point onto the road, independently of the script
    s, t = road.project(pos["x"], pos["y"])
    assert s == pytest.approx(pos["s"], abs=0.01)
    inner, outer = road.lane_bounds(lane_id, s)
    centre = math.copysign((inner + outer) / 2, lane_id)
    assert abs(t - centre - pos["offset"]) < 0.01
    assert abs(t - centre) < (outer - inner) / 2
    # lane -> world
    x, y, h = road.lane_centre(lane_id, pos["s"])
    assert math.dist((x, y), (pos["x"], pos["y"])) < 0.01
    if road.lanes[lane_id][0] == "driving":  # vehicles face the driving direction
        expected = h if lane_id < 0 else h + math.pi
        assert abs(wrap(pos["h"] - expected)) < 1e-3


def _lane_type(pos: dict) -> str:
    return roads()[pos["roadId"]].lanes[pos["laneId"]][0]


def test_scenario_semantics() -> None:
    data = positions()
    arms = {name: arm["roadId"] for name, arm in data["map"]["arms"].items()}
    conn = data["map"]["connecting_roads"]
    uis1, uis2 = data["uis1"], data["uis2"]
    north = math.pi / 2

    ego = uis1["ego_start"]
    assert (ego["roadId"], ego["laneId"], ego["s"]) == (arms["south"], 1, 30.0)
    assert (uis1["ego_destination"]["roadId"], uis1["ego_destination"]["laneId"]) == (
        arms["east"],
        -1,
    )
    assert uis2["ego_start"] == ego
    assert (uis2["ego_destination"]["roadId"], uis2["ego_destination"]["laneId"]) == (
        arms["west"],
        -1,
    )
    # the bike rides north on the south arm's east sidewalk, ahead of the ego
    bike = uis1["bike_start"]
    assert _lane_type(bike) == "sidewalk" and bike["roadId"] == arms["south"]
    assert bike["x"] > ego["x"] and bike["y"] > ego["y"]
    assert wrap(bike["h"] - north) == pytest.approx(0, abs=1e-6)
    # ... and ends north of the east arm, having crossed it
    dest = uis1["bike_destination"]
    assert _lane_type(dest) == "sidewalk" and dest["roadId"] == arms["east"]
    assert dest["y"] > 0 > uis1["ego_destination"]["y"]

    oncoming, oncoming_dest = uis2["oncoming_start"], uis2["oncoming_destination"]
    assert (oncoming["roadId"], oncoming["laneId"]) == (arms["north"], 1)
    assert (oncoming_dest["roadId"], oncoming_dest["laneId"]) == (arms["south"], -1)
    straight = roads()[conn["north->south"]]
    drive_distance = oncoming["s"] + straight.length + oncoming_dest["s"]
    assert drive_distance == pytest.approx(60.0, abs=0.5)

    sync = uis2["intersection_location"]
    assert sync["roadId"] == conn["south->west"] and sync["laneId"] == -1
    assert math.hypot(sync["x"], sync["y"]) < data["map"]["junction_radius"] / 2

    ped, ped_dest = uis2["pedestrian_start"], uis2["pedestrian_destination"]
    assert ped["roadId"] == ped_dest["roadId"] == arms["west"]
    assert _lane_type(ped) == _lane_type(ped_dest) == "sidewalk"
    assert ped["y"] < uis2["ego_destination"]["y"] < ped_dest["y"]


# --- (4) schema --------------------------------------------------------------------------------


def _opendrive_17_schema() -> Path | None:
    """OpenDRIVE 1.7 XSD shipped with scenariogeneration (or asam-qc-opendrive), if installed."""
    candidates = []
    try:
        import scenariogeneration

        candidates.append(Path(scenariogeneration.__file__).parents[1] / "schemas")
    except ImportError:
        pass
    try:
        import qc_opendrive

        candidates.append(Path(qc_opendrive.__file__).parent / "schema" / "1.7.0")
    except ImportError:
        pass
    for folder in candidates:
        if (folder / "opendrive_17_core.xsd").is_file():
            return folder / "opendrive_17_core.xsd"
    return None


def test_validates_against_opendrive_17_xsd() -> None:
    xsd = _opendrive_17_schema()
    if xsd is None:
        # scenariogeneration (a test dependency) ships the XSD, so under CI it must be there.
        if os.environ.get("CI"):
            pytest.fail("no OpenDRIVE 1.7 XSD installed (scenariogeneration ships one)")
        pytest.skip("no OpenDRIVE 1.7 XSD installed")
    schema = etree.XMLSchema(etree.parse(str(xsd)))
    ok = schema.validate(tree())
    assert ok, "\n".join(f"{e.line}: {e.message}" for e in list(schema.error_log)[:20])

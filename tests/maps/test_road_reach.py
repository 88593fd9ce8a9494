"""Each road's reach (how far its lanes extend from its reference line, which grows its bounding
box) is worked out without `RoadMap.bands`, for speed; it must give the same floats as `bands`."""

from __future__ import annotations

from pathlib import Path

import pytest

from maps import sg_networks as sg
from maps import test_intersection_map as evaluator
from sceml.maps import RoadMap, load_map
from sceml.maps.model import piecewise

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def maps(tmp_path_factory: pytest.TempPathFactory) -> dict[str, RoadMap]:
    folder = tmp_path_factory.mktemp("scenariogeneration")
    files = ROOT / "tests" / "importer" / "files"
    return {
        "intersection": load_map(evaluator.XODR),
        "highway": load_map(files / "highway.xodr"),
        "two-tees": load_map(files / "two-tees.xodr"),
        "curvy": load_map(sg.curvy_network(folder)),
        "tee": load_map(sg.tee_network(folder)),
    }


def _reach_by_bands(road_map: RoadMap) -> dict[str, float]:
    """The reach as it was computed before, from a LaneBand per lane and sample."""
    return {
        road.id: max(
            (
                sum(abs(b.outer - b.inner) for b in road_map.bands(road, s))
                + (abs(piecewise(road.lane_offset, s)) if road.lane_offset else 0.0)
                for s in road_map.reference_line(road.id).s
            ),
            default=0.0,
        )
        for road in road_map.roads.values()
    }


@pytest.mark.parametrize("name", ["intersection", "highway", "two-tees", "curvy", "tee"])
def test_the_reach_equals_the_one_bands_give(maps: dict[str, RoadMap], name: str) -> None:
    road_map = maps[name]
    expected = _reach_by_bands(road_map)
    assert road_map._reach == expected  # the same floats, not close ones
    assert all(reach > 0 for reach in expected.values())  # every road here has lanes


def test_the_intersections_roads_reach_their_lanes_widths() -> None:
    # maps/intersection.xodr (built by maps/build_intersection.py): outside the junction each road
    # has a 3.5 m driving lane and a 2 m sidewalk a side and no lane offset: 11 m in all (read by
    # hand in the file).
    road_map = load_map(evaluator.XODR)
    straight = [r for r in road_map.roads.values() if r.junction in (None, "-1", "")]
    assert straight
    for road in straight:
        assert road_map._reach[road.id] == 11.0

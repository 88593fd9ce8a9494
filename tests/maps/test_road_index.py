"""The road index of `RoadMap.world_to_lane` only skips roads: every answer equals the one found
by projecting onto every road, as before the index (issue 31)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from maps import sg_networks as sg
from maps import test_intersection_map as evaluator
from sceml.maps import LaneCoordinate, RoadMap, load_map

ROOT = Path(__file__).resolve().parents[2]
TOLERANCES = (0.0, 0.5, 1.0, 50.0)


@pytest.fixture(scope="module")
def maps(tmp_path_factory: pytest.TempPathFactory) -> dict[str, RoadMap]:
    folder = tmp_path_factory.mktemp("scenariogeneration")
    return {
        "intersection": load_map(evaluator.XODR),
        "highway": load_map(ROOT / "tests" / "importer" / "files" / "highway.xodr"),
        "curvy": load_map(sg.curvy_network(folder)),
        "tee": load_map(sg.tee_network(folder)),
    }


def _every_road(road_map: RoadMap, x: float, y: float, tolerance: float) -> list[LaneCoordinate]:
    """world_to_lane with the index and the kept answers bypassed: each road's box, then its
    projection."""
    original = RoadMap._near
    try:
        RoadMap._near = lambda self, x, y, tolerance: list(self.roads.values())  # type: ignore[method-assign]
        return road_map._lanes_at(x, y, tolerance)
    finally:
        RoadMap._near = original  # type: ignore[method-assign]


def _points(road_map: RoadMap, count: int, seed: int) -> list[tuple[float, float]]:
    """Uniform points over the map's box (grown by 20 m) and points a few metres off lane
    centres, where lanes and their edges are."""
    rng = np.random.default_rng(seed)
    xmin, ymin, xmax, ymax = road_map.bounds()
    points = [
        (float(x), float(y))
        for x, y in zip(
            rng.uniform(xmin - 20, xmax + 20, count),
            rng.uniform(ymin - 20, ymax + 20, count),
            strict=True,
        )
    ]
    for road in road_map.roads.values():
        for lane in (band.lane for band in road_map.bands(road, 0.0)):
            for s in rng.uniform(0.0, road.length, 3):
                try:
                    pose = road_map.lane_to_world(road.id, lane.id, float(s))
                except Exception:  # a lane that is not there at s
                    continue
                dx, dy = rng.normal(0.0, 2.0, 2)
                points.append((pose.x + float(dx), pose.y + float(dy)))
    return points


@pytest.mark.parametrize("name", ["intersection", "highway", "curvy", "tee"])
def test_the_index_changes_no_answer(maps: dict[str, RoadMap], name: str) -> None:
    road_map = maps[name]
    compared = found = 0
    for x, y in _points(road_map, 400, seed=31):
        for tolerance in TOLERANCES:
            answer = road_map.world_to_lane(x, y, tolerance)
            expected = _every_road(road_map, x, y, tolerance)
            assert answer == expected, (name, x, y, tolerance)
            # Asked again, the kept answer: equal, and a list of its own.
            again = road_map.world_to_lane(x, y, tolerance)
            assert again == expected and again is not answer
            compared += 1
            found += bool(expected)
    # The points must exercise both answers: lanes found and none.
    assert found > compared // 10
    assert compared - found > 0


def test_the_index_skips_roads_far_away(maps: dict[str, RoadMap]) -> None:
    """At a lane centre on an arm of the intersection only the roads near it are considered."""
    road_map = maps["intersection"]
    road = next(iter(road_map.roads.values()))
    pose = road_map.lane_to_world(road.id, -1, road.length / 2)
    near = road_map._near(pose.x, pose.y, 0.0)
    assert road in near
    assert len(near) < len(road_map.roads)

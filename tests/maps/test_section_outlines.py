"""Lane outlines drawn a section at a time equal each lane's outline taken point by point, and
thinning a line keeps exactly the points that leave the chord (issue 31: the preview page)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from maps import sg_networks as sg
from maps import test_intersection_map as evaluator
from sceml.maps import PositionError, RoadMap, load_map
from sceml.maps.planview import SAMPLE_STEP
from sceml.render.mapscene import thin

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def maps(tmp_path_factory: pytest.TempPathFactory) -> dict[str, RoadMap]:
    folder = tmp_path_factory.mktemp("scenariogeneration")
    return {
        "intersection": load_map(evaluator.XODR),
        "highway": load_map(ROOT / "tests" / "importer" / "files" / "highway.xodr"),
        "curvy": load_map(sg.curvy_network(folder)),
    }


def _outline_point_by_point(road_map: RoadMap, road_id: str, index: int, lane_id: int) -> list:
    """The outline from the public per-point answers: the pose at s and the lane's band at s."""
    road = road_map.road(road_id)
    section = road.sections[index]
    end = road.sections[index + 1].s if index + 1 < len(road.sections) else road.length
    count = max(2, math.ceil((end - section.s) / SAMPLE_STEP) + 1)
    inner, outer = [], []
    for s in np.linspace(section.s, end, count):
        x, y, h = road_map.reference_line(road.id).pose(float(s))
        band = road_map.band(road.id, lane_id, float(s))
        inner.append((x - band.inner * math.sin(h), y + band.inner * math.cos(h)))
        outer.append((x - band.outer * math.sin(h), y + band.outer * math.cos(h)))
    return inner + outer[::-1]


@pytest.mark.parametrize("name", ["intersection", "highway", "curvy"])
def test_each_lane_of_each_section_has_its_point_by_point_outline(
    maps: dict[str, RoadMap], name: str
) -> None:
    road_map = maps[name]
    checked = 0
    for road in road_map.roads.values():
        for index, section in enumerate(road.sections):
            try:
                wanted = {
                    lane.id: _outline_point_by_point(road_map, road.id, index, lane.id)
                    for lane in section.lanes()
                }
            except PositionError:
                continue  # a lane the next section lacks: test_a_lane_that_ends_with_its_section
            outlines = road_map.section_outlines(road, section)
            assert sorted(outlines) == sorted(wanted)
            for lane in section.lanes():
                assert outlines[lane.id].tolist() == [list(p) for p in wanted[lane.id]]
                assert road_map.lane_outline(road, section, lane.id).tolist() == (
                    outlines[lane.id].tolist()
                )
                checked += 1
    assert checked >= 4


def test_a_lane_that_ends_with_its_section_is_drawn_to_the_section_end(
    maps: dict[str, RoadMap],
) -> None:
    # curvy's road 1: its second section has a lane -2 the third does not. At the section's end
    # the next section is in force, so the per-point lookup fails there; the outline keeps the
    # section's own lane, as wide as its width polynomial says at the end.
    road_map = maps["curvy"]
    drawn = 0
    for road in road_map.roads.values():
        for index, section in enumerate(road.sections[:-1]):
            following = {lane.id for lane in road.sections[index + 1].lanes()}
            for lane in section.lanes():
                if lane.id in following:
                    continue
                outline = road_map.lane_outline(road, section, lane.id)
                end = road.sections[index + 1].s
                count = len(outline) // 2
                assert count == max(2, math.ceil((end - section.s) / SAMPLE_STEP) + 1)
                # The last sample: inner point (count - 1) and outer point (count) face each
                # other across the lane.
                across = float(np.linalg.norm(outline[count - 1] - outline[count]))
                assert across == pytest.approx(max(lane.width(end - section.s), 0.0), abs=1e-9)
                drawn += 1
    assert drawn >= 1


def test_thin_keeps_the_ends_and_the_corners_only() -> None:
    # An L: along x to (10, 0), then up to (10, 5); a chord skipping the corner misses it by 2.4 m.
    line = np.array([(0.0, 0.0), (2.5, 0.0), (5.0, 0.001), (10.0, 0.0), (10.0, 2.5), (10.0, 5.0)])
    assert thin(line).tolist() == [[0.0, 0.0], [10.0, 0.0], [10.0, 5.0]]
    # 3 cm off the chord from (0, 0) to (10, 0) is more than the default 2 cm: kept.
    bent = np.array([(0.0, 0.0), (5.0, 0.03), (10.0, 0.0)])
    assert thin(bent).tolist() == bent.tolist()
    assert thin(bent, tolerance=0.05).tolist() == [[0.0, 0.0], [10.0, 0.0]]
    two = line[:2]
    assert thin(two) is two

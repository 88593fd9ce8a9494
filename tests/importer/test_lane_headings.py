"""A LanePosition's Orientation is kept as its heading relative to the lane's direction of traffic
(esmini 3.6 reads it so: in lane-headings.xosc it places Ego at heading 0.05, Lead at 0 and
Other at 0.1 rad, checked by hand in its CSV log), exported back, placed and previewed."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml import io, schema
from sceml.build import lane
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.maps import load_map
from sceml.maps.resolve import resolve
from sceml.render.labels import describe_position
from sceml.simulate.setup import make_actor

from .test_positions_kept import VERSIONS

FILES = Path(__file__).resolve().parent / "files"
HEADINGS = FILES / "lane-headings.xosc"


def starts() -> dict[str, scm.Position]:
    imported = import_file(HEADINGS)
    assert imported.report.counts()["opaque"] == 0
    return {a.name: a.startPosition for a in imported.scenario.nodes[0].actors}


def test_orientations_import_as_headings_relative_to_the_lane() -> None:
    found = starts()
    assert {name: type(p).__name__ for name, p in found.items()} == dict.fromkeys(
        ("Ego", "Lead", "Other"), "LanePosition"
    )
    assert found["Ego"].h.value == pytest.approx(0.05)
    assert found["Lead"].h.value == pytest.approx(3.141593)
    # absolute 0.1 rad on lane -2, whose traffic runs along the road's heading 0
    assert found["Other"].h.value == pytest.approx(0.1)


def test_the_heading_places_the_start_as_esmini_does() -> None:
    road_map = load_map(FILES / "highway.xodr")
    poses = {name: resolve(p, road_map) for name, p in starts().items()}
    assert [c for p in poses.values() if p for c in (p.x, p.y)] == pytest.approx(
        [50.0, -1.75, 90.0, 1.75, 120.0, -5.25]
    )
    headings = {name: math.remainder(p.heading, math.tau) for name, p in poses.items() if p}
    assert headings == pytest.approx({"Ego": 0.05, "Lead": 0.0, "Other": 0.1}, abs=1e-5)


def test_the_preview_drives_a_turned_start_the_way_it_heads() -> None:
    road_map = load_map(FILES / "highway.xodr")
    lead = scm.Car(name="Lead", startPosition=lane(1, 1, 90.0, h=math.pi))
    actor = make_actor(lead, road_map)
    actor.place()
    assert (actor.x, actor.y, actor.heading) == pytest.approx((90.0, 1.75, 0.0), abs=1e-9)


def test_the_box_shows_the_heading() -> None:
    assert describe_position(lane(1, -1, 50.0, h=0.05), {}) == "road 1 lane -1 s 50 m, h 0.05 rad"


@pytest.mark.parametrize("version", VERSIONS)
def test_lane_headings_export_back_as_relative_orientations(version: str, tmp_path: Path) -> None:
    model = tmp_path / "lane-headings.xmi"
    import_to_file(HEADINGS, model)
    exported = tmp_path / "lane-headings.xosc"
    export_to_file(io.load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    again = import_file(exported)
    back = {a.name: a.startPosition for a in again.scenario.nodes[0].actors}
    assert {name: round(p.h.value, 6) for name, p in back.items()} == {
        "Ego": 0.05,
        "Lead": 3.141593,
        "Other": 0.1,
    }
    assert 'type="relative" h="0.1"' in exported.read_text()

"""The map view: actors, targets and radii where the model puts them, crop, ranges, errors, bytes."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Polygon, Wedge

import scemlmodel as scm
from sceml.maps import MapError
from sceml.model.loading import load
from sceml.render.mapscene import MapViewError, build_scene, junction_boxes
from sceml.render.mapview import MapFigure, draw, inline_svg, map_view

from .svgtools import SVG, parse

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
ALL_EXAMPLES = sorted(p.name for p in EXAMPLES.glob("*.xmi"))


def drawn(path: Path, extent: str = "scenario") -> MapFigure:
    document = load(path)
    return draw(build_scene(document.root, document.path), extent=extent)  # type: ignore[arg-type]


def box_of(figure: MapFigure, name: str) -> tuple[np.ndarray, float, float, float]:
    """Centre, length, width and heading (rad) of an actor's drawn rectangle."""
    polygon = figure.artists[f"actor-{name}"]
    assert isinstance(polygon, Polygon)
    corners = polygon.get_xy()[:4]
    along, across = corners[0] - corners[1], corners[1] - corners[2]
    heading = math.atan2(along[1], along[0])
    return corners.mean(axis=0), float(np.hypot(*along)), float(np.hypot(*across)), heading


@pytest.mark.parametrize("name", ALL_EXAMPLES)
def test_every_example_draws_with_each_actors_name(name: str) -> None:
    document = load(EXAMPLES / name)
    svg = map_view(document.root, document.path, "svg").data
    png = map_view(document.root, document.path, "png").data
    assert png.startswith(b"\x89PNG") and len(png) > 10_000
    texts = " ".join("".join(t.itertext()) for t in parse(svg).iter(f"{SVG}text"))
    for actor in document.root.nodes[0].actors:
        assert actor.name in texts


def test_actor_boxes_sit_where_the_lane_positions_say() -> None:
    figure = drawn(EXAMPLES / "uis1-concrete.xmi")
    centre, length, width, heading = box_of(figure, "ego")
    # road 3, lane 1, s = 30: the south arm, northbound (docs/map.md)
    assert centre == pytest.approx([1.75, -39.0], abs=1e-6)
    assert (length, width) == pytest.approx((4.5, 1.8))  # a Car's default size
    assert heading == pytest.approx(math.pi / 2)
    centre, length, width, heading = box_of(figure, "bike")
    assert centre == pytest.approx([4.5, -24.0], abs=1e-6)  # east sidewalk of the south arm
    assert (length, width) == pytest.approx((1.8, 0.6))
    assert heading == pytest.approx(math.pi / 2)


def test_an_actors_own_size_and_world_heading_are_drawn(tmp_path: Path) -> None:
    document = load(EXAMPLES / "uis1-concrete.xmi")
    ego = document.root.nodes[0].actors[0]
    ego.length, ego.width = scm.Value(value=6.0), scm.Value(value=2.5)
    ego.startPosition = scm.WorldPosition(
        x=scm.Value(value=20.0), y=scm.Value(value=-1.75), h=scm.Value(value=math.pi)
    )
    figure = draw(build_scene(document.root, document.path))
    centre, length, width, heading = box_of(figure, "ego")
    assert centre == pytest.approx([20.0, -1.75])
    assert (length, width) == pytest.approx((6.0, 2.5))
    assert abs(heading) == pytest.approx(math.pi)


def test_targets_and_radii_of_uis1() -> None:
    figure = drawn(EXAMPLES / "uis1-concrete.xmi")
    star = figure.artists["target-TurnRight_1"]
    assert isinstance(star, Line2D)
    assert (star.get_xdata()[0], star.get_ydata()[0]) == (34.0, -1.75)
    route = figure.artists["route-TurnRight_1"]
    assert isinstance(route, Line2D)
    assert list(route.get_xdata()) == pytest.approx([1.75, 34.0])  # from the ego's start
    assert list(route.get_ydata()) == pytest.approx([-39.0, -1.75])
    location = figure.artists["circle-InLocationRadius_1"]
    assert isinstance(location, Circle)
    assert location.center == (34.0, -1.75) and location.radius == 3.0
    vehicle = figure.artists["circle-InVehicleRadius_1"]  # around its target actor, the ego
    assert isinstance(vehicle, Circle)
    assert vehicle.center == pytest.approx((1.75, -39.0)) and vehicle.radius == 12.0


def test_module_uses_are_drawn_with_the_values_the_use_gives() -> None:
    figure = drawn(EXAMPLES / "uis2-concrete.xmi")
    cross = figure.artists["target-CrossingManeuver_1.Cross_1"]
    assert isinstance(cross, Line2D)
    assert (cross.get_xdata()[0], cross.get_ydata()[0]) == (-10.0, 4.5)  # the use's overrides
    radius = figure.artists["circle-CrossingManeuver_1.InVehicleRadius_1"]
    assert isinstance(radius, Circle)
    # around the car (the trigger role), with the use's triggerRadius
    assert radius.center == pytest.approx((-1.75, 39.0)) and radius.radius == 15.0
    centre, _, _, heading = box_of(figure, "car")
    assert centre == pytest.approx([-1.75, 39.0]) and heading == pytest.approx(-math.pi / 2)


def test_the_crop_holds_every_actor_and_the_junction() -> None:
    for name in ("uis1-concrete.xmi", "uis2-logical.xmi", "overtaking-concrete.xmi"):
        figure = drawn(EXAMPLES / name)
        (x0, x1), (y0, y1) = figure.axes.get_xlim(), figure.axes.get_ylim()
        for actor in figure.scene.placed_actors():
            for x, y in actor.corners():
                assert x0 + 10 < x < x1 - 10 and y0 + 10 < y < y1 - 10, (name, actor.name)
        for jx0, jy0, jx1, jy1 in junction_boxes(figure.scene.road_map):
            assert x0 <= jx0 and jx1 <= x1 and y0 <= jy0 and jy1 <= y1
        assert x1 - x0 < 240 or y1 - y0 < 240  # not the whole map
    whole = drawn(EXAMPLES / "uis1-concrete.xmi", extent="map")
    assert whole.axes.get_xlim() == (-120.0, 120.0) and whole.axes.get_ylim() == (-120.0, 120.0)


def test_a_lane_range_is_a_shaded_stretch_of_the_lane() -> None:
    document = load(EXAMPLES / "uis1-logical.xmi")
    ego = document.root.nodes[0].actors[0]
    ego.startPosition.s = scm.Range(min=20.0, max=40.0)
    figure = draw(build_scene(document.root, document.path))
    area = figure.artists["range-ego"]
    assert isinstance(area, Polygon) and area.get_hatch() == "///"
    xy = area.get_xy()
    # lane 1 of the south arm (x 0 .. 3.5) from s = 20 (y = -29) to s = 40 (y = -49)
    assert xy[:, 0].min() == pytest.approx(0.0, abs=1e-6)
    assert xy[:, 0].max() == pytest.approx(3.5, abs=1e-6)
    assert xy[:, 1].min() == pytest.approx(-49.0) and xy[:, 1].max() == pytest.approx(-29.0)
    centre, *_ = box_of(figure, "ego")
    assert centre == pytest.approx([1.75, -39.0], abs=1e-6)  # the box at the middle


def test_world_ranges_and_ranged_radii_are_shaded() -> None:
    document = load(EXAMPLES / "uis1-logical.xmi")
    cross = next(n for n in document.root.nodes if n.name == "Cross_1")
    cross.destination.x = scm.Range(min=8.0, max=12.0)
    cross.destination.y = scm.UniformDistribution(min=4.0, max=5.0)
    figure = draw(build_scene(document.root, document.path))
    area = figure.artists["range-Cross_1"]
    assert isinstance(area, Polygon)
    xy = area.get_xy()
    assert (xy[:, 0].min(), xy[:, 0].max()) == (8.0, 12.0)
    assert (xy[:, 1].min(), xy[:, 1].max()) == (4.0, 5.0)
    ring = figure.artists["ring-InVehicleRadius_1"]  # radius Range 8 .. 16 in uis1-logical
    assert isinstance(ring, Wedge) and (ring.r, ring.width) == (16.0, 8.0)
    outer = figure.artists["circle-InVehicleRadius_1-2"]
    assert isinstance(outer, Circle) and outer.radius == 16.0


def test_a_town_or_no_map_is_a_clear_error(tmp_path: Path) -> None:
    document = load(EXAMPLES / "uis1-concrete.xmi")
    document.root.nodes[0].map = "Town03"
    with pytest.raises(MapViewError, match="simulator town.*OpenDRIVE") as caught:
        map_view(document.root, document.path)
    assert caught.value.exit_code == 2
    document.root.nodes[0].map = None
    with pytest.raises(MapViewError, match="names no map"):
        map_view(document.root, document.path)


def test_a_missing_map_file_is_a_map_error() -> None:
    document = load(EXAMPLES / "uis1-concrete.xmi")
    document.root.nodes[0].map = "../maps/nowhere.xodr"
    with pytest.raises(MapError, match="does not exist") as caught:
        map_view(document.root, document.path)
    assert caught.value.file is not None and "nowhere.xodr" in caught.value.file


def test_positions_off_the_map_are_left_out_with_a_note() -> None:
    document = load(EXAMPLES / "uis1-concrete.xmi")
    document.root.nodes[0].actors[1].startPosition.roadId = "99"
    figure = draw(build_scene(document.root, document.path))
    assert "actor-bike" not in figure.artists and "actor-ego" in figure.artists
    assert any("no road '99'" in note for note in figure.scene.notes)


def test_a_functional_scenario_draws_the_map_and_says_why_no_actors() -> None:
    figure = drawn(EXAMPLES / "uis1-functional.xmi")
    assert not figure.scene.placed_actors()
    assert figure.scene.notes[0] == "the actors have no positions: only the map is drawn"
    assert "note" in figure.artists and "lanes-driving-roads" in figure.artists


def test_svg_bytes_are_the_same_every_time() -> None:
    document = load(EXAMPLES / "uis2-logical.xmi")
    first = map_view(document.root, document.path, "svg").data
    assert map_view(document.root, document.path, "svg").data == first
    assert b"<dc:date>" not in first


def test_inline_svg_drops_the_page_wide_style_sheet() -> None:
    document = load(EXAMPLES / "uis1-concrete.xmi")
    svg = map_view(document.root, document.path, "svg").data
    assert b"<style" in svg
    inline = inline_svg(svg)
    assert inline.startswith("<svg") and "<style" not in inline and 'id="actor-ego"' in inline

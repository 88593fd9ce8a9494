"""`sceml render --view map` and the map view in `sceml report`, through click."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from sceml.cli.render import render
from sceml.cli.report import report

from .svgtools import parse


def test_render_map_view_writes_svg_and_png(examples_copy: Path, tmp_path: Path) -> None:
    scenario = str(examples_copy / "uis2-concrete.xmi")
    for suffix, magic in ((".svg", b"<?xml"), (".png", b"\x89PNG")):
        out = tmp_path / "out" / f"uis2-map{suffix}"
        result = CliRunner().invoke(render, [scenario, "--view", "map", "-o", str(out)])
        assert result.exit_code == 0, result.output
        assert out.read_bytes().startswith(magic)
    svg = parse((tmp_path / "out" / "uis2-map.svg").read_bytes())
    assert {"actor-ego", "actor-car", "actor-pedestrian"} <= {g.get("id") for g in svg.iter()}


def test_render_map_view_of_a_town_writes_nothing(examples_copy: Path, tmp_path: Path) -> None:
    scenario = examples_copy / "uis1-town.xmi"
    text = (examples_copy / "uis1-concrete.xmi").read_text()
    scenario.write_text(text.replace("../maps/intersection.xodr", "Town03"))
    out = tmp_path / "out.svg"
    result = CliRunner().invoke(render, [str(scenario), "--view", "map", "-o", str(out)])
    assert result.exit_code == 2
    assert "simulator town" in result.output and "OpenDRIVE" in result.output
    assert "Traceback" not in result.output and not out.exists()


def test_render_map_view_of_a_broken_map_names_its_line(
    examples_copy: Path, tmp_path: Path
) -> None:
    (examples_copy.parent / "maps" / "intersection.xodr").write_text("<OpenDRIVE>\n<road>\n")
    out = tmp_path / "out.png"
    result = CliRunner().invoke(
        render, [str(examples_copy / "uis1-concrete.xmi"), "--view", "map", "-o", str(out)]
    )
    assert result.exit_code == 2 and "intersection.xodr:" in result.output
    assert not out.exists()


def test_render_map_view_of_a_functional_scenario_says_there_are_no_positions(
    examples_copy: Path, tmp_path: Path
) -> None:
    out = tmp_path / "f.svg"
    result = CliRunner().invoke(
        render, [str(examples_copy / "uis1-functional.xmi"), "--view", "map", "-o", str(out)]
    )
    assert result.exit_code == 0 and out.exists()
    assert "the actors have no positions" in result.output


def test_map_view_of_a_library_is_a_usage_error(examples_copy: Path, tmp_path: Path) -> None:
    library = str(examples_copy / "library" / "sceml-library.xmi")
    result = CliRunner().invoke(render, [library, "--view", "map", "-o", str(tmp_path / "m.svg")])
    assert result.exit_code == 2 and "scenarios, not module libraries" in result.output


def test_report_holds_the_map_view(examples_copy: Path, tmp_path: Path) -> None:
    out = tmp_path / "r.html"
    result = CliRunner().invoke(report, [str(examples_copy / "uis2-logical.xmi"), "-o", str(out)])
    assert result.exit_code == 0, result.output
    html = out.read_text()
    figure = html[html.index('id="map-view"') :]
    assert figure.index('id="actor-pedestrian"') < figure.index("</div>")
    assert "<h2>Map view</h2>" in html


def test_report_without_a_readable_map_says_why(examples_copy: Path, tmp_path: Path) -> None:
    scenario = examples_copy / "uis1-town.xmi"
    text = (examples_copy / "uis1-concrete.xmi").read_text()
    scenario.write_text(text.replace("../maps/intersection.xodr", "Town03"))
    out = tmp_path / "r.html"
    result = CliRunner().invoke(report, [str(scenario), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output  # the town itself is validation's business
    html = out.read_text()
    assert "No map view: the scenario&#39;s map &#39;Town03&#39; is a simulator town" in html
    assert 'id="actor-ego"' not in html

"""`sceml render` and `sceml report` through click: formats, exit codes and atomic output."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from sceml.cli.render import render
from sceml.cli.report import report

from .svgtools import groups, parse

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_render_svg_png_pdf(tmp_path: Path) -> None:
    for suffix, magic in ((".svg", b"<?xml"), (".png", b"\x89PNG"), (".pdf", b"%PDF")):
        out = tmp_path / f"uis1{suffix}"
        result = CliRunner().invoke(render, [str(EXAMPLES / "uis1-logical.xmi"), "-o", str(out)])
        assert result.exit_code == 0, result.output
        assert out.read_bytes().startswith(magic)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["uis1.pdf", "uis1.png", "uis1.svg"]


def test_render_options_reach_the_diagram(tmp_path: Path) -> None:
    out = tmp_path / "uis2.svg"
    arguments = [str(EXAMPLES / "uis2-logical.xmi"), "-o", str(out), "--modules", "expanded"]
    assert CliRunner().invoke(render, [*arguments, "--legend"]).exit_code == 0
    svg = parse(out.read_bytes())
    assert groups(svg, "sceml-module") and groups(svg, "sceml-legend")
    assert CliRunner().invoke(render, [*arguments, "--view", "bt"]).exit_code == 0
    assert groups(parse(out.read_bytes()), "sceml-bt-parallel-all")


def test_unknown_suffix_is_a_usage_error(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        render, [str(EXAMPLES / "uis1-logical.xmi"), "-o", str(tmp_path / "x.gif")]
    )
    assert result.exit_code == 2 and ".svg, .png or .pdf" in result.output
    assert list(tmp_path.iterdir()) == []


def test_library_needs_a_module_name(tmp_path: Path) -> None:
    library = str(EXAMPLES / "library" / "sceml-library.xmi")
    out = str(tmp_path / "m.svg")
    result = CliRunner().invoke(render, [library, "-o", out])
    assert result.exit_code == 2 and "CrossingManeuver" in result.output
    assert (
        CliRunner().invoke(render, [library, "-o", out, "--module", "CrossingManeuver"]).exit_code
        == 0
    )


def test_unreadable_input_exits_2_without_traceback(tmp_path: Path) -> None:
    bad = tmp_path / "bad.xmi"
    bad.write_text("<not closed")
    result = CliRunner().invoke(render, [str(bad), "-o", str(tmp_path / "x.svg")])
    assert result.exit_code == 2 and "malformed XML" in result.output
    assert "Traceback" not in result.output


def test_report_writes_one_html_file(tmp_path: Path) -> None:
    out = tmp_path / "uis2.html"
    result = CliRunner().invoke(report, [str(EXAMPLES / "uis2-logical.xmi"), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output
    html = out.read_text(encoding="utf-8")
    assert "<svg" in html and "actor-table" in html and "parameter-table" in html
    assert "src=" not in html and 'href="http' not in html  # self-contained
    assert (
        CliRunner()
        .invoke(report, [str(EXAMPLES / "uis2-logical.xmi"), "-o", str(tmp_path / "r.svg")])
        .exit_code
        == 2
    )


def test_help_explains_the_options() -> None:
    text = CliRunner().invoke(render, ["--help"]).output
    for option in ("--output", "--view", "--modules", "--legend", "--module"):
        assert option in text

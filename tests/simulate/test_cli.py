"""`sceml simulate` and the preview figure of `sceml report`, through click's CliRunner."""

from __future__ import annotations

import csv
import json
from pathlib import Path

from click.testing import CliRunner
from conftest import EXAMPLES

from sceml.cli import cli


def test_simulate_writes_the_page_the_trajectories_and_the_summary(tmp_path: Path) -> None:
    page, table, report = tmp_path / "run.html", tmp_path / "t.csv", tmp_path / "s.json"
    result = CliRunner().invoke(
        cli,
        [
            "simulate",
            str(EXAMPLES / "uis1-concrete.xmi"),
            "-o",
            str(page),
            "--csv",
            str(table),
            "--json",
            str(report),
        ],
    )
    assert result.exit_code == 0, result.output
    assert "ended at" in result.output and "by the end node" in result.output
    html = page.read_text(encoding="utf-8")
    assert "not a vehicle-dynamics simulator" in html
    assert 'id="actor-ego"' in html and 'id="time-slider"' in html
    assert "http://" not in html.replace("http://www.w3.org/2000/svg", "")  # no network
    summary = json.loads(report.read_text(encoding="utf-8"))
    assert summary["end"]["reason"] == "end node"
    assert {m["actors"][0] for m in summary["metrics"]} == {"ego"}
    rows = list(csv.DictReader(table.read_text(encoding="utf-8").splitlines()))
    samples = round(summary["end"]["time"] / summary["step"]) + 1
    assert len(rows) == 2 * samples  # two actors, every sample
    assert rows[0] == {
        "time": "0.000",
        "actor": "ego",
        "x": "1.750",
        "y": "-39.000",
        "heading": "1.5708",
        "speed": "5.000",
    }


def test_simulate_refuses_a_logical_scenario_with_exit_2(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        cli, ["simulate", str(EXAMPLES / "uis1-logical.xmi"), "-o", str(tmp_path / "x.html")]
    )
    assert result.exit_code == 2
    assert "concrete" in result.output
    assert not (tmp_path / "x.html").exists()


def test_report_of_a_concrete_scenario_has_the_preview_run(tmp_path: Path) -> None:
    concrete, logical = tmp_path / "c.html", tmp_path / "l.html"
    runner = CliRunner()
    assert (
        runner.invoke(
            cli, ["report", str(EXAMPLES / "uis2-concrete.xmi"), "-o", str(concrete)]
        ).exit_code
        == 0
    )
    assert (
        runner.invoke(
            cli, ["report", str(EXAMPLES / "uis2-logical.xmi"), "-o", str(logical)]
        ).exit_code
        == 0
    )
    html = concrete.read_text(encoding="utf-8")
    assert 'id="preview-run"' in html and "CrossingManeuver_1.Cross_1" in html
    assert "ego – car: least distance" in html
    assert 'id="preview-run"' not in logical.read_text(encoding="utf-8")

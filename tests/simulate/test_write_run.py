"""A run's files as a library call (what `sceml simulate` writes): all of them or none."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from sceml.errors import SceMLError
from sceml.model.loading import load_scenario
from sceml.simulate import simulate
from sceml.simulate.outputs import CSV_COLUMNS, write_run

UIS1 = Path(__file__).resolve().parents[2] / "examples" / "uis1-concrete.xmi"


def test_the_page_csv_and_json_are_written_together(tmp_path: Path) -> None:
    scenario = load_scenario(UIS1).root
    run = simulate(scenario, UIS1)
    page, table, summary = tmp_path / "run.html", tmp_path / "run.csv", tmp_path / "run.json"
    assert write_run(run, scenario, UIS1, page, table, summary) == [page, table, summary]
    assert page.read_text().lstrip().lower().startswith("<!doctype html>")
    assert table.read_text().splitlines()[0] == ",".join(CSV_COLUMNS)
    assert json.loads(summary.read_text())["end"]["time"] == pytest.approx(run.end_time)


def test_one_file_that_cannot_be_written_leaves_none(tmp_path: Path) -> None:
    scenario = load_scenario(UIS1).root
    run = simulate(scenario, UIS1)
    blocked = tmp_path / "a-file"
    blocked.write_text("not a folder")
    with pytest.raises(SceMLError):
        write_run(run, scenario, UIS1, tmp_path / "run.html", blocked / "run.csv")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-file"]

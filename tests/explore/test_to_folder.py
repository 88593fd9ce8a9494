"""A search written to a folder as a library call (what `sceml explore` runs), without the CLI."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.cli.explore import explore_command
from sceml.errors import SceMLError
from sceml.explore import METRICS
from sceml.explore.to_folder import ExploreRequest, check_budget, explore_to_folder
from sceml.model.loading import load_scenario

UIS1 = Path(__file__).resolve().parents[2] / "examples" / "uis1-logical.xmi"


def test_the_outputs_and_what_they_hold(tmp_path: Path) -> None:
    out = tmp_path / "explored"
    heard: list[int] = []
    outcome = explore_to_folder(
        load_scenario(UIS1), UIS1, out, ExploreRequest(budget=4, top=1), progress=heard.append
    )
    assert sum(heard) == 4 and len(outcome.exploration.evaluations) == 4
    assert sorted(p.name for p in out.iterdir()) == [
        "parameter-space.png",
        "runs.csv",
        "uis1_critical_01.xmi",
        "uis1_critical_01.xosc",
    ]
    assert outcome.runs_csv == out / "runs.csv" and outcome.plot == out / "parameter-space.png"
    # A header and one row a run.
    assert len(outcome.runs_csv.read_text().splitlines()) == 5
    [critical] = outcome.critical
    assert critical.files == [out / "uis1_critical_01.xmi", out / "uis1_critical_01.xosc"]
    assert critical.problem is None
    assert critical.evaluation is outcome.exploration.ranked()[0]


def test_a_failed_search_leaves_no_folder(tmp_path: Path) -> None:
    out = tmp_path / "explored"
    concrete = UIS1.with_name("uis1-concrete.xmi")
    with pytest.raises(SceMLError, match="varies no parameter"):
        explore_to_folder(load_scenario(concrete), concrete, out, ExploreRequest(budget=4))
    assert not out.exists()


def test_a_budget_beyond_memory_is_refused_before_anything_runs() -> None:
    with pytest.raises(SceMLError, match="runs would take about .* of memory"):
        check_budget(load_scenario(UIS1), 10**15, 0.05)


def test_the_command_offers_the_metrics_the_search_knows() -> None:
    # The command names them itself so as not to import the preview before it runs.
    [metric] = [p for p in explore_command.params if p.name == "metric"]
    assert (
        sorted(metric.type.choices)
        == sorted(METRICS)
        == [  # type: ignore[attr-defined]
            "collision",
            "min-distance",
            "min-ttc",
            "pet",
        ]
    )

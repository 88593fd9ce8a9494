"""`explore` on the logical UIS1: it finds the collision the paper says UIS1 can end in."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import EXAMPLES

from sceml.cli import cli
from sceml.explore import ExploreError, explore
from sceml.model.loading import load_scenario
from sceml.simulate import simulate

UIS1 = EXAMPLES / "uis1-logical.xmi"


def test_explore_finds_collisions_of_ego_and_bike_that_simulate_again_as_collisions(
    tmp_path: Path,
) -> None:
    result = CliRunner().invoke(
        cli,
        [
            "explore",
            str(UIS1),
            "--metric",
            "collision",
            "--budget",
            "60",
            "--top",
            "3",
            "--seed",
            "4",
            "-o",
            str(tmp_path),
        ],
    )
    assert result.exit_code == 0, result.output
    rows = list(csv.DictReader((tmp_path / "runs.csv").read_text(encoding="utf-8").splitlines()))
    assert len(rows) == 60
    assert {"design", "refine"} == {row["phase"] for row in rows}
    hits = [row for row in rows if row["collision"] == "yes"]
    assert hits and all(row["colliding"] == "ego-bike" for row in hits)
    assert (tmp_path / "parameter-space.png").stat().st_size > 10_000
    for rank in (1, 2, 3):
        concrete = tmp_path / f"uis1_critical_{rank:02d}.xmi"
        assert concrete.with_suffix(".xosc").exists()
        document = load_scenario(concrete, allow=[UIS1.parent.parent / "maps"])
        run = simulate(document.root, concrete)  # the saved file, read back, on its map
        assert run.pair("ego", "bike").collision


def test_refinement_finds_more_collisions_than_the_design() -> None:
    scenario = load_scenario(UIS1).root
    found = explore(scenario, UIS1, metric="collision", budget=80, seed=2)
    share = {
        phase: sum(e.run is not None and e.run.collided for e in runs) / len(runs)
        for phase in ("design", "refine")
        if (runs := [e for e in found.evaluations if e.phase == phase])
    }
    assert share["refine"] > share["design"] > 0


def test_the_same_seed_gives_the_same_runs_and_another_seed_others() -> None:
    scenario = load_scenario(UIS1).root

    def runs(seed: int) -> list[tuple[tuple[float, ...], float]]:
        found = explore(scenario, UIS1, metric="min-ttc", budget=24, seed=seed)
        return [(e.values, e.score) for e in found.evaluations]

    assert runs(7) == runs(7)
    assert runs(7) != runs(8)


def test_a_concrete_scenario_has_nothing_to_explore() -> None:
    concrete = EXAMPLES / "uis1-concrete.xmi"
    with pytest.raises(ExploreError, match="varies no parameter"):
        explore(load_scenario(concrete).root, concrete, metric="pet", budget=10)

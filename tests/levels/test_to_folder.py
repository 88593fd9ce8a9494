"""Sampling into a folder as a library call (what `sceml sample` runs), without the CLI."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.levels.manifest import read_manifest
from sceml.levels.paths import LevelError
from sceml.levels.to_folder import (
    SampleRequest,
    blocking_problems,
    load_logical,
    plan_sampling,
    sample_to_folder,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
UIS1 = EXAMPLES / "uis1-logical.xmi"


def test_a_grid_run_writes_its_samples_and_manifest(tmp_path: Path) -> None:
    document = load_logical(UIS1)
    assert blocking_problems(document) == []
    planned = plan_sampling(document, SampleRequest(UIS1, "grid", None, 0, tmp_path, "xmi"))
    heard: list[int] = []
    outcome = sample_to_folder(planned, executor="local", progress=heard.append)
    # UIS1's grid: ego.initialSpeed 3..7 step 1 (5 levels) x radius 8..16 step 4 (3 levels).
    assert outcome.written == 15 and not outcome.skipped and outcome.failed == []
    assert outcome.files == 15 and sum(heard) == 15 and outcome.values == {}
    assert sorted(p.name for p in tmp_path.glob("*.xmi"))[:2] == [
        "uis1_00000.xmi",
        "uis1_00001.xmi",
    ]
    manifest = read_manifest(tmp_path)
    assert len(manifest["samples"]) == 15 and manifest["run"]["strategy"] == "grid"


def test_one_index_gives_its_values_and_no_manifest(tmp_path: Path) -> None:
    document = load_logical(UIS1)
    request = SampleRequest(UIS1, "grid", None, 0, tmp_path, "xmi", index=14)
    outcome = sample_to_folder(plan_sampling(document, request), executor="local")
    # The last grid point: both ranges at their maximum, the distributions (which the grid
    # does not vary) at their nominal value: the normal's mean, the uniform's middle.
    assert outcome.values == {
        "ego.initialSpeed": 7.0,
        "Accelerate_1.targetSpeed": 8.0,
        "InVehicleRadius_1.radius": 16.0,
        "Accelerate_2.targetSpeed": 4.5,
    }
    assert [p.name for p in tmp_path.iterdir()] == ["uis1_00014.xmi"]


def test_only_logical_scenarios_are_sampled() -> None:
    with pytest.raises(LevelError, match="this one is concrete") as refused:
        load_logical(EXAMPLES / "uis1-concrete.xmi")
    assert refused.value.file == str(EXAMPLES / "uis1-concrete.xmi")

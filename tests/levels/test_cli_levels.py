"""The concretize, promote, sample and export-distribution commands, run through CliRunner."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from lxml import etree

import scemlmodel as scm
from sceml.cli.concretize import concretize
from sceml.cli.export_logical import export_distribution_command
from sceml.cli.promote import promote
from sceml.cli.sample import sample
from sceml.levels.manifest import read_manifest
from sceml.model.compare import differences
from sceml.model.loading import load_scenario
from sceml.xosc import schema

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

UIS2_VALUES = [
    "ego.Accelerate_1.targetSpeed=7",
    "ego.initialSpeed=5",
    "InLocationRadius_2.radius=4",
    "DriveDistance_1.speed=10",
    "CrossingManeuver_1.triggerRadius=15",
    "CrossingManeuver_1.crossingSpeed=1.5",
]


def _invoke(command, args: list[str]):  # type: ignore[no-untyped-def]
    return CliRunner().invoke(command, [str(a) for a in args], catch_exceptions=False)


def test_concretize_reproduces_the_concrete_example(examples_copy: Path, tmp_path: Path) -> None:
    out = examples_copy / "uis2-mine.xmi"
    args = [examples_copy / "uis2-logical.xmi", "-o", out]
    for value in UIS2_VALUES:
        args += ["--set", value]
    result = _invoke(concretize, args)
    assert result.exit_code == 0, result.output
    mine = load_scenario(out).root
    reference = load_scenario(examples_copy / "uis2-concrete.xmi").root
    assert differences(mine, reference) == []


def test_concretize_rejects_unknown_paths_with_the_valid_ones(tmp_path: Path) -> None:
    result = _invoke(
        concretize,
        [EXAMPLES / "uis2-logical.xmi", "--set", "ego.topSpeed=3", "-o", tmp_path / "x.xmi"],
    )
    assert result.exit_code == 2
    assert "unknown parameter path 'ego.topSpeed'" in result.output
    assert (
        "ego.initialSpeed" in result.output and "CrossingManeuver_1.crossingSpeed" in result.output
    )
    assert not (tmp_path / "x.xmi").exists()


def test_concretize_names_what_is_left_open(tmp_path: Path) -> None:
    result = _invoke(
        concretize,
        [EXAMPLES / "uis2-logical.xmi", "--set", "ego.initialSpeed=4", "-o", tmp_path / "x.xmi"],
    )
    assert result.exit_code == 1
    assert "DriveDistance_1.speed ({8, 10, 12} m/s)" in result.output


def test_promote_uis1_functional_gives_the_logical_example(examples_copy: Path) -> None:
    out = examples_copy / "uis1-promoted.xmi"
    result = _invoke(
        promote,
        [
            examples_copy / "uis1-functional.xmi",
            "--ranges",
            EXAMPLES / "uis1-ranges.yaml",
            "-o",
            out,
        ],
    )
    assert result.exit_code == 0, result.output
    promoted = load_scenario(out).root
    assert differences(promoted, load_scenario(examples_copy / "uis1-logical.xmi").root) == []


def test_promote_reports_what_the_ranges_file_misses(tmp_path: Path) -> None:
    ranges = tmp_path / "ranges.json"
    ranges.write_text(json.dumps({"ego.initialSpeed": {"min": 3, "max": 7, "step": 1}}))
    result = _invoke(
        promote, [EXAMPLES / "uis1-functional.xmi", "--ranges", ranges, "-o", tmp_path / "o.xmi"]
    )
    assert result.exit_code == 1
    assert "Accelerate_1.targetSpeed" in result.output and "ego.startPosition" in result.output


def test_promote_refuses_a_malformed_ranges_file(tmp_path: Path) -> None:
    ranges = tmp_path / "ranges.yaml"
    ranges.write_text("ego.initialSpeed: {min: 3, max: [\n")
    result = _invoke(
        promote, [EXAMPLES / "uis1-functional.xmi", "--ranges", ranges, "-o", tmp_path / "o.xmi"]
    )
    assert result.exit_code == 2
    assert "malformed ranges file" in result.output


def _numbers_in(xosc: Path) -> dict[str, float]:
    """The sampled numbers as the .xosc holds them, read by XPath (independently of SceML)."""
    root = etree.parse(str(xosc)).getroot()

    def one(xpath: str) -> float:
        (value,) = root.xpath(xpath)
        return float(value)

    return {
        "ego.initialSpeed": one("//Private[@entityRef='ego']//AbsoluteTargetSpeed/@value"),
        "Accelerate_1.targetSpeed": one(
            "//Event[@name='Accelerate_1']//AbsoluteTargetSpeed/@value"
        ),
        "DriveDistance_1.speed": one(
            "//Event[@name='DriveDistance_1']//AbsoluteTargetSpeed/@value"
        ),
        "CrossingManeuver_1.triggerRadius": one("//RelativeDistanceCondition/@value"),
    }


@pytest.mark.parametrize("workers", ["1", "2"])
def test_sample_random_writes_valid_files_and_a_true_manifest(tmp_path: Path, workers: str) -> None:
    out = tmp_path / "out"
    result = _invoke(
        sample,
        [
            EXAMPLES / "uis2-logical.xmi",
            "--strategy",
            "random",
            "--n",
            "12",
            "--seed",
            "4",
            "-o",
            out,
            "--workers",
            workers,
            "--format",
            "both",
        ],
    )
    assert result.exit_code == 0, result.output
    assert re.search(r"12 written, 0 skipped, [\d.]+ s, \d+ files/s", result.output)
    manifest = read_manifest(out)
    assert [s["index"] for s in manifest["samples"]] == list(range(12))
    for row in manifest["samples"][:4]:
        xosc_name, xmi_name = row["files"]
        xosc = out / xosc_name
        assert schema.validate_file(xosc) == []
        for path, value in _numbers_in(xosc).items():
            assert value == row["values"][path]
        concrete = load_scenario(out / xmi_name).root
        assert concrete.nodes[0].level == scm.AbstractionLevel.concrete
        assert concrete.nodes[0].actors[0].initialSpeed.value == row["values"]["ego.initialSpeed"]
        override = {o.parameter: o.value.value for o in concrete.nodes[-1].overrides}
        assert override["crossingSpeed"] == row["values"]["CrossingManeuver_1.crossingSpeed"]
    csv_lines = (out / "manifest.csv").read_text().splitlines()
    assert len(csv_lines) == 13 and csv_lines[0].startswith(
        "index,status,reason,files,ego.initialSpeed"
    )


def test_sample_grid_writes_the_product_of_level_counts(tmp_path: Path) -> None:
    out = tmp_path / "grid"
    result = _invoke(
        sample, [EXAMPLES / "uis1-logical.xmi", "--strategy", "grid", "-o", out, "--workers", "2"]
    )
    assert result.exit_code == 0, result.output
    # UIS1: ego.initialSpeed 5 levels x InVehicleRadius_1.radius 3 levels.
    assert len(list(out.glob("*.xosc"))) == 15
    assert "15 written, 0 skipped" in result.output


def test_sample_index_reproduces_one_sample(tmp_path: Path) -> None:
    common = [EXAMPLES / "uis2-logical.xmi", "--strategy", "lhs", "--n", "20", "--seed", "8"]
    assert _invoke(sample, [*common, "-o", tmp_path / "all", "--workers", "1"]).exit_code == 0
    again = _invoke(sample, [*common, "--index", "13", "-o", tmp_path / "one"])
    assert again.exit_code == 0, again.output
    assert (tmp_path / "one" / "uis2_00013.xosc").read_bytes() == (
        tmp_path / "all" / "uis2_00013.xosc"
    ).read_bytes()
    refused = CliRunner().invoke(
        sample,
        [
            str(EXAMPLES / "uis2-logical.xmi"),
            "--strategy",
            "lhs",
            "--index",
            "3",
            "-o",
            str(tmp_path / "x"),
        ],
    )
    assert refused.exit_code == 2 and "--n" in refused.output


def test_sample_refuses_a_functional_scenario(tmp_path: Path) -> None:
    result = _invoke(sample, [EXAMPLES / "uis2-functional.xmi", "-o", tmp_path / "f"])
    assert result.exit_code == 1 and "this one is functional" in result.output


def test_export_distribution_refuses_1_0(tmp_path: Path) -> None:
    result = _invoke(
        export_distribution_command,
        [EXAMPLES / "uis2-logical.xmi", "-o", tmp_path, "--osc-version", "1.0"],
    )
    # A usage error (issue 14): the option only offers the versions that have distributions.
    assert result.exit_code == 2 and "'1.0' is not one of '1.1', '1.2', '1.3'" in result.output
    assert list(tmp_path.iterdir()) == []

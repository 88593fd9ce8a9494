"""`sceml info` and the CLI's general behaviour."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

import scemlmodel as scm
from sceml import __version__
from sceml.cli import cli
from sceml.model.saving import save

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_version() -> None:
    result = CliRunner().invoke(cli, ["--version"])
    assert result.exit_code == 0 and __version__ in result.output


def test_info_on_uis2_concrete_lists_actors_module_use_and_level() -> None:
    result = CliRunner().invoke(cli, ["info", str(EXAMPLES / "uis2-concrete.xmi")])
    assert result.exit_code == 0, result.output
    assert "level: concrete" in result.output
    for line in ("ego: Car (ego)", "car: Car", "pedestrian: Pedestrian"):
        assert line in result.output
    assert "CrossingManeuver_1: CrossingManeuver from library/sceml-library.xmi" in result.output
    assert "crosser=pedestrian, trigger=car" in result.output


def test_info_json() -> None:
    result = CliRunner().invoke(cli, ["info", "--json", str(EXAMPLES / "uis1-logical.xmi")])
    summary = json.loads(result.output)
    assert summary["level"] == "logical"
    assert summary["node_counts"] == {
        "EndNode": 1,
        "RootNode": 1,
        "condition": 3,
        "lateral": 2,
        "longitudinal": 2,
    }


def test_info_on_library() -> None:
    result = CliRunner().invoke(cli, ["info", str(EXAMPLES / "library" / "sceml-library.xmi")])
    assert result.exit_code == 0 and "CrossingManeuver" in result.output


def test_unreadable_input_exits_2_without_traceback(tmp_path: Path) -> None:
    bad = tmp_path / "broken.xmi"
    bad.write_text("<not closed")
    result = CliRunner().invoke(cli, ["info", str(bad)])
    assert result.exit_code == 2
    assert f"{bad}:1: malformed XML" in result.output
    assert "Traceback" not in result.output


def test_help_explains_every_command() -> None:
    result = CliRunner().invoke(cli, ["--help"])
    assert result.exit_code == 0
    for command in ("info", "dev"):
        assert command in result.output


def test_info_on_a_scenario_without_a_root_node_shows_no_level(tmp_path: Path) -> None:
    file = tmp_path / "rootless.xmi"
    save(scm.Scenario(), file)
    result = CliRunner().invoke(cli, ["info", str(file)])
    assert result.exit_code == 0, result.output
    assert "  level: ?\n" in result.output  # as the diagrams and sample show a missing level
    as_json = CliRunner().invoke(cli, ["info", "--json", str(file)])
    assert json.loads(as_json.output)["level"] is None

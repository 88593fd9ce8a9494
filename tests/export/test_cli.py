"""`sceml export` and `sceml check-xosc` through click's test runner."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from click.testing import CliRunner

from sceml.cli.check_xosc import check_xosc
from sceml.cli.export import export
from sceml.xosc import schema

GOLDEN = Path(__file__).resolve().parent / "golden"


def test_export_writes_a_valid_file_referring_to_the_map(
    examples_copy: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out" / "uis1.xosc"
    result = CliRunner().invoke(
        export, [str(examples_copy / "uis1-concrete.xmi"), "-o", str(out), "--osc-version", "1.2"]
    )
    assert result.exit_code == 0, result.output
    tree = schema.parse_file(out)
    assert schema.validate_tree(tree) == []
    logic = tree.getroot().find("RoadNetwork/LogicFile").get("filepath")
    assert (out.parent / logic).resolve() == (examples_copy.parent / "maps" / "intersection.xodr")


def test_export_date_option_sets_the_header(examples_copy: Path, tmp_path: Path) -> None:
    out = tmp_path / "uis1.xosc"
    args = [str(examples_copy / "uis1-concrete.xmi"), "-o", str(out), "--date", "2030-05-06"]
    assert CliRunner().invoke(export, args).exit_code == 0
    header = schema.parse_file(out).getroot().find("FileHeader")
    assert header.get("date") == "2030-05-06T00:00:00"


def test_export_refuses_a_logical_scenario_with_exit_1(examples_copy: Path, tmp_path: Path) -> None:
    out = tmp_path / "uis2.xosc"
    result = CliRunner().invoke(export, [str(examples_copy / "uis2-logical.xmi"), "-o", str(out)])
    assert result.exit_code == 1
    assert "SCEML-X001" in result.output and "Traceback" not in result.output
    assert not out.exists()


def test_export_carla_defaults_to_1_0_on_the_scenarios_own_map(
    examples_copy: Path, tmp_path: Path
) -> None:
    out = tmp_path / "carla.xosc"
    args = [str(examples_copy / "uis2-concrete.xmi"), "-o", str(out), "--profile", "carla"]
    done = CliRunner().invoke(export, args)
    assert done.exit_code == 0, done.output
    tree = schema.parse_file(out)
    assert schema.declared_version(tree) == "1.0"
    logic = tree.find("RoadNetwork/LogicFile").get("filepath")
    assert logic.endswith("maps/intersection.xodr")
    assert (out.parent / logic).resolve() == (
        examples_copy.parent / "maps/intersection.xodr"
    ).resolve()
    town = CliRunner().invoke(export, [*args, "--town", "Town03"])
    assert town.exit_code == 0, town.output
    assert schema.parse_file(out).find("RoadNetwork/LogicFile").get("filepath") == "Town03"


def test_export_missing_file_is_a_usage_error(tmp_path: Path) -> None:
    result = CliRunner().invoke(
        export, [str(tmp_path / "nope.xmi"), "-o", str(tmp_path / "o.xosc")]
    )
    assert result.exit_code == 2


def test_check_xosc_passes_goldens_and_reports_formats(tmp_path: Path) -> None:
    files = [str(GOLDEN / "uis1-1.0-generic.xosc"), str(GOLDEN / "uis2-1.3-generic.xosc")]
    text = CliRunner().invoke(check_xosc, files)
    assert text.exit_code == 0, text.output
    assert "XOSC-QC-SKIPPED" in text.output  # 1.0 gets the XSD only
    report = CliRunner().invoke(check_xosc, [*files, "--format", "json"])
    data = json.loads(report.output)
    assert data["tool"] == "sceml check-xosc" and data["summary"]["errors"] == 0
    junit = CliRunner().invoke(check_xosc, [*files, "--format", "junit"])
    assert junit.exit_code == 0 and "<testsuite" in junit.output


def test_check_xosc_reports_schema_errors_with_exit_1(tmp_path: Path) -> None:
    broken = tmp_path / "broken.xosc"
    shutil.copy(GOLDEN / "uis1-1.2-generic.xosc", broken)
    broken.write_text(
        broken.read_text(encoding="utf-8").replace("<CatalogLocations/>", ""), encoding="utf-8"
    )
    result = CliRunner().invoke(check_xosc, [str(broken)])
    assert result.exit_code == 1
    assert "XOSC-XSD" in result.output


def test_check_xosc_unreadable_file_exits_2(tmp_path: Path) -> None:
    bad = tmp_path / "bad.xosc"
    bad.write_text("<OpenSCENARIO>", encoding="utf-8")
    result = CliRunner().invoke(check_xosc, [str(bad)])
    assert result.exit_code == 2


def test_export_places_problems_of_a_flattened_module_at_the_uses_line(
    examples_copy: Path, tmp_path: Path
) -> None:
    source = examples_copy / "overtaking-concrete.xmi"
    args = [str(source), "-o", str(tmp_path / "o.xosc"), "--profile", "carla", "--town", "T"]
    result = CliRunner().invoke(export, args)
    assert result.exit_code == 1
    lines = source.read_text().splitlines()
    use_line = next(i for i, text in enumerate(lines, 1) if 'name="Overtaking_1"' in text)
    inner = "(Overtaking_1.PassVehicle_1.ChangeLaneRight_1.TimeElapsed_1)"
    assert f"{source}:{use_line}: error[SCEML-E003] TimeElapsed cannot" in result.output
    assert inner in result.output

"""`sceml migrate` and the notice every command gives for a file of an older release."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from metamodel_releases import CURRENT, HISTORY_10

from sceml.cli import cli


@pytest.fixture
def old_examples(tmp_path: Path) -> Path:
    shutil.copytree(HISTORY_10 / "examples", tmp_path / "examples")
    shutil.copytree(HISTORY_10 / "maps", tmp_path / "maps")
    (tmp_path / ".sceml-root").touch()  # one project, so the examples may read ../maps
    return tmp_path / "examples"


def invoke(*args: str | Path) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, [str(a) for a in args])
    return result.exit_code, result.stdout, result.stderr


def test_other_commands_read_old_files_with_a_notice(old_examples: Path) -> None:
    status, out, err = invoke("info", old_examples / "uis2-concrete.xmi")
    assert status == 0 and "scenario 'UIS2'" in out
    assert f"uis2-concrete.xmi: saved with metamodel release 1.0; read as release {CURRENT}" in err
    assert "sceml migrate" in err


def test_validate_warns_and_strict_makes_it_an_error(old_examples: Path) -> None:
    status, out, _ = invoke("validate", old_examples / "uis2-concrete.xmi")
    assert status == 0
    assert out.count("warning[SCEML-V001]") == 2  # the scenario and the library it uses
    status, out, _ = invoke("validate", "--strict", old_examples / "uis2-concrete.xmi")
    assert status == 1
    status, out, _ = invoke("validate", "--format", "json", old_examples / "uis1-concrete.xmi")
    codes = [d["code"] for f in json.loads(out)["files"] for d in f["diagnostics"]]
    assert "SCEML-V001" in codes


def test_migrate_in_place_with_backup(old_examples: Path) -> None:
    scenario = old_examples / "uis1-concrete.xmi"
    original = scenario.read_bytes()
    status, out, _ = invoke("migrate", "--in-place", "--backup", scenario)
    assert status == 0
    assert f"release 1.0 -> {CURRENT}, 0 change(s)" in out
    assert (old_examples / "uis1-concrete.xmi.1.0.bak").read_bytes() == original
    assert f"metamodel/{CURRENT}".encode() in scenario.read_bytes()
    status, out, _ = invoke("migrate", "--in-place", scenario)
    assert status == 0 and "already of the current metamodel release; left as it is" in out


def test_migrate_several_files_into_a_folder_as_json(old_examples: Path, tmp_path: Path) -> None:
    files = [old_examples / "uis1-functional.xmi", old_examples / "uis2-functional.xmi"]
    status, out, _ = invoke("migrate", *files, "-o", tmp_path / "out", "--format", "json")
    assert status == 0
    rows = json.loads(out)
    assert [Path(r["written"]).name for r in rows] == ["uis1-functional.xmi", "uis2-functional.xmi"]
    assert all(r["migration"]["from"] == "1.0" and r["migration"]["to"] == CURRENT for r in rows)
    assert files[0].read_bytes().count(b"metamodel/1.0") == 1  # the originals are untouched


def test_migrate_needs_one_destination(old_examples: Path) -> None:
    status, _, err = invoke("migrate", old_examples / "uis1-concrete.xmi")
    assert status == 2 and "either -o/--output or --in-place" in err
    status, _, err = invoke(
        "migrate", "--backup", "-o", "x.xmi", old_examples / "uis1-concrete.xmi"
    )
    assert status == 2 and "--backup goes with --in-place" in err


def test_migrate_reports_an_unreadable_file(tmp_path: Path) -> None:
    bad = tmp_path / "bad.xmi"
    bad.write_text("<not xml")
    status, _, err = invoke("migrate", "--in-place", bad)
    assert status == 2 and "bad.xmi:1: malformed XML" in err

"""Tests for sceml.xosc.qualitychecker: running ASAM's OpenSCENARIO XML checker bundle."""

from __future__ import annotations

import logging
import os
import tempfile
from pathlib import Path

import pytest
from lxml import etree

from sceml.xosc.qualitychecker import (
    CheckerStatus,
    QualityIssue,
    QualityReport,
    run_quality_checker,
)
from sceml.xosc.schema import UnsafeXMLError

DATA = Path(__file__).parent / "data"
SCHEMA_CHECKER = "check_asam_xosc_xml_valid_schema"
UNIQUE_NAMES_CHECKER = "check_asam_xosc_reference_control_unique_element_names_on_same_level"
UNIQUE_NAMES_RULE = "asam.net:xosc:1.2.0:reference_control.unique_element_names_on_same_level"


@pytest.mark.parametrize("name", ["minimal_1_2.xosc", "minimal_1_3.xosc"])
def test_valid_1_2_and_1_3_files_have_no_issues(name: str) -> None:
    report = run_quality_checker(DATA / name)
    assert isinstance(report, QualityReport)
    assert report.issues == ()
    assert report.ok
    assert not report.skipped_below_1_2
    assert report.checker_statuses[SCHEMA_CHECKER].status == "completed"
    # The reference checks really ran (only the OpenDRIVE-dependent one may skip: the
    # fixture's straight_road.xodr deliberately does not exist).
    statuses = report.checker_statuses.values()
    assert sum(s.status == "completed" for s in statuses) >= 15
    assert all(isinstance(s, CheckerStatus) for s in statuses)


def test_duplicate_names_are_reported() -> None:
    report = run_quality_checker(DATA / "qc_duplicate_names_1_2.xosc")
    assert not report.ok
    (issue,) = [i for i in report.issues if i.rule_uid == UNIQUE_NAMES_RULE]
    assert isinstance(issue, QualityIssue)
    assert issue.level == "error"
    assert issue.xpath == "/OpenSCENARIO/Entities/ScenarioObject[2]"
    assert "Ego" in issue.message
    assert issue.checker_id == UNIQUE_NAMES_CHECKER


def test_schema_violation_is_reported_with_line() -> None:
    report = run_quality_checker(DATA / "invalid_missing_attribute_1_2.xosc")
    (issue,) = report.issues
    assert issue.rule_uid == "asam.net:xosc:1.0.0:xml.valid_schema"
    assert issue.line == 13
    assert "vehicleCategory" in issue.message
    # Later checks depend on a schema-valid file, so the bundle skips them.
    unique = report.checker_statuses[UNIQUE_NAMES_CHECKER]
    assert unique.status == "skipped" and "Preconditions" in unique.summary
    assert not report.skipped_below_1_2


@pytest.mark.parametrize(
    ("name", "version"), [("minimal_1_0.xosc", "1.0"), ("minimal_1_1.xosc", "1.1")]
)
def test_files_below_1_2_report_checks_as_skipped(name: str, version: str) -> None:
    report = run_quality_checker(DATA / name)
    assert report.version == version
    assert report.skipped_below_1_2
    assert report.ok  # skipping is by design, not a failure
    assert report.checker_statuses[SCHEMA_CHECKER].status == "completed"
    for status in report.checker_statuses.values():
        if any(":1.2.0:" in uid for uid in status.rule_uids):
            assert status.status == "skipped"
            assert "lower than definition setting" in status.summary
    assert len(report.skipped_checkers) == 12


def test_malformed_file_is_reported_by_the_bundle(tmp_path: Path) -> None:
    bad = tmp_path / "broken.xosc"
    bad.write_text("<OpenSCENARIO>\n  <FileHeader>\n</OpenSCENARIO>\n", encoding="utf-8")
    report = run_quality_checker(bad)
    assert report.version is None and not report.skipped_below_1_2
    (issue,) = report.issues
    assert issue.rule_uid.endswith("xml.valid_xml_document")
    assert issue.line == 3


@pytest.mark.parametrize("name", ["billion_laughs.xosc", "xxe.xosc"])
def test_dtd_documents_are_refused_before_the_bundle_sees_them(name: str) -> None:
    with pytest.raises(UnsafeXMLError):
        run_quality_checker(DATA / name)


def test_hostile_logic_file_is_refused(tmp_path: Path) -> None:
    (tmp_path / "straight_road.xodr").write_text(
        '<?xml version="1.0"?>\n<!DOCTYPE OpenDRIVE [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n'
        "<OpenDRIVE>&x;</OpenDRIVE>\n"
    )
    xosc = tmp_path / "scenario.xosc"
    xosc.write_bytes((DATA / "minimal_1_2.xosc").read_bytes())
    with pytest.raises(UnsafeXMLError) as info:
        run_quality_checker(xosc)
    assert info.value.file is not None and info.value.file.endswith("straight_road.xodr")


def test_missing_file_raises() -> None:
    with pytest.raises(FileNotFoundError):
        run_quality_checker(DATA / "does_not_exist.xosc")


def test_in_process_run_leaves_logging_and_cwd_alone(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    caplog: pytest.LogCaptureFixture,
    capfd: pytest.CaptureFixture[str],
) -> None:
    monkeypatch.chdir(tmp_path)
    caplog.set_level(logging.DEBUG)
    root = logging.getLogger()
    handlers, level = list(root.handlers), root.level
    report = run_quality_checker(DATA / "qc_duplicate_names_1_2.xosc")
    assert report.issues
    assert Path.cwd() == tmp_path  # the bundle chdirs to resolve LogicFile; we restore
    assert root.handlers == handlers and root.level == level
    assert not root.filters
    assert caplog.records == []
    out, err = capfd.readouterr()
    assert out == "" and err == ""


def test_relative_path_works_from_another_cwd(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(DATA)
    report = run_quality_checker("minimal_1_3.xosc")
    assert report.ok and report.path == DATA / "minimal_1_3.xosc"


def test_in_process_result_file(tmp_path: Path) -> None:
    target = tmp_path / "out.xqar"
    report = run_quality_checker(DATA / "qc_duplicate_names_1_2.xosc", result_file=target)
    assert len(report.issues) == 1
    assert etree.parse(str(target)).getroot().tag == "CheckerResults"


def test_subprocess_mode_matches_in_process_and_cleans_up(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))
    keep = tmp_path / "kept.xqar"
    path = DATA / "qc_duplicate_names_1_2.xosc"
    sub = run_quality_checker(path, in_process=False, result_file=keep)
    inproc = run_quality_checker(path)
    assert sub.issues == inproc.issues
    assert {k: v.status for k, v in sub.checker_statuses.items()} == {
        k: v.status for k, v in inproc.checker_statuses.items()
    }
    assert keep.is_file()
    assert list(scratch.iterdir()) == []  # config + .xqar temp dir removed
    assert not any(p.suffix == ".xqar" for p in Path(os.getcwd()).iterdir())


def test_fresh_process_gets_no_logging_side_effects() -> None:
    # In a fresh interpreter the root logger has no handlers, so the bundle's import-time
    # basicConfig() and logging.info() calls would install a stderr handler.
    import subprocess
    import sys

    import sceml

    code = (
        "import logging, sys\n"
        "from sceml.xosc.qualitychecker import run_quality_checker\n"
        "report = run_quality_checker(sys.argv[1])\n"
        "root = logging.getLogger()\n"
        "assert report.issues and root.handlers == [] and root.level == logging.WARNING\n"
    )
    env = dict(os.environ, PYTHONPATH=str(Path(sceml.__file__).resolve().parent.parent))
    proc = subprocess.run(
        [sys.executable, "-c", code, str(DATA / "qc_duplicate_names_1_2.xosc")],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == "" and proc.stderr == ""


def test_bundle_crash_becomes_quality_checker_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from sceml.xosc import qualitychecker

    def boom(config: object, result: object) -> None:
        os.chdir(tmp_path)  # the real bundle may leave the cwd changed when it raises
        raise ValueError("bundle exploded")

    before = Path.cwd()
    monkeypatch.setattr(qualitychecker._bundle(), "run_checks", boom)
    with pytest.raises(qualitychecker.QualityCheckerError, match="bundle exploded") as info:
        run_quality_checker(DATA / "minimal_1_3.xosc")
    assert info.value.file == str(DATA / "minimal_1_3.xosc")
    assert Path.cwd() == before

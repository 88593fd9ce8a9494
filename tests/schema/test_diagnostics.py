"""XSD and Quality Checker findings come out of the library as Diagnostics, not CLI-made rows."""

from __future__ import annotations

from pathlib import Path

from sceml.diagnostics import Severity
from sceml.xosc.check import check_file
from sceml.xosc.qualitychecker import QualityIssue, quality_diagnostics

DATA = Path(__file__).parent / "data"


def test_an_xsd_violation_is_an_error_diagnostic_with_line_and_path() -> None:
    path = DATA / "invalid_missing_attribute_1_2.xosc"
    report = check_file(path, quality=False)
    assert report.unreadable is None and report.diagnostics
    first = report.diagnostics[0]
    assert (first.severity, first.code, first.file) == (Severity.ERROR, "XOSC-XSD", str(path))
    assert first.line and first.path and first.message.startswith("OpenSCENARIO 1.2 XSD: ")


def test_quality_checker_levels_map_to_severities() -> None:
    issue = QualityIssue("asam.net:xosc:1.0.0:rule", "checker", "warning", "odd", 7, None, "/X")
    diagnostic = issue.diagnostic("f.xosc")
    assert (diagnostic.severity, diagnostic.code, diagnostic.line) == (
        Severity.WARNING,
        "asam.net:xosc:1.0.0:rule",
        7,
    )
    assert QualityIssue("r", "c", "fatal?", "m").diagnostic().severity is Severity.ERROR


def test_before_1_2_the_checker_says_it_did_not_run() -> None:
    [skipped] = quality_diagnostics(DATA / "minimal_1_0.xosc", "1.0")
    assert (skipped.severity, skipped.code) == (Severity.INFO, "XOSC-QC-SKIPPED")


def test_an_unsafe_file_is_unreadable_not_raised() -> None:
    report = check_file(DATA / "xxe.xosc")
    assert report.unreadable and not report.diagnostics


def test_the_checked_versions_come_from_the_one_versions_list() -> None:
    from sceml.xosc import qualitychecker, schema

    assert set(qualitychecker.CHECKED_VERSIONS) < set(schema.SUPPORTED_VERSIONS)
    assert (
        tuple(v for v in schema.SUPPORTED_VERSIONS if v not in ("1.0", "1.1"))
        == qualitychecker.CHECKED_VERSIONS
    )


def test_the_quality_checker_is_not_run_on_files_above_the_limit() -> None:
    # ASAM's bundle took 144 s on a 20 MB file (issue 26): above the limit it is left out, said.
    export = Path(__file__).parents[1] / "export" / "golden" / "uis1-1.3-generic.xosc"
    assert check_file(export).diagnostics == []  # the checker ran and found nothing
    limited = check_file(export, quality_max_bytes=100)
    [skipped] = limited.diagnostics
    assert (skipped.severity, skipped.code) == (Severity.INFO, "XOSC-QC-SKIPPED")
    assert (
        "Quality Checker was not run" in skipped.message and "--quality-max-mb" in skipped.message
    )

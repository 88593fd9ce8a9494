"""Diagnostics of many files as text, JSON or JUnit XML, and the exit code they amount to.

Independent of where diagnostics come from (validation, XSD checks): it only reads Diagnostic
objects. The JSON shape is documented in docs/validation-json.md.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from lxml import etree

from .diagnostics import Diagnostic, Severity

#: Version of the JSON shape; bumped when a field changes meaning or disappears.
JSON_SCHEMA_VERSION = 1


@dataclass
class FileReport:
    """What one input file gave: its diagnostics, or why it could not be read at all."""

    file: str
    diagnostics: list[Diagnostic] = field(default_factory=list)
    unreadable: str | None = None

    def count(self, severity: Severity) -> int:
        """How many diagnostics of one severity."""
        return sum(1 for d in self.diagnostics if d.severity is severity)

    def failures(self, strict: bool = False) -> list[Diagnostic]:
        """The diagnostics that fail the file: errors, and warnings too when strict."""
        worst = Severity.WARNING if strict else Severity.ERROR
        return [d for d in self.diagnostics if d.severity >= worst]


def exit_code(reports: Sequence[FileReport], strict: bool = False) -> int:
    """0 when clean, 1 when any file has errors (or warnings, if strict), 2 when one is unreadable."""
    if any(report.unreadable is not None for report in reports):
        return 2
    return 1 if any(report.failures(strict) for report in reports) else 0


def _line(diagnostic: Diagnostic, file: str) -> str:
    # Diagnostic's own text form, placed in the report's file when it names none itself.
    return str(replace(diagnostic, file=diagnostic.file or file))


def format_text(reports: Sequence[FileReport]) -> str:
    """Compiler-style lines, `file:line: error[SCEML-S004] message (path)`, and a summary line."""
    lines = []
    for report in reports:
        if report.unreadable is not None:
            lines.append(f"{report.file}: error: cannot read: {report.unreadable}")
        lines.extend(_line(d, report.file) for d in report.diagnostics)
    totals = _totals(reports)
    summary = (
        f"{totals['files']} file(s): {totals['errors']} error(s), {totals['warnings']} "
        f"warning(s), {totals['infos']} info(s)"
    )
    if totals["unreadable"]:
        summary += f", {totals['unreadable']} unreadable"
    lines.append(summary)
    return "\n".join(lines) + "\n"


def _totals(reports: Sequence[FileReport]) -> dict[str, int]:
    return {
        "files": len(reports),
        "errors": sum(r.count(Severity.ERROR) for r in reports),
        "warnings": sum(r.count(Severity.WARNING) for r in reports),
        "infos": sum(r.count(Severity.INFO) for r in reports),
        "unreadable": sum(1 for r in reports if r.unreadable is not None),
    }


def _status(report: FileReport) -> str:
    if report.unreadable is not None:
        return "unreadable"
    return "invalid" if report.count(Severity.ERROR) else "valid"


def format_json(reports: Sequence[FileReport], tool: str = "sceml validate") -> str:
    """The documented JSON report: a summary and, per file, its status and diagnostics."""
    from . import __version__  # read from the package metadata: only when a report is written

    document = {
        "schema": JSON_SCHEMA_VERSION,
        "tool": tool,
        "version": __version__,
        "summary": _totals(reports),
        "files": [
            {
                "file": report.file,
                "status": _status(report),
                "unreadable": report.unreadable,
                "diagnostics": [d.to_json() for d in report.diagnostics],
            }
            for report in reports
        ],
    }
    return json.dumps(document, indent=2) + "\n"


def format_junit(
    reports: Sequence[FileReport], strict: bool = False, suite: str = "sceml validate"
) -> str:
    """JUnit XML: one testcase per file, one failure per error (per warning too when strict).

    An unreadable file is a testcase with an `error`; other diagnostics go to its system-out.
    """
    cases = []
    failures = errors = 0
    for report in reports:
        case = etree.Element("testcase", name=report.file, classname=suite.replace(" ", "."))
        if report.unreadable is not None:
            etree.SubElement(case, "error", message=report.unreadable, type="unreadable")
            errors += 1
        failing = report.failures(strict)
        for diagnostic in failing:
            failure = etree.SubElement(
                case, "failure", message=diagnostic.message, type=diagnostic.code
            )
            failure.text = _line(diagnostic, report.file)
            failures += 1
        failed = {id(d) for d in failing}
        rest = [d for d in report.diagnostics if id(d) not in failed]
        if rest:
            etree.SubElement(case, "system-out").text = "\n".join(
                _line(d, report.file) for d in rest
            )
        cases.append(case)
    root = etree.Element("testsuites", name=suite)
    attributes = {"tests": len(cases), "failures": failures, "errors": errors, "skipped": 0}
    testsuite = etree.SubElement(
        root, "testsuite", name=suite, **{k: str(v) for k, v in attributes.items()}
    )
    testsuite.extend(cases)
    for key in ("tests", "failures", "errors"):
        root.set(key, str(attributes[key]))
    text: bytes = etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
    return text.decode()


def render(
    reports: Sequence[FileReport], format: str, strict: bool = False, tool: str = "sceml validate"
) -> str:
    """The report in one of `text`, `json` or `junit`; `tool` names the command that made it."""
    if format == "junit":
        return format_junit(reports, strict, suite=tool)
    if format == "json":
        return format_json(reports, tool=tool)
    return format_text(reports)

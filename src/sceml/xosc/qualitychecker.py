"""Runs ASAM's OpenSCENARIO XML Quality Checker bundle on a .xosc file and returns plain results.

The bundle is ``asam-qc-openscenarioxml`` (module ``qc_openscenario``, CLI
``qc_openscenario.main:main``), built on ``qc_baselib`` Configuration/Result. Two ways to run it:

* in-process (default, ~4 ms per small file after a one-off ~0.15 s import): we call the
  bundle's own ``run_checks(config, result)`` -- exactly what its CLI ``main()`` does, minus
  writing the ``.xqar`` file. Its side effects are contained: ``logging.basicConfig`` done at
  import is undone; during a run the bundle's root-logger records from this thread are dropped
  (a temporary NullHandler keeps ``logging.info`` from calling ``basicConfig`` again); and the
  working directory, which the bundle changes to resolve RoadNetwork/LogicFile, is restored
  even when the bundle raises. Runs are serialised by a lock because the cwd is process-wide:
  other threads that rely on relative paths should use ``in_process=False``.
* subprocess (``in_process=False``, ~0.2-0.35 s per file, mostly interpreter start-up and
  imports): the real CLI with a generated config XML; its ``.xqar`` result is written to a
  temporary directory, read back and deleted. Checker summaries then carry the CLI's
  generated "N issue(s) are found." suffix, which the in-process mode does not add.

Before handing a file to the bundle (whose parser is lxml's default one) the file and a
literal RoadNetwork/LogicFile are screened with :mod:`sceml.xosc.schema`'s hardened reader, so
documents with a DOCTYPE raise :class:`sceml.xosc.schema.UnsafeXMLError`.

By design the bundle only applies its 1.2.0 rules (references, parameters, data types) to
OpenSCENARIO >= 1.2; for older files only the basic XML and schema checks run and
``QualityReport.skipped_below_1_2`` is True. Library code here never prints.
"""

from __future__ import annotations

import contextlib
import functools
import logging
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import types
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Final, cast

from lxml import etree

from sceml.diagnostics import Diagnostic, Severity
from sceml.errors import SceMLError
from sceml.xosc import schema

__all__ = [
    "CheckerStatus",
    "QualityCheckerError",
    "QualityIssue",
    "QualityReport",
    "quality_diagnostics",
    "run_quality_checker",
]


def _number(version: str) -> tuple[int, ...]:
    """`1.2` as (1, 2), so that versions compare as numbers."""
    return tuple(int(part) for part in version.split("."))


#: The first OpenSCENARIO version the bundle applies its rules to; the versions come from
#: `schema.SUPPORTED_VERSIONS`, the one list.
FIRST_CHECKED_VERSION: Final = "1.2"
CHECKED_VERSIONS: Final = tuple(
    v for v in schema.SUPPORTED_VERSIONS if _number(v) >= _number(FIRST_CHECKED_VERSION)
)

#: Diagnostic codes of the checker's own outcomes (its issues keep their rule UIDs).
FAILED_CODE: Final = "XOSC-QC"
SKIPPED_CODE: Final = "XOSC-QC-SKIPPED"
_SEVERITIES: Final = {
    "error": Severity.ERROR,
    "warning": Severity.WARNING,
    "information": Severity.INFO,
}

_BUNDLE_MODULE: Final = "qc_openscenario"

_RUN_LOCK = threading.Lock()


class QualityCheckerError(SceMLError):
    """The Quality Checker bundle could not be run or crashed outside its own error handling."""


@dataclass(frozen=True, slots=True)
class QualityIssue:
    """One issue reported by a checker of the bundle."""

    rule_uid: str
    checker_id: str
    level: str  # "error" | "warning" | "information"
    message: str
    line: int | None = None
    column: int | None = None
    xpath: str | None = None

    def __str__(self) -> str:
        where = f"line {self.line}" if self.line is not None else (self.xpath or "")
        return f"[{self.level}] {self.rule_uid}: {self.message}" + (f" ({where})" if where else "")

    def diagnostic(self, file: str | None = None) -> Diagnostic:
        """The issue as a Diagnostic under its rule UID; an unknown level counts as an error."""
        return Diagnostic(
            _SEVERITIES.get(self.level, Severity.ERROR),
            self.rule_uid,
            self.message,
            path=self.xpath,
            file=file,
            line=self.line,
        )


@dataclass(frozen=True, slots=True)
class CheckerStatus:
    """Outcome of one checker: status is "completed", "skipped" or "error"."""

    checker_id: str
    status: str
    summary: str
    rule_uids: tuple[str, ...]


@dataclass(frozen=True)
class QualityReport:
    """Everything the bundle said about one file."""

    path: Path
    version: str | None  # "major.minor" from the FileHeader, None if unreadable
    issues: tuple[QualityIssue, ...]
    checker_statuses: Mapping[str, CheckerStatus]
    skipped_below_1_2: bool
    bundle_version: str

    @property
    def ok(self) -> bool:
        """No issues, and no checker crashed (skipped checkers do not count against ok)."""
        return not self.issues and all(s.status != "error" for s in self.checker_statuses.values())

    @property
    def skipped_checkers(self) -> tuple[str, ...]:
        return tuple(c for c, s in self.checker_statuses.items() if s.status == "skipped")


def quality_diagnostics(path: Path, version: str) -> list[Diagnostic]:
    """The checker's findings on one file as Diagnostics; below 1.2 an INFO that it did not run,
    and a checker that cannot run an ERROR (XOSC-QC) rather than an exception."""
    if version not in CHECKED_VERSIONS:
        message = (
            f"ASAM Quality Checker rules apply from OpenSCENARIO {FIRST_CHECKED_VERSION}; "
            f"{version} got the XSD only"
        )
        return [Diagnostic(Severity.INFO, SKIPPED_CODE, message, file=str(path))]
    try:
        report = run_quality_checker(path)
    except QualityCheckerError as error:
        message = f"Quality Checker failed: {error.message}"
        return [Diagnostic(Severity.ERROR, FAILED_CODE, message, file=str(path))]
    return [issue.diagnostic(str(path)) for issue in report.issues]


def run_quality_checker(
    path: str | os.PathLike[str],
    *,
    in_process: bool = True,
    timeout: float | None = 120.0,
    result_file: str | os.PathLike[str] | None = None,
) -> QualityReport:
    """Run the ASAM OpenSCENARIO XML checker bundle on ``path``.

    ``result_file``, if given, receives a copy of the bundle's ``.xqar`` result (for the ASAM
    report tools); otherwise nothing is left on disk. ``timeout`` applies to the subprocess
    mode only. Raises schema.UnsafeXMLError for DOCTYPE documents, FileNotFoundError for a
    missing file and QualityCheckerError if the bundle itself fails.
    """
    input_path = Path(path).resolve()
    if not input_path.is_file():
        raise FileNotFoundError(f"no such OpenSCENARIO file: {input_path}")
    version = _screen(input_path)

    if not in_process:
        return _to_report(input_path, version, _run_subprocess(input_path, timeout, result_file))
    result, config = _run_in_process(input_path)
    report = _to_report(input_path, version, result)
    if result_file:
        # Like the CLI; done after _to_report because generate_summary appends to summaries.
        result.copy_param_from_config(config)
        result.write_to_file(os.fspath(result_file), generate_summary=True)
    return report


def _screen(path: Path) -> str | None:
    """Refuse DTD-carrying inputs; return the declared "major.minor" version if readable."""
    try:
        tree = schema.parse_file(path)
    except schema.XMLParseError:
        return None  # not well-formed: the bundle reports that itself (valid_xml_document)
    _screen_logic_file(path, tree)
    header = tree.getroot().find("FileHeader")
    if header is None:
        return None
    try:
        return f"{int(header.get('revMajor', ''))}.{int(header.get('revMinor', ''))}"
    except ValueError:
        return None


def _screen_logic_file(path: Path, tree: etree._ElementTree) -> None:
    # The bundle parses the referenced OpenDRIVE file with lxml's default parser too.
    # Parameterised paths ($Road) are resolved by the bundle only and cannot be screened here.
    logic = tree.getroot().find("RoadNetwork/LogicFile")
    filepath = logic.get("filepath") if logic is not None else None
    if not filepath or filepath.startswith("$"):
        return
    xodr = (path.parent / filepath).resolve()
    if xodr.is_file():
        # Only refusal matters here; malformed road files are the bundle's business.
        with contextlib.suppress(schema.XMLParseError):
            schema.parse_file(xodr)


@functools.cache
def _bundle() -> types.ModuleType:
    """Import the bundle once, undoing the logging.basicConfig() its main module runs."""
    root = logging.getLogger()
    handlers, level = list(root.handlers), root.level
    try:
        import qc_openscenario.main as qc_main
    except ImportError as exc:  # pragma: no cover - dependency is declared in pyproject
        raise QualityCheckerError(f"{_BUNDLE_MODULE} is not installed: {exc}") from exc
    finally:
        for handler in root.handlers[:]:
            if handler not in handlers:
                root.removeHandler(handler)
        root.setLevel(level)
    return cast(types.ModuleType, qc_main)


class _DropThreadRecords(logging.Filter):
    """Drops records emitted on the root logger by one thread (the one running the bundle)."""

    def __init__(self, thread_id: int) -> None:
        super().__init__()
        self.thread_id = thread_id

    def filter(self, record: logging.LogRecord) -> bool:
        return record.thread != self.thread_id


@contextmanager
def _contained_run() -> Iterator[None]:
    root = logging.getLogger()
    drop = _DropThreadRecords(threading.get_ident())
    with _RUN_LOCK:  # cwd and the root logger are process-wide; one bundle run at a time
        try:
            cwd: str | None = os.getcwd()
        except FileNotFoundError:
            cwd = None
        # logging.info() calls basicConfig() whenever the root logger has no handler.
        guard = logging.NullHandler() if not root.handlers else None
        root.addFilter(drop)
        if guard is not None:
            root.addHandler(guard)
        try:
            yield
        finally:
            if guard is not None:
                root.removeHandler(guard)
            root.removeFilter(drop)
            if cwd is not None:
                os.chdir(cwd)


def _new_config(input_path: Path, result_path: Path | None) -> Any:
    from qc_baselib import Configuration

    bundle_name = _bundle().constants.BUNDLE_NAME
    config = Configuration()
    config.set_config_param(name="InputFile", value=str(input_path))
    config.register_checker_bundle(checker_bundle_name=bundle_name)
    if result_path is not None:
        config.set_checker_bundle_param(bundle_name, name="resultFile", value=str(result_path))
    return config


def _run_in_process(input_path: Path) -> tuple[Any, Any]:
    from qc_baselib import Result

    qc_main = _bundle()
    constants = qc_main.constants
    config = _new_config(input_path, None)
    result = Result()
    # Mirrors qc_openscenario.main.main(), which offers no in-process entry point of its own.
    result.register_checker_bundle(
        name=constants.BUNDLE_NAME,
        description="OpenScenario checker bundle",
        version=constants.BUNDLE_VERSION,
        summary="",
    )
    result.set_result_version(version=constants.BUNDLE_VERSION)
    with _contained_run():
        try:
            qc_main.run_checks(config, result)
        except Exception as exc:
            raise QualityCheckerError(
                f"Quality Checker bundle failed: {exc}", file=str(input_path)
            ) from exc
    return result, config


def _run_subprocess(
    input_path: Path, timeout: float | None, result_file: str | os.PathLike[str] | None
) -> Any:
    from qc_baselib import Result

    with tempfile.TemporaryDirectory(prefix="sceml-qc-") as tmp:
        xqar = Path(tmp) / "xoscBundle.xqar"
        config_path = Path(tmp) / "config.xml"
        _new_config(input_path, xqar).write_to_file(str(config_path))
        try:
            proc = subprocess.run(
                [sys.executable, "-m", _BUNDLE_MODULE, "-c", str(config_path)],
                cwd=tmp,  # anything else the CLI might write lands in the temp dir too
                capture_output=True,
                text=True,
                timeout=timeout,
                check=False,
            )
        except subprocess.TimeoutExpired as exc:
            raise QualityCheckerError("Quality Checker timed out", file=str(input_path)) from exc
        if proc.returncode != 0 or not xqar.is_file():
            tail = "\n".join(proc.stderr.strip().splitlines()[-5:])
            raise QualityCheckerError(
                f"Quality Checker exited with {proc.returncode}: {tail}", file=str(input_path)
            )
        result = Result()
        result.load_from_file(str(xqar))
        if result_file:
            shutil.copyfile(xqar, result_file)
    return result


def _level_name(level: Any) -> str:
    return str(getattr(level, "name", level)).lower()


def _to_report(input_path: Path, version: str | None, result: Any) -> QualityReport:
    constants = _bundle().constants
    bundle = result.get_checker_bundle_result(constants.BUNDLE_NAME)
    issues: list[QualityIssue] = []
    statuses: dict[str, CheckerStatus] = {}
    for checker in bundle.checkers:
        statuses[checker.checker_id] = CheckerStatus(
            checker_id=checker.checker_id,
            status=str(getattr(checker.status, "value", checker.status)),
            summary=checker.summary or "",
            rule_uids=tuple(rule.rule_uid for rule in checker.addressed_rule),
        )
        for issue in checker.issues:
            line = column = None
            xpath = None
            details = []
            for location in issue.locations:
                if location.description:
                    details.append(location.description)
                for file_loc in location.file_location:
                    if line is None and file_loc.row is not None:
                        line, column = file_loc.row, file_loc.column
                for xml_loc in location.xml_location:
                    xpath = xpath or xml_loc.xpath
            message = issue.description + (": " + "; ".join(details) if details else "")
            issues.append(
                QualityIssue(
                    rule_uid=issue.rule_uid,
                    checker_id=checker.checker_id,
                    level=_level_name(issue.level),
                    message=message,
                    line=line,
                    column=column,
                    xpath=xpath,
                )
            )
    below_1_2 = version is not None and _number(version) < _number(FIRST_CHECKED_VERSION)
    return QualityReport(
        path=input_path,
        version=version,
        issues=tuple(issues),
        checker_statuses=types.MappingProxyType(statuses),
        skipped_below_1_2=below_1_2,
        bundle_version=bundle.version,
    )

"""`sceml validate`: exit codes, the three formats, -o, --limits, and the generated rules doc."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import yaml
from click.testing import CliRunner
from junitparser import Error, Failure, JUnitXml

from sceml.cli.validate import validate
from sceml.validation import docs

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
EXAMPLES = REPO / "examples"
CORPUS = HERE / "corpus"
INVALID = CORPUS / "s004-join-one-input.xmi"
WARNING_ONLY = CORPUS / "a004-unused-target.xmi"


def run(*arguments: object) -> tuple[int, str]:
    result = CliRunner().invoke(validate, [str(a) for a in arguments])
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    return result.exit_code, result.output


def test_each_reference_example_exits_0() -> None:
    for path in [*EXAMPLES.glob("*.xmi"), *(EXAMPLES / "library").glob("*.xmi")]:
        status, output = run(path)
        assert status == 0, output
        assert output.endswith("1 file(s): 0 error(s), 0 warning(s), 0 info(s)\n")


def test_errors_exit_1_with_compiler_style_lines() -> None:
    status, output = run(INVALID)
    assert status == 1
    first = output.splitlines()[0]
    assert first == (
        f"{INVALID}:17: error[SCEML-S004] join 'JoinAllFinished_1' has 1 incoming flow(s); "
        "a join needs at least two (JoinAllFinished_1)"
    )


def test_warnings_fail_only_when_strict() -> None:
    assert run(WARNING_ONLY)[0] == 0
    assert run(WARNING_ONLY, "--strict")[0] == 1


def test_unreadable_file_exits_2_and_the_others_are_still_validated(tmp_path: Path) -> None:
    broken = tmp_path / "broken.xmi"
    broken.write_text("<scemlmodel:Scenario", encoding="utf-8")
    status, output = run(broken, INVALID, tmp_path / "missing.xmi")
    assert status == 2
    lines = output.splitlines()
    assert lines[0].startswith(f"{broken}: error: cannot read: line 1: malformed XML")
    assert any("[SCEML-S004]" in line for line in lines)
    assert f"{tmp_path / 'missing.xmi'}: error: cannot read: no such file" in lines
    assert lines[-1] == "3 file(s): 1 error(s), 0 warning(s), 0 info(s), 2 unreadable"


def test_usage_errors_exit_2() -> None:
    assert run()[0] == 2
    assert run(INVALID, "--format", "xml")[0] == 2


def test_json_has_the_documented_shape(tmp_path: Path) -> None:
    status, output = run(INVALID, WARNING_ONLY, tmp_path / "missing.xmi", "--format", "json")
    assert status == 2
    report = json.loads(output)
    assert set(report) == {"schema", "tool", "version", "summary", "files"}
    assert report["schema"] == 1
    assert report["summary"] == {
        "files": 3,
        "errors": 1,
        "warnings": 1,
        "infos": 0,
        "unreadable": 1,
    }
    invalid, warned, missing = report["files"]
    assert (invalid["status"], warned["status"], missing["status"]) == (
        "invalid",
        "valid",
        "unreadable",
    )
    assert missing["unreadable"] == "no such file" and missing["diagnostics"] == []
    assert invalid["diagnostics"] == [
        {
            "severity": "error",
            "code": "SCEML-S004",
            "message": "join 'JoinAllFinished_1' has 1 incoming flow(s); a join needs at least two",
            "file": str(INVALID),
            "line": 17,
            "fragment": "//@nodes.3",
            "path": "JoinAllFinished_1",
        }
    ]


def test_junit_parses_with_one_testcase_per_file_and_one_failure_per_error(
    tmp_path: Path,
) -> None:
    target = tmp_path / "report.xml"
    multi = CORPUS / "multi-levels.xmi"
    status, output = run(
        EXAMPLES / "uis1-concrete.xmi",
        multi,
        WARNING_ONLY,
        tmp_path / "missing.xmi",
        "--format",
        "junit",
        "-o",
        target,
    )
    assert (status, output) == (2, "")
    suite = next(iter(JUnitXml.fromfile(str(target))))
    cases = {case.name: case for case in suite}
    assert list(cases) == [
        str(EXAMPLES / "uis1-concrete.xmi"),
        str(multi),
        str(WARNING_ONLY),
        str(tmp_path / "missing.xmi"),
    ]
    assert cases[str(EXAMPLES / "uis1-concrete.xmi")].result == []
    failures = cases[str(multi)].result
    assert all(isinstance(f, Failure) for f in failures)
    # The 11 errors of this case, counted by hand (12 before FollowTrajectory_1 counted as lateral
    # only: it no longer conflicts with the crossing's Accelerate_1, only with its Cross_1).
    assert len(failures) == 11
    assert {f.type for f in failures} == {
        "SCEML-C001",
        "SCEML-M004",
        "SCEML-M006",
        "SCEML-P002",
        "SCEML-P003",
        "SCEML-P005",
        "SCEML-P006",
    }
    assert cases[str(WARNING_ONLY)].result == []  # a warning is no failure unless --strict
    assert cases[str(WARNING_ONLY)].system_out.count("warning[SCEML-A004]") == 1
    assert [type(r) for r in cases[str(tmp_path / "missing.xmi")].result] == [Error]
    assert (suite.tests, suite.failures, suite.errors) == (4, 11, 1)


def test_junit_strict_makes_warnings_failures() -> None:
    status, output = run(WARNING_ONLY, "--format", "junit", "--strict")
    assert status == 1
    case = next(iter(next(iter(JUnitXml.fromstring(output.encode())))))
    assert [r.type for r in case.result] == ["SCEML-A004"]


def test_limits_option(tmp_path: Path) -> None:
    example = EXAMPLES / "uis2-concrete.xmi"
    slow = tmp_path / "limits.toml"
    slow.write_text("[Car]\nmax_speed = 6.0\n", encoding="utf-8")
    status, output = run(example, "--limits", slow)
    assert status == 1
    assert "error[SCEML-L001] ego.Accelerate_1.targetSpeed is 7 m/s, above the Car limit" in output
    bad = tmp_path / "bad.yaml"
    bad.write_text("Robot: {}\n", encoding="utf-8")
    status, output = run(example, "--limits", bad)
    assert status == 2 and "unknown actor kind 'Robot'" in output


def test_output_file_is_written_atomically_over_an_old_one(tmp_path: Path) -> None:
    target = tmp_path / "report.txt"
    target.write_text("old", encoding="utf-8")
    assert run(INVALID, "-o", target) == (1, "")
    assert "[SCEML-S004]" in target.read_text(encoding="utf-8")
    assert [p.name for p in tmp_path.iterdir()] == ["report.txt"]


def test_validates_a_copy_with_its_library_in_another_folder(examples_copy: Path) -> None:
    shutil.rmtree(examples_copy / "library")
    status, output = run(examples_copy / "uis2-concrete.xmi")
    assert status == 1
    assert "[SCEML-M013]" in output and "sceml-library.xmi" in output


def test_help_explains_every_option() -> None:
    status, output = run("--help")
    assert status == 0
    for option in ("--format", "--strict", "--limits", "--osc-version", "--output"):
        assert option in output


def test_rules_doc_is_the_registry_rendering() -> None:
    committed = (REPO / "docs" / "validation-rules.md").read_text(encoding="utf-8")
    assert committed == docs.render(), "regenerate: python -m sceml.validation.docs"
    assert (
        "| `SCEML-S004` | error | JoiningPolicy | A join has at least two incoming flows. |"
        in committed
    )


def test_pre_commit_hook() -> None:
    [hook] = yaml.safe_load((REPO / ".pre-commit-hooks.yaml").read_text(encoding="utf-8"))
    assert (hook["id"], hook["entry"], hook["files"]) == (
        "sceml-validate",
        "sceml validate",
        r"\.xmi$",
    )

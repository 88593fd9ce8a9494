"""`sceml import`'s exit code: errors the original has too do not fail it; errors the import
causes do, and --strict makes any error fail it (issue 24).

A rule registered with `judges_stated_values` (the actor kind's limits, the map) judges a value
as the file states it: `stated-values.xosc` breaks L001, L002 and R003 as written, and esmini
plays it as it is. `no-start.xosc` has an actor the file gives no start: SCEML-E002 is the
model's, not a value's.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from sceml.cli import cli
from sceml.diagnostics import Diagnostic, Severity
from sceml.importer.verdict import judge
from sceml.validation import REGISTRY

FILES = Path(__file__).resolve().parent / "files"
BLOCK = "the original has these too"


def _import(tmp_path: Path, name: str, *options: str) -> tuple[int, str, str]:
    runner = CliRunner()
    output = tmp_path / f"{name}.xmi"
    result = runner.invoke(
        cli, ["import", str(FILES / f"{name}.xosc"), "-o", str(output), *options]
    )
    return result.exit_code, result.stdout, result.stderr


def _codes(text: str) -> set[str]:
    return {word.split("[")[1].split("]")[0] for word in text.split() if "[SCEML-" in word}


def test_errors_the_original_has_too_are_listed_and_do_not_fail_the_import(
    tmp_path: Path,
) -> None:
    code, out, err = _import(tmp_path, "stated-values")
    assert code == 0, err
    assert (tmp_path / "stated-values.xmi").is_file()
    before, block = err.split(BLOCK)
    # Nothing above the block; in it, the three values as the file states them.
    assert _codes(before) == set()
    assert _codes(block) == {"SCEML-L001", "SCEML-L002", "SCEML-R003"}
    assert "Walker.initialSpeed is 8 m/s" in block
    assert "Ego.SpeedUp.rate is 10 m/s2" in block
    assert "road '1' has no lane -4" in block


def test_strict_fails_on_the_errors_the_original_has_too(tmp_path: Path) -> None:
    code, _, err = _import(tmp_path, "stated-values", "--strict")
    assert code == 1
    # The model is written all the same, and the block says the same.
    assert (tmp_path / "stated-values.xmi").is_file()
    assert _codes(err.split(BLOCK)[1]) == {"SCEML-L001", "SCEML-L002", "SCEML-R003"}
    assert "--strict makes them" not in err


def test_an_error_the_import_causes_fails_it_beside_the_originals(tmp_path: Path) -> None:
    code, _, err = _import(tmp_path, "no-start")
    assert code == 1
    before, block = err.split(BLOCK)
    assert _codes(before) == {"SCEML-E002"}
    assert "actor 'Parked' has no start position" in before
    assert _codes(block) == {"SCEML-L002"}


def test_a_clean_import_prints_no_block(tmp_path: Path) -> None:
    code, _, err = _import(tmp_path, "trajectory-start")
    assert code == 0, err
    assert BLOCK not in err


def test_the_rules_that_judge_stated_values_are_the_limits_and_the_map() -> None:
    stated = {rule.code for rule in REGISTRY.rules() if rule.judges_stated_values}
    assert stated == {
        "SCEML-L001",
        "SCEML-L002",
        "SCEML-L003",
        "SCEML-R003",
        "SCEML-R004",
        "SCEML-R005",
        "SCEML-R008",
        "SCEML-R009",
    }


def _diagnostic(code: str, severity: Severity = Severity.ERROR) -> Diagnostic:
    return Diagnostic(severity, code, "m")


def test_the_verdict_splits_by_rule_and_gives_the_exit_code() -> None:
    deserved = judge([_diagnostic("SCEML-L002"), _diagnostic("SCEML-R005", Severity.WARNING)])
    assert [d.code for d in deserved.originals] == ["SCEML-L002", "SCEML-R005"]
    assert deserved.caused_errors == ()
    assert [d.code for d in deserved.original_errors] == ["SCEML-L002"]
    assert deserved.exit_code() == 0
    assert deserved.exit_code(strict=True) == 1
    caused = judge([_diagnostic("SCEML-E002"), _diagnostic("SCEML-S013", Severity.WARNING)])
    assert [d.code for d in caused.caused_errors] == ["SCEML-E002"]
    assert caused.exit_code() == 1
    # Warnings alone fail nothing, not even strictly.
    assert judge([_diagnostic("SCEML-S013", Severity.WARNING)]).exit_code(strict=True) == 0


def test_a_code_no_rule_owns_is_never_the_originals() -> None:
    verdict = judge([_diagnostic("SCEML-X000")])
    assert verdict.originals == ()
    assert verdict.exit_code() == 1

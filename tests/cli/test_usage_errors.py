"""A bad option value is a usage error (exit 2, as the README promises), refused by the option's
type, which calls the same parser the library uses."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.errors import ArgumentError
from sceml.export.writer import header_date
from sceml.levels.concretize import parse_assignment

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
LOGICAL = str(EXAMPLES / "uis2-logical.xmi")
CONCRETE = str(EXAMPLES / "uis2-concrete.xmi")


@pytest.mark.parametrize(
    ("arguments", "expected"),
    [
        (["sample", LOGICAL, "--strategy", "random", "-o", "{out}"], "--n"),
        (["sample", LOGICAL, "--strategy", "lhs", "-o", "{out}"], "--n"),
        (["sample", LOGICAL, "--index", "100000", "-o", "{out}"], "sample index"),
        (["concretize", LOGICAL, "--set", "x=25km/h", "-o", "{out}/c.xmi"], "PATH=NUMBER"),
        (["concretize", LOGICAL, "--set", "nonsense", "-o", "{out}/c.xmi"], "PATH=NUMBER"),
        (["concretize", LOGICAL, "--set", "no.such.path=3", "-o", "{out}/c.xmi"], "unknown"),
        (["export", CONCRETE, "--date", "yesterday", "-o", "{out}/a.xosc"], "ISO 8601"),
        (["export-distribution", LOGICAL, "--date", "yesterday", "-o", "{out}"], "ISO 8601"),
        (["export-distribution", LOGICAL, "--osc-version", "1.0", "-o", "{out}"], "1.0"),
    ],
)
def test_bad_option_values_are_usage_errors(
    tmp_path: Path, arguments: list[str], expected: str
) -> None:
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, [a.format(out=out) for a in arguments])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert result.exit_code == 2, result.output
    assert expected in result.output, result.output
    assert not out.exists()


def test_help_offers_only_versions_that_are_accepted() -> None:
    result = CliRunner().invoke(cli, ["export-distribution", "--help"])
    assert "1.1|1.2|1.3" in result.output and "1.0" not in result.output.replace("1.0 has", "")


def test_the_parsers_are_the_library_s() -> None:
    assert parse_assignment("ego.initialSpeed= 5") == ("ego.initialSpeed", 5.0)
    assert header_date("2026-01-01") == "2026-01-01T00:00:00"
    for parse, text in [(parse_assignment, "a=nan"), (header_date, "noon")]:
        with pytest.raises(ArgumentError):
            parse(text)

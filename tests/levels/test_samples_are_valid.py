"""Every sample of a clean logical scenario is a valid concrete scenario (SPEC §5), so what a
sample needs (map, start positions) is required of the logical scenario already."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.diagnostics import Severity
from sceml.model.loading import load
from sceml.validation import validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CORPUS = Path(__file__).resolve().parents[1] / "validation" / "corpus"


def sample(logical: Path, out: Path) -> tuple[int, str]:
    arguments = ["sample", str(logical), "--strategy", "random", "--n", "3", "--workers", "1"]
    result = CliRunner().invoke(cli, [*arguments, "--format", "xmi", "-o", str(out)])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    return result.exit_code, result.output


@pytest.mark.parametrize("name", ["e002-logical-no-start-position.xmi", "e001-logical-no-map.xmi"])
def test_a_logical_scenario_samples_could_not_use_is_refused_before_sampling(
    tmp_path: Path, name: str
) -> None:
    code, output = sample(CORPUS / name, tmp_path / "out")
    assert code == 1 and ("SCEML-E002" in output or "SCEML-E001" in output), output
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("logical", sorted(EXAMPLES.glob("*-logical.xmi")), ids=lambda p: p.name)
def test_every_sample_of_a_clean_logical_example_validates(tmp_path: Path, logical: Path) -> None:
    code, output = sample(logical, tmp_path)
    assert code == 0, output
    samples = sorted(tmp_path.glob("*.xmi"))
    assert len(samples) == 3
    for path in samples:
        document = load(path, allow=[EXAMPLES, EXAMPLES.parent / "maps"])
        errors = [
            d for d in validate(document.root, document=document) if d.severity >= Severity.ERROR
        ]
        assert errors == [], [str(e) for e in errors]

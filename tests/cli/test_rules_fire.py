"""Every documented rule can fire on a file or a model (issue 14, fault 7)."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from sceml.cli import cli
from sceml.validation import REGISTRY

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_e003_fires_for_a_profile_that_cannot_express_a_kind() -> None:
    overtaking = str(EXAMPLES / "overtaking-concrete.xmi")
    result = CliRunner().invoke(cli, ["validate", "--profile", "carla", overtaking])
    assert result.exit_code == 1, result.output
    assert "[SCEML-E003] KeepVelocity cannot be exported" in result.output, result.output
    assert "carla" in result.output
    clean = CliRunner().invoke(cli, ["validate", "--profile", "generic", overtaking])
    assert clean.exit_code == 0, clean.output


def test_m014_says_where_it_fires() -> None:
    # A file with two modules of one name is refused when read; models built in memory (the
    # builder API, the editor) are where the rule reports it.
    assert "in memory" in REGISTRY.rule("SCEML-M014").description

"""`sceml export --allow-implausible`: a model whose only errors are plausibility limits it
states itself (a bicycle at 30 m/s) is written with each limit as a warning; without the flag it
is refused with a hint; any other error still refuses, flag or not."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result
from lxml import etree

from sceml.cli import cli


def sceml(*arguments: object) -> Result:
    result = CliRunner().invoke(cli, [str(a) for a in arguments])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    return result


def _fast_bike(examples: Path) -> Path:
    source = examples / "uis1-concrete.xmi"
    text = source.read_text(encoding="utf-8")
    bike_speed = '<initialSpeed xsi:type="scemlmodel:Value" value="0.0"/>'
    assert text.count(bike_speed) == 1
    source.write_text(text.replace(bike_speed, bike_speed.replace("0.0", "30.0")), encoding="utf-8")
    return source


def test_a_model_whose_only_errors_are_limits_is_refused_with_a_hint(
    examples_copy: Path, tmp_path: Path
) -> None:
    source = _fast_bike(examples_copy)
    result = sceml("export", source, "-o", tmp_path / "a.xosc")
    assert result.exit_code == 1
    assert "error[SCEML-L001] bike.initialSpeed is 30 m/s" in result.output, result.output
    assert "plausibility limits only: --allow-implausible writes it" in result.output
    assert not (tmp_path / "a.xosc").exists()


def test_allow_implausible_writes_it_as_stated_and_warns(
    examples_copy: Path, tmp_path: Path
) -> None:
    source = _fast_bike(examples_copy)
    result = sceml("export", source, "-o", tmp_path / "a.xosc", "--allow-implausible")
    assert result.exit_code == 0, result.output
    assert "warning[SCEML-L001] bike.initialSpeed is 30 m/s" in result.output
    assert "(written anyway: --allow-implausible)" in result.output
    speeds = {
        private.get("entityRef"): target.get("value")
        for private in etree.parse(str(tmp_path / "a.xosc")).iter("Private")
        for target in private.iter("AbsoluteTargetSpeed")
    }
    assert speeds["bike"] == "30.0"


def test_other_errors_still_refuse_with_the_flag(examples_copy: Path, tmp_path: Path) -> None:
    source = _fast_bike(examples_copy)
    source.write_text(
        source.read_text().replace('timeOfDay="12:00:00"', 'timeOfDay="noon"'), encoding="utf-8"
    )
    result = sceml("export", source, "-o", tmp_path / "a.xosc", "--allow-implausible")
    assert result.exit_code == 1
    assert (
        "error[SCEML-E004]" in result.output and "--allow-implausible writes" not in result.output
    )
    assert not (tmp_path / "a.xosc").exists()

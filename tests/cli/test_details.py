"""The smaller faults of issue 14: what the commands say, and what the diagrams show."""

from __future__ import annotations

import re
from pathlib import Path

import click
import pytest
from click.testing import CliRunner, Result

from sceml.cli import cli, commands
from sceml.files import safexml
from sceml.model.loading import load
from sceml.render import diagram, to_bytes

from ..render.svgtools import groups, parse, text_of

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GOLDEN = Path(__file__).resolve().parents[1] / "export" / "golden"


def sceml(*arguments: object) -> Result:
    result = CliRunner().invoke(cli, [str(a) for a in arguments])
    assert result.exception is None or isinstance(result.exception, SystemExit)
    return result


@pytest.mark.parametrize(
    ("size", "limit", "text"),
    [
        (100 * 2**20, safexml.DEFAULT_MAX_BYTES, "file is 100 MiB, above the 64 MiB limit"),
        (2000, 1000, "file is 2000 bytes, above the 1000-byte limit"),
        (3 * 2**20 + 2**19, 2**20, "file is 3.5 MiB, above the 1 MiB limit"),
    ],
)
def test_the_size_limit_is_said_in_the_units_the_docs_use(size: int, limit: int, text: str) -> None:
    assert safexml.size_problem(size, limit) == f"{text} (set SCEML_MAX_BYTES to change it)"
    assert safexml.size_problem(limit, limit) is None
    assert "64 MiB" in (Path(__file__).resolve().parents[2] / "docs/security.md").read_text()


def test_check_xosc_junit_report_is_named_after_check_xosc() -> None:
    result = sceml(
        "check-xosc", "--no-quality-checker", "--format", "junit", GOLDEN / "uis1-1.3-generic.xosc"
    )
    assert result.exit_code == 0, result.output
    assert 'name="sceml check-xosc"' in result.output and "sceml validate" not in result.output


def test_export_reports_each_problem_once_with_its_line(
    examples_copy: Path, tmp_path: Path
) -> None:
    source = examples_copy / "uis1-concrete.xmi"
    source.write_text(source.read_text().replace('timeOfDay="12:00:00"', 'timeOfDay="noon"'))
    result = sceml("export", source, "-o", tmp_path / "a.xosc")
    assert result.exit_code == 1
    assert result.output.count("'noon'") == 1, result.output
    assert f"{source}:5: error[SCEML-E004]" in result.output, result.output
    assert not (tmp_path / "a.xosc").exists()


def _commands(group: click.Group, prefix: tuple[str, ...] = ()):  # type: ignore[no-untyped-def]
    listed = commands() if group is cli else group.commands
    for name, command in listed.items():
        if isinstance(command, click.Group):
            yield from _commands(command, (*prefix, name))
        else:
            yield (*prefix, name), command


ACRONYMS = {"ASAM", "XSD", "XML", "DOCTYPE", "JSON", "HTML", "SVG", "PNG", "PDF", "CI", "ISO"}


@pytest.mark.parametrize(
    ("path", "command"), list(_commands(cli)), ids=[" ".join(p) for p, _ in _commands(cli)]
)
def test_help_names_only_arguments_and_options_the_command_has(
    path: tuple[str, ...], command: click.Command
) -> None:
    context = click.Context(command, info_name=" ".join(path))
    shown = " ".join(
        [
            *command.collect_usage_pieces(context),
            *(" ".join(p.get_help_record(context) or ()) for p in command.get_params(context)),
        ]
    )
    named = set(re.findall(r"\b[A-Z][A-Z_]{2,}\b", command.help or "")) - ACRONYMS
    missing = {word for word in named if not re.search(rf"\b{word}\b", shown)}
    assert not missing, f"{' '.join(path)} --help names {missing}, which it does not have"


def test_the_behavior_tree_legend_explains_the_behavior_tree() -> None:
    scenario = load(EXAMPLES / "uis1-concrete.xmi").root
    svg = parse(to_bytes(diagram(scenario, view="bt", legend=True), "svg"))
    assert len(groups(svg, "sceml-legend")) == 1
    text = " ".join(text_of(g) for g in groups(svg, "sceml-legend-caption"))
    for caption in ("sequence", "parallel", "all", "one", "wait"):
        assert caption in text.lower(), text
    assert "in-port" not in text.lower() and "join" not in text.lower(), text


@pytest.mark.parametrize("view", ["flow", "bt"])
def test_boxes_show_kind_and_name(view: str) -> None:
    scenario = load(EXAMPLES / "uis1-concrete.xmi").root
    svg = parse(to_bytes(diagram(scenario, view=view), "svg"))  # type: ignore[arg-type]
    texts = [text_of(g) for g in groups(svg, "sceml-node")]
    assert any("Accelerate" in t and "Accelerate_1" in t for t in texts), texts
    assert any("InVehicleRadius" in t and "InVehicleRadius_1" in t for t in texts), texts

"""sceml diff and sceml render --diff as a reviewer and a CI job use them."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner
from diff.conftest import actor, node
from lxml import etree

import scemlmodel as scm
from sceml.cli import cli
from sceml.model import params


def run(*arguments: str | Path) -> tuple[int, str]:
    result = CliRunner().invoke(cli, [str(a) for a in arguments])
    return result.exit_code, result.output


def _tolerance_and_move(scenario: scm.Scenario) -> None:
    node(scenario, "TurnLeft_1").tolerance = params.value(4.0)
    node(scenario, "End").diagramPosition = scm.DiagramPosition(x=0.0, y=300.0)


def test_text_lists_parts_and_no_layout_hides_positions(uis2: Path, edited) -> None:
    new = edited(_tolerance_and_move)
    code, shown = run("diff", uis2, new)
    assert code == 0
    assert "Nodes\n  ~ TurnLeft_1.tolerance: 3 -> 4 m\n" in shown
    assert "Layout (diagram positions only)\n  ~ End moved auto -> (0, 300)\n" in shown
    code, shown = run("diff", uis2, new, "--no-layout")
    assert "End moved" not in shown and "TurnLeft_1.tolerance" in shown


def test_exit_code_fails_only_when_a_guarded_part_changes(uis2: Path, edited) -> None:
    new = edited(_tolerance_and_move)
    assert run("diff", uis2, new, "--exit-code", "actors")[0] == 0
    assert run("diff", uis2, new, "--exit-code", "root")[0] == 0
    assert run("diff", uis2, new, "--exit-code", "TurnLeft_1")[0] == 1
    assert run("diff", uis2, new, "--exit-code", "nodes")[0] == 1
    assert run("diff", uis2, new, "--exit-code", "any")[0] == 1
    assert run("diff", uis2, new, "--no-layout", "--exit-code", "layout")[0] == 0


def test_json_gives_parameter_values_in_the_editor_protocol_shape(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        actor(scenario, "ego").initialSpeed = params.span(4.0, 6.0)

    code, shown = run("diff", uis2, edited(edit), "--format", "json", "--exit-code", "actors")
    assert code == 1
    data = json.loads(shown)
    assert data["schemaVersion"] == 1
    assert data["summary"] == {
        "root": 0, "actors": 1, "nodes": 0, "modules": 0, "flows": 0, "layout": 0
    }  # fmt: skip
    (change,) = data["changes"]
    assert change["path"] == "ego.initialSpeed"
    assert change["old"] == {"type": "range", "min": 3.0, "max": 7.0, "step": 1.0}
    assert change["new"] == {"type": "range", "min": 4.0, "max": 6.0, "step": None}
    assert change["unit"] == "m/s"
    assert data["blocked"] == [change]


def test_junit_fails_the_guarded_changes_only(uis2: Path, edited) -> None:
    code, shown = run(
        "diff", uis2, edited(_tolerance_and_move), "--format", "junit", "--exit-code", "layout"
    )
    assert code == 1
    suite = etree.fromstring(shown.encode()).find("testsuite")
    assert suite is not None
    assert (suite.get("tests"), suite.get("failures")) == ("2", "1")
    failed = [case.get("name") for case in suite if case.find("failure") is not None]
    assert failed == ["~ End moved auto -> (0, 300)"]


def test_markdown_is_a_pull_request_comment(uis2: Path, edited, tmp_path: Path) -> None:
    out = tmp_path / "comment.md"
    assert run("diff", uis2, edited(_tolerance_and_move), "--format", "markdown", "-o", out)[0] == 0
    text = out.read_text()
    assert text.startswith("### Scenario changes")
    assert "#### Nodes\n\n- `~ TurnLeft_1.tolerance: 3 -> 4 m`\n" in text


def test_html_draws_marks_a_legend_and_the_list(uis2: Path, edited, tmp_path: Path) -> None:
    def edit(scenario: scm.Scenario) -> None:
        _tolerance_and_move(scenario)
        drive = node(scenario, "DriveDistance_1")
        for flow in [f for f in scenario.flows if drive in (f.source, f.target)]:
            scenario.flows.remove(flow)
        scenario.nodes.remove(drive)

    out = tmp_path / "diff.html"
    assert run("diff", uis2, edited(edit), "--format", "html", "-o", out)[0] == 0
    page = etree.parse(str(out), etree.HTMLParser())
    svg = page.find(".//section[@id='diagram']/svg")
    assert svg is not None
    classes = " ".join(g.get("class", "") for g in svg.iter("g"))
    # A changed box, a removed ghost, two removed arrows (into and out of DriveDistance_1).
    assert classes.count("sceml-diff-changed") == 1
    assert classes.count("sceml-diff-removed") == 3
    marks = [t.text for t in svg.iter("text") if t.text and t.text[0] in "+~-"]
    assert "~ changed" in marks and "- removed" in marks
    legend = [" ".join(item.itertext()) for item in page.iterfind(".//div[@role='listitem']")]
    assert len(legend) == 3 and "+ added" in legend[0]
    listed = [li.text for li in page.iterfind(".//section[@id='changes']//li")]
    assert "~ TurnLeft_1.tolerance: 3 -> 4 m" in listed
    assert "- DriveDistance_1 (DriveDistance) removed" in listed


def test_render_diff_writes_the_marked_diagram(uis2: Path, edited, tmp_path: Path) -> None:
    out = tmp_path / "diff.svg"
    code, _ = run("render", edited(_tolerance_and_move), "--diff", uis2, "-o", out)
    assert code == 0
    svg = etree.parse(str(out)).getroot()
    classes = [g.get("class", "") for g in svg.iter("{http://www.w3.org/2000/svg}g")]
    texts = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}text")]
    # The changed TurnLeft_1 box, and the legend's sample for changes.
    assert sum("sceml-diff-changed" in c for c in classes) == 2
    assert "Changes" in texts
    assert run("render", uis2, "--diff", uis2, "--view", "bt", "-o", out)[0] == 2


def test_unreadable_input_is_a_usage_error(uis2: Path, tmp_path: Path) -> None:
    broken = tmp_path / "broken.xmi"
    broken.write_text("<not-xmi")
    assert run("diff", uis2, broken)[0] == 2
    assert run("diff", uis2)[0] == 2

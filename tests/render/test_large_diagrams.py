"""Diagrams too large to read or lay out are refused quickly, not left to exhaust Graphviz."""

from __future__ import annotations

import sys
from pathlib import Path

import graphviz
import pytest
from click.testing import CliRunner

import sceml.review.page as report_module
from sceml.cli import cli
from sceml.model.loading import load, load_library
from sceml.render import DiagramTooLargeError, diagram, drawn_nodes
from sceml.review.page import build_report

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "benchmarks"))
from scale_scenarios import write  # noqa: E402

EXAMPLES = REPO / "examples"


@pytest.fixture(scope="module")
def big(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A generated scenario of about 600 nodes on the real map (with the library and the map it
    names beside it), on disk."""
    return write(600, tmp_path_factory.mktemp("big"))


def test_a_diagram_above_the_limit_is_refused_before_anything_is_drawn(
    big: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    root = load(big).root
    count = drawn_nodes(root, "collapsed")
    assert count == len(root.nodes)
    drawn: list[object] = []
    monkeypatch.setattr(graphviz.Digraph, "node", lambda self, *a, **k: drawn.append(a))
    with pytest.raises(DiagramTooLargeError, match=f"{count:,} boxes, more than the 500"):
        diagram(root, max_nodes=500)
    assert drawn == []  # refused before a single box was made
    assert diagram(root, max_nodes=count) is not None
    assert len(drawn) >= count  # with the limit raised, every box is made


def test_expanded_module_uses_count_their_definitions() -> None:
    root = load(EXAMPLES / "uis2-concrete.xmi").root
    crossing = load_library(EXAMPLES / "library" / "sceml-library.xmi").root
    definition = next(m for m in crossing.modules if m.name == "CrossingManeuver")
    assert drawn_nodes(root, "collapsed") == len(root.nodes)
    assert drawn_nodes(root, "expanded") == len(root.nodes) + len(definition.nodes)


def test_render_refuses_with_exit_1_and_writes_nothing(big: Path, tmp_path: Path) -> None:
    out = tmp_path / "big.svg"
    result = CliRunner().invoke(cli, ["render", str(big), "-o", str(out), "--max-nodes", "500"])
    assert result.exit_code == 1, result.output
    assert "--max-nodes" in result.output and "boxes" in result.output
    assert not out.exists()


def test_the_report_omits_the_diagram_and_keeps_its_tables(
    big: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(report_module, "MAX_DIAGRAM_NODES", 500)
    html = build_report(load(big), [])
    assert "Diagram omitted:" in html and "<svg" not in html.split("<h2>Diagram</h2>")[1][:500]
    assert "<h2>Parameters</h2>" in html or "Parameters" in html

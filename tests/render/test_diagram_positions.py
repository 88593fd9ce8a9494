"""Diagram positions (the editor's layout) are notation: no label, table or export shows them."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

import scemlmodel as scm
from sceml.export import export
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.modules.library import describe_features
from sceml.render.labels import Scope, parameter_items


def _place_every_node(graph: scm.Graph) -> None:
    for index, node in enumerate(graph.nodes):
        node.diagramPosition = scm.DiagramPosition(x=float(index * 100), y=-40.5)


def test_positions_are_saved_but_never_shown_or_exported(examples_copy: Path) -> None:
    path = examples_copy / "uis2-concrete.xmi"
    before = export(load(path).root, date="2026-01-01T00:00:00")
    document = load(path)
    _place_every_node(document.root)
    save(document.root, path)
    assert b"diagramPosition" in path.read_bytes()

    reloaded = load(path)
    placed = [n for n in reloaded.root.nodes if n.diagramPosition is not None]
    assert len(placed) == len(reloaded.root.nodes)
    assert reloaded.root.nodes[2].diagramPosition.x == 200.0
    for node in reloaded.root.nodes:
        assert "diagramPosition" not in dict(parameter_items(node, Scope()))
        assert "diagramPosition" not in describe_features(node)
    after = export(reloaded.root, date="2026-01-01T00:00:00")
    assert etree.tostring(after) == etree.tostring(before)

"""Copy and paste: deep copies of nodes and the flows among them, pasted under fresh names."""

from __future__ import annotations

import re
from typing import Any

import scemlmodel as scm

from ..model.copying import Copier
from ..modules import naming
from .context import Clipboard, EditContext, require
from .node_ops import FIXED, _coordinates, adopt

_NUMBERED = re.compile(r"_\d+$")


def copy_nodes(graph: scm.Graph, nodes: list[scm.GraphElement]) -> Clipboard:
    """Deep copies of `nodes` (root, end and ports left out) and the flows among them."""
    chosen = [node for node in dict.fromkeys(nodes) if not isinstance(node, FIXED)]
    copier = Copier()
    copies = copier.copy_all(chosen)
    copier.copy_references()
    index = {node: position for position, node in enumerate(chosen)}
    pairs = [
        (index[flow.source], index[flow.target])
        for flow in graph.flows
        if flow.source in index and flow.target in index
    ]
    return Clipboard(copies, pairs)


def _fresh_name(name: str, taken: set[str]) -> str:
    if name not in taken:
        return name
    return naming.numbered(_NUMBERED.sub("", name) or "Node", taken)


def paste(ctx: EditContext, op: dict[str, Any]) -> None:
    """Add copies of the clipboard's nodes, renamed unique, moved by `offset`, with their flows."""
    require(bool(ctx.clipboard.nodes), "nothing has been copied")
    dx, dy = _coordinates(op.get("offset") or {"x": 40, "y": 40})
    copier = Copier()
    pasted = copier.copy_all(ctx.clipboard.nodes)
    copier.copy_references()
    taken = ctx.node_names()
    for node in pasted:
        node.name = _fresh_name(str(node.name), taken)
        taken.add(node.name)
        if node.diagramPosition is not None:
            node.diagramPosition.x += dx
            node.diagramPosition.y += dy
        adopt(ctx, node)
    for source, target in ctx.clipboard.flows:
        flow = scm.Flow()
        ctx.rec.insert(ctx.graph, "flows", flow)
        ctx.rec.set(flow, "source", pasted[source])
        ctx.rec.set(flow, "target", pasted[target])
        ctx.ids.of(flow, "f")

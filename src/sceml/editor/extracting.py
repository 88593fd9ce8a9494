"""The extract_module operation: selected nodes become a library module, used in their place.

The module is built by `sceml.modules.extract.plan_extraction` (on a copy of the scenario) and
written to its library at once; undo puts the library file back as it was (and redo writes it
again). The live scenario is then changed as the Extraction says, through the recorder like
any other edit, so undo gives back the very same nodes and flows.
"""

from __future__ import annotations

from typing import Any

import scemlmodel as scm

from ..errors import SceMLError
from ..files.writing import write_atomically
from ..model.saving import save
from ..modules.extract import Extraction, plan_extraction
from .context import EditContext, argument, check_text, require
from .errors import OperationError
from .node_ops import detach_flow


def extract_module(ctx: EditContext, op: dict[str, Any]) -> None:
    """Move the selected nodes into a new module of a library file and use it instead."""
    require(isinstance(ctx.graph, scm.Scenario), "modules are extracted from a scenario")
    chosen, name, library_text = (argument(op, key) for key in ("nodes", "name", "library"))
    require(isinstance(chosen, list), "'nodes' must be a list of node ids")
    require(isinstance(name, str) and name.strip() != "", "the module needs a name")
    require(isinstance(library_text, str) and library_text != "", "'library' must name a file")
    check_text("name", name)
    nodes = [ctx.node(i) for i in chosen]
    library, path = ctx.find_library(library_text, True)
    previous = path.read_bytes() if path.is_file() else None
    try:
        extraction = plan_extraction(ctx.graph, [str(node.name) for node in nodes], name, library)
    except SceMLError as error:
        _forget(library, name)
        raise OperationError(error.message) from None
    definition = extraction.use.definition

    def write() -> None:
        if definition not in library.modules:
            library.modules.append(definition)
        try:
            save(library, path)
        except SceMLError as error:
            _forget(library, name)
            raise OperationError(error.message) from None

    def unwrite() -> None:
        # Undo puts the library file back as it was: without the module, or not there at all.
        _forget(library, name)
        if previous is None:
            path.unlink(missing_ok=True)
        else:
            write_atomically(path, previous)

    ctx.rec.outside(library, write, unwrite)
    _replace(ctx, extraction)


def _forget(library: scm.Library, name: str) -> None:
    for definition in list(library.modules):
        if definition.name == name:
            library.modules.remove(definition)


def _replace(ctx: EditContext, extraction: Extraction) -> None:
    """Apply the extraction to the live scenario through the recorder, so that undo gives back
    the very same nodes and flows."""
    nodes, use = extraction.region.nodes, extraction.use
    # Drawn where the selection was, at the middle of its nodes.
    placed = [n.diagramPosition for n in nodes if n.diagramPosition is not None]
    if placed:
        x = sum(p.x for p in placed) / len(placed)
        y = sum(p.y for p in placed) / len(placed)
        use.diagramPosition = scm.DiagramPosition(x=x, y=y)
    members = set(nodes)
    for flow in [f for f in ctx.graph.flows if f.source in members or f.target in members]:
        detach_flow(ctx, flow)
    for node in nodes:
        ctx.rec.remove(ctx.graph, "nodes", node)
    ctx.rec.insert(ctx.graph, "nodes", use, extraction.position)
    ctx.created.append(ctx.ids.of(use, "n"))
    for start, end in extraction.connections():
        flow = scm.Flow()
        ctx.rec.insert(ctx.graph, "flows", flow)
        ctx.rec.set(flow, "source", start)
        ctx.rec.set(flow, "target", end)
        ctx.ids.of(flow, "f")

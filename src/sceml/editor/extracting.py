"""The extract_module operation: selected nodes become a library module, used in their place.

The module is built by `sceml.modules.extract` on a copy of the scenario and written to its
library at once; undo puts the library file back as it was (and redo writes it again). The live scenario is then changed
through the recorder like any other edit, so undo gives back the very same nodes and flows.
"""

from __future__ import annotations

from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..errors import SceMLError
from ..files.writing import write_atomically
from ..model.copying import Copier
from ..model.saving import save
from ..modules.extract import extract, find_region
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
        region = find_region(ctx.graph, nodes)
        built = _build_module(ctx.graph, nodes, name, library)
    except SceMLError as error:
        _forget(library, name)
        raise OperationError(error.message) from None
    definition = built[2]

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
    _replace(ctx, region.nodes, region.source, region.targets, built)


def _build_module(
    scenario: scm.Scenario, nodes: list[scm.GraphElement], name: str, library: scm.Library
) -> tuple[str, list[tuple[str, EObject]], scm.ModuleDefinition]:
    """Run extract on a copy; the use's name and bindings (to live actors), the new definition."""
    copier = Copier()
    duplicate = copier.copy(scenario)
    copier.copy_references()
    live = {copy: original for original, copy in copier.copies.items()}
    use = extract(duplicate, [str(node.name) for node in nodes], name, library)
    bindings = [(str(b.role), live.get(b.actor, b.actor)) for b in use.bindings]
    return str(use.name), bindings, use.definition


def _forget(library: scm.Library, name: str) -> None:
    for definition in list(library.modules):
        if definition.name == name:
            library.modules.remove(definition)


def _replace(
    ctx: EditContext,
    nodes: list[scm.GraphElement],
    source: scm.GraphElement,
    targets: list[scm.GraphElement],
    built: tuple[str, list[tuple[str, EObject]], scm.ModuleDefinition],
) -> None:
    use_name, bindings, definition = built
    use = scm.ModuleUse(name=use_name)
    use.definition = definition
    for role, actor in bindings:
        use.bindings.append(scm.RoleBinding(role=role, actor=actor))
    placed = [n.diagramPosition for n in nodes if n.diagramPosition is not None]
    if placed:
        x = sum(p.x for p in placed) / len(placed)
        y = sum(p.y for p in placed) / len(placed)
        use.diagramPosition = scm.DiagramPosition(x=x, y=y)
    index = min(list(ctx.graph.nodes).index(n) for n in nodes)
    members = set(nodes)
    for flow in [f for f in ctx.graph.flows if f.source in members or f.target in members]:
        detach_flow(ctx, flow)
    for node in nodes:
        ctx.rec.remove(ctx.graph, "nodes", node)
    ctx.rec.insert(ctx.graph, "nodes", use, index)
    ctx.created.append(ctx.ids.of(use, "n"))
    for start, end in [(source, use), *((use, target) for target in targets)]:
        flow = scm.Flow()
        ctx.rec.insert(ctx.graph, "flows", flow)
        ctx.rec.set(flow, "source", start)
        ctx.rec.set(flow, "target", end)
        ctx.ids.of(flow, "f")

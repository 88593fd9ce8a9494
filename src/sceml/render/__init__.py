"""Diagrams of scenarios and module libraries: the SceML flow notation and the behavior-tree view.

graph = diagram(load("uis2-logical.xmi").root, view="flow", modules="expanded")
data = to_bytes(graph, "svg")
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pyecore.ecore import EProxy

import scemlmodel as scm

from .bt import bt_diagram
from .flow import Diagram, Modules, RenderError, flow_diagram
from .style import legend_graph

if TYPE_CHECKING:
    import graphviz  # imported where a graph is drawn: the preview page only reads styles

View = Literal["flow", "bt"]

#: Output formats, by file suffix.
FORMATS = ("svg", "png", "pdf")

__all__ = [
    "FORMATS",
    "MAX_DIAGRAM_NODES",
    "Diagram",
    "DiagramTooLargeError",
    "ModuleChoiceError",
    "RenderError",
    "diagram",
    "drawn_nodes",
    "flow_diagram",
    "legend_graph",
    "select_module",
    "to_bytes",
]


class ModuleChoiceError(RenderError):
    """A library was given without naming one of its modules, or with a name it does not hold."""

    exit_code = 2


def select_module(library: scm.Library, name: str | None) -> scm.ModuleDefinition:
    """The library's module called `name`; the error lists the names it holds."""
    names = [str(module.name) for module in library.modules]
    for module in library.modules:
        if name is not None and module.name == name:
            return module
    listed = ", ".join(names) or "(none)"
    if name is None:
        raise ModuleChoiceError(f"this is a module library; choose a module to draw: {listed}")
    raise ModuleChoiceError(f"the library has no module {name!r}; it holds: {listed}")


class DiagramTooLargeError(RenderError):
    """A diagram with more boxes than a person can read, and than Graphviz lays out in seconds."""


#: Boxes above which a diagram is refused: Graphviz's `dot` takes about 3 s for 5,000 boxes
#: of a flow, 20 s for 10,000 and runs out of memory near 50,000 (benchmarks in issue 17).
MAX_DIAGRAM_NODES = 5000


def drawn_nodes(target: scm.Graph, modules: Modules) -> int:
    """How many boxes a diagram of `target` has: its nodes, plus, when module uses are drawn
    expanded, the nodes of each use's definition (recursively)."""
    count = 0
    pending: list[scm.Graph] = [target]
    while pending:
        graph = pending.pop()
        count += len(graph.nodes)
        if modules != "expanded":
            continue
        for node in graph.nodes:
            if isinstance(node, scm.ModuleUse):
                try:
                    definition = node.definition
                    if isinstance(definition, EProxy):
                        definition = definition.force_resolve()
                except Exception:  # a broken use is drawn as one box; its error is reported
                    continue
                if isinstance(definition, scm.ModuleDefinition):
                    pending.append(definition)
    return count


def diagram(
    root: scm.Scenario | scm.Library,
    *,
    view: View = "flow",
    modules: Modules = "collapsed",
    legend: bool = False,
    module: str | None = None,
    max_nodes: int = MAX_DIAGRAM_NODES,
) -> graphviz.Digraph:
    """The Graphviz graph of a scenario, or of one module of a library, in the chosen view.

    DiagramTooLargeError when it would have more than `max_nodes` boxes.
    """
    target: scm.Scenario | scm.ModuleDefinition
    if isinstance(root, scm.Library):
        target = select_module(root, module)
    elif module is not None:
        raise ModuleChoiceError("--module applies to module libraries, not to scenarios")
    else:
        target = root
    boxes = drawn_nodes(target, modules)
    if boxes > max_nodes:
        raise DiagramTooLargeError(
            f"the diagram would have {boxes:,} boxes, more than the {max_nodes:,} a person can "
            "read and Graphviz lays out in seconds; draw one module of it, collapse module uses, "
            "or raise the limit with --max-nodes (Graphviz needs minutes and gigabytes near "
            "50,000)"
        )
    if view == "bt":
        return bt_diagram(target, modules=modules, legend=legend)
    return flow_diagram(target, modules=modules, legend=legend).graph


def to_bytes(graph: graphviz.Digraph, fmt: str) -> bytes:
    """Lay out and render with Graphviz's `dot`; RenderError if it is missing or fails."""
    if fmt not in FORMATS:
        raise RenderError(f"unknown output format {fmt!r}; use one of {', '.join(FORMATS)}")
    import graphviz

    try:
        picture: bytes = graph.pipe(format=fmt)
        return picture
    except graphviz.ExecutableNotFound:
        raise RenderError(
            "Graphviz's `dot` program is not installed (Debian: apt-get install graphviz)"
        ) from None
    except graphviz.CalledProcessError as error:
        message = (error.stderr or b"").decode(errors="replace").strip()
        raise RenderError(f"Graphviz failed: {message or error}") from None

"""Diagrams of scenarios and module libraries: the SceML flow notation and the behavior-tree view.

graph = diagram(load("uis2-logical.xmi").root, view="flow", modules="expanded")
data = to_bytes(graph, "svg")
"""

from __future__ import annotations

from typing import Literal

import graphviz

import scemlmodel as scm

from .bt import bt_diagram
from .flow import Diagram, Modules, RenderError, flow_diagram
from .style import legend_graph

View = Literal["flow", "bt"]

#: Output formats, by file suffix.
FORMATS = ("svg", "png", "pdf")

__all__ = [
    "FORMATS",
    "Diagram",
    "ModuleChoiceError",
    "RenderError",
    "diagram",
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


def diagram(
    root: scm.Scenario | scm.Library,
    *,
    view: View = "flow",
    modules: Modules = "collapsed",
    legend: bool = False,
    module: str | None = None,
) -> graphviz.Digraph:
    """The Graphviz graph of a scenario, or of one module of a library, in the chosen view."""
    target: scm.Scenario | scm.ModuleDefinition
    if isinstance(root, scm.Library):
        target = select_module(root, module)
    elif module is not None:
        raise ModuleChoiceError("--module applies to module libraries, not to scenarios")
    else:
        target = root
    if view == "bt":
        return bt_diagram(target, modules=modules, legend=legend)
    return flow_diagram(target, modules=modules, legend=legend).graph


def to_bytes(graph: graphviz.Digraph, fmt: str) -> bytes:
    """Lay out and render with Graphviz's `dot`; RenderError if it is missing or fails."""
    if fmt not in FORMATS:
        raise RenderError(f"unknown output format {fmt!r}; use one of {', '.join(FORMATS)}")
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

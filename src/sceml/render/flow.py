"""The flow view: a scenario or module definition drawn in the SceML notation with Graphviz.

Every drawn element gets an SVG id derived from its EMF URI fragment (`//@nodes.3` -> `nodes.3`;
inside an expanded module use, the use's id, a slash, then the fragment of the element inside its
library, e.g. `nodes.9/modules.0/nodes.2`). `Diagram.ids` maps model objects to those ids, which is
how the HTML report links diagnostics to nodes.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal

from pyecore.ecore import EObject

import scemlmodel as scm

from ..errors import SceMLError
from ..model import catalog
from ..model.graph import finishes_with_first
from ..model.locating import uri_fragment
from . import style
from .labels import (
    Scope,
    action_lines,
    bound_actor,
    definition_lines,
    loaded_definition,
    root_lines,
    scenario_title,
    use_lines,
)

if TYPE_CHECKING:
    import graphviz

Modules = Literal["collapsed", "expanded"]

#: Extra Graphviz attributes for the boxes and arrows of some model objects.
Marks = Mapping[EObject, Mapping[str, str]]


class RenderError(SceMLError):
    """A diagram cannot be produced (Graphviz missing or failing, a view that does not apply)."""


def dom_id(obj: EObject, prefix: str = "") -> str:
    """The SVG id of a model element: its URI fragment without `//@`, under an optional prefix."""
    fragment = uri_fragment(obj).removeprefix("//").replace("/@", "/").removeprefix("@")
    return prefix + (fragment or "root")


@dataclass
class Diagram:
    """A Graphviz graph and, for each drawn model object, the SVG ids that show it."""

    graph: graphviz.Digraph
    ids: dict[EObject, list[str]] = field(default_factory=dict)

    def remember(self, obj: EObject, element_id: str) -> None:
        """Record that `element_id` shows `obj` (a module internal can be shown more than once)."""
        self.ids.setdefault(obj, []).append(element_id)


def new_digraph(name: str) -> graphviz.Digraph:
    """An empty top-to-bottom digraph with the notation's fonts and spacing."""
    import graphviz  # here, not above: importing the render package must not cost a diagram

    graph = graphviz.Digraph(name, graph_attr=style.GRAPH_ATTRIBUTES)
    graph.node_attr.update(style.NODE_ATTRIBUTES)
    graph.edge_attr.update(style.EDGE_ATTRIBUTES)
    return graph


def look_of(node: EObject) -> style.Look:
    """The look of a graph element by its metaclass and, for action nodes, its category."""
    if isinstance(node, scm.ActionNode):
        category = catalog.category(node) or ""
        return (
            style.OPAQUE
            if category == "opaque"
            else style.CATEGORY_LOOKS.get(category, style.UNKNOWN)
        )
    looks = {
        scm.RootNode: style.ROOT,
        scm.EndNode: style.END,
        scm.JoinAllFinished: style.JOIN_ALL,
        scm.JoinOneFinished: style.JOIN_ONE,
        scm.InPort: style.IN_PORT,
        scm.OutPort: style.OUT_PORT,
        scm.ModuleUse: style.MODULE,
    }
    return next((look for cls, look in looks.items() if isinstance(node, cls)), style.UNKNOWN)


def flow_diagram(
    root: scm.Scenario | scm.ModuleDefinition | scm.Library,
    *,
    modules: Modules = "collapsed",
    legend: bool = False,
    marks: Marks | None = None,
) -> Diagram:
    """Draw a scenario, a module definition on its own (framed, with its ports) or a whole library.

    `marks` adds Graphviz attributes to the boxes and arrows of some objects (what `sceml diff`
    marks as added or changed); style words are added to the box's own, not put in their place.
    """
    drawer = _FlowDrawer(modules, marks or {})
    if isinstance(root, scm.Library):
        for definition in root.modules:
            drawer.draw_definition(definition)
    elif isinstance(root, scm.ModuleDefinition):
        drawer.draw_definition(root)
    else:
        drawer.draw_graph(root, drawer.diagram.graph, Scope())
    if legend:
        style.add_legend(drawer.diagram.graph)
    return drawer.diagram


class _FlowDrawer:
    """Walks graphs and module uses, adding nodes, flows and clusters to one Graphviz graph."""

    def __init__(self, modules: Modules, marks: Marks) -> None:
        self.modules = modules
        self.marks = marks
        self.diagram = Diagram(new_digraph("sceml"))
        # Where flows attach to a drawn node: an expanded use is entered at its in-port and
        # left at its out-port.
        self.entry: dict[str, str] = {}
        self.exit: dict[str, str] = {}

    def draw_graph(self, graph: scm.Graph, target: graphviz.Digraph, scope: Scope) -> None:
        """Draw every node, then every flow, of a scenario or definition into `target`."""
        for node in graph.nodes:
            self.draw_node(node, target, scope)
        for flow in graph.flows:
            self.draw_flow(flow, target, scope)

    def draw_definition(self, definition: scm.ModuleDefinition) -> None:
        """A library module alone: a frame titled with its name, roles and parameters."""
        lines = definition_lines(definition)
        label = style.html_label(str(definition.name), lines, subtitle="module definition")
        self._cluster(definition, label, Scope(chain=(definition,)), dom_id(definition))

    def draw_node(self, node: EObject, target: graphviz.Digraph, scope: Scope) -> None:
        """One graph element: a box, a join or end symbol, a port, or a module use."""
        if isinstance(node, scm.ModuleUse):
            self.draw_use(node, target, scope)
            return
        element_id = dom_id(node, scope.prefix)
        attributes = look_of(node).attrs()
        attributes["id"] = element_id
        attributes["tooltip"] = str(node.name or node.eClass.name)
        if isinstance(node, scm.ActionNode):
            # Kind, then the name messages and --set paths use, then actors and parameters.
            attributes["label"] = style.html_label(
                node.eClass.name,
                action_lines(node, scope),
                subtitle=str(node.name) if node.name else None,
            )
            actor = bound_actor(node.referenceActor, scope)
            if actor:
                attributes["class"] += f" sceml-actor-{actor}"
        elif isinstance(node, scm.RootNode):
            scenario = node.eContainer()
            attributes["label"] = style.html_label(
                scenario_title(scenario), root_lines(node, scenario)
            )
        elif isinstance(node, scm.EndNode):
            one = finishes_with_first(node)
            attributes["label"] = "End ?" if one else "End"
        attributes.setdefault("label", str(node.name or node.eClass.name))
        _mark(attributes, self.marks.get(node))
        target.node(element_id, **attributes)
        self.diagram.remember(node, element_id)
        self.entry[element_id] = self.exit[element_id] = element_id

    def draw_flow(self, flow: scm.Flow, target: graphviz.Digraph, scope: Scope) -> None:
        """A flow as an arrow; dangling flows are left out (validation reports them)."""
        if flow.source is None or flow.target is None:
            return
        source = self.exit.get(dom_id(flow.source, scope.prefix))
        sink = self.entry.get(dom_id(flow.target, scope.prefix))
        if source is None or sink is None:
            return
        element_id = dom_id(flow, scope.prefix)
        attributes = {"class": "sceml-flow"}
        _mark(attributes, self.marks.get(flow))
        target.edge(source, sink, id=element_id, **attributes)
        self.diagram.remember(flow, element_id)

    def draw_use(self, use: scm.ModuleUse, target: graphviz.Digraph, scope: Scope) -> None:
        """A module use: collapsed into one box, or expanded into a frame with its ports."""
        element_id = dom_id(use, scope.prefix)
        definition = loaded_definition(use)
        if definition is None:
            self._collapsed(use, target, scope, "definition not found", style.BROKEN_MODULE)
            return
        if any(definition is seen for seen in scope.chain):
            self._collapsed(use, target, scope, "recursive use", style.BROKEN_MODULE)
            return
        if self.modules == "collapsed":
            self._collapsed(use, target, scope, None, style.MODULE)
            return
        inner = inner_scope(use, definition, scope, f"{element_id}/")
        title = f"{use.name}: {definition.name}"
        label = style.html_label(title, use_lines(use, scope))
        self._cluster(definition, label, inner, element_id, target=target)
        self.diagram.remember(use, element_id)
        ports = _ports(definition)
        if ports[0] is not None:
            self.entry[element_id] = dom_id(ports[0], inner.prefix)
        if ports[1] is not None:
            self.exit[element_id] = dom_id(ports[1], inner.prefix)

    def _collapsed(
        self,
        use: scm.ModuleUse,
        target: graphviz.Digraph,
        scope: Scope,
        problem: str | None,
        look: style.Look,
    ) -> None:
        element_id = dom_id(use, scope.prefix)
        definition = loaded_definition(use)
        name = str(definition.name) if definition is not None and problem is None else str(use.name)
        attributes = look.attrs()
        attributes["id"] = element_id
        attributes["tooltip"] = str(use.name)
        attributes["label"] = style.html_label(
            name, use_lines(use, scope), subtitle=problem or "module"
        )
        _mark(attributes, self.marks.get(use))
        target.node(element_id, **attributes)
        self.diagram.remember(use, element_id)
        self.entry[element_id] = self.exit[element_id] = element_id

    def _cluster(
        self,
        definition: scm.ModuleDefinition,
        label: str,
        scope: Scope,
        element_id: str,
        target: graphviz.Digraph | None = None,
    ) -> None:
        parent = target if target is not None else self.diagram.graph
        # Graphviz only frames subgraphs whose name starts with "cluster".
        with parent.subgraph(name=f"cluster_{element_id}") as cluster:
            cluster.attr(label=label, id=element_id, **style.CLUSTER_ATTRIBUTES)
            self.draw_graph(definition, cluster, scope)
        self.diagram.remember(definition, element_id)


def _mark(attributes: dict[str, str], mark: Mapping[str, str] | None) -> None:
    """Add a mark's attributes; its style words and class go beside the element's own."""
    for key, value in (mark or {}).items():
        joiner = {"style": ",", "class": " "}.get(key)
        held = attributes.get(key)
        attributes[key] = f"{held}{joiner}{value}" if joiner and held else value


def _ports(definition: scm.ModuleDefinition) -> tuple[scm.InPort | None, scm.OutPort | None]:
    in_port = next((n for n in definition.nodes if isinstance(n, scm.InPort)), None)
    out_port = next((n for n in definition.nodes if isinstance(n, scm.OutPort)), None)
    return in_port, out_port


def inner_scope(
    use: scm.ModuleUse, definition: scm.ModuleDefinition, outer: Scope, prefix: str
) -> Scope:
    """The scope inside a use: roles bound to actor names, parameters to the values given."""
    bindings = {binding.role: binding.actor for binding in use.bindings}
    roles: dict[EObject, str] = {}
    for role in definition.roles:
        actor = bound_actor(bindings.get(role.name), outer)
        if actor:
            roles[role] = actor
    overrides = {override.parameter: override.value for override in use.overrides}
    values: dict[EObject, scm.ParameterValue | None] = {}
    for parameter in definition.parameters:
        given = overrides.get(parameter.name, parameter.default)
        if isinstance(given, scm.ParameterRef) and given.parameter in outer.parameters:
            given = outer.parameters[given.parameter]
        values[parameter] = given
    return Scope(roles, values, (*outer.chain, definition), prefix)

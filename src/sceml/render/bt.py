"""The behavior-tree view: a scenario's flow graph as sequence, parallel-all and parallel-one nodes.

The flow graph is turned into a tree by series-parallel reduction, with the root node as source
and the end node as sink (an in-port and out-port inside an expanded module). Every flow starts as
an edge carrying an empty sequence; then, until one edge from source to sink is left:

- series: a node with one incoming and one outgoing edge is removed, and the two edges become one
  carrying `first + [node] + second` (join nodes add nothing: their policy lives in the parallel);
- parallel: several edges between the same two nodes become one carrying a parallel node whose
  policy is that of the node they meet at (join-all, join-one, or the end node's policy). Because
  policies are associative, merging some of a join's inputs first does not change the meaning.

A graph that is not series-parallel (two branches cross-linked through a join) gets stuck. Then
the first stuck join J (in topological order) is cut: its incoming edges are redirected to the
sink, so those branches end there, and J is reached from the source through a `wait` leaf that
waits until J's predecessors have finished (all or one of them). This is exact when the end node
joins all; under a join-one end the cut branches also count as finishing paths. The tree is then
flagged as not series-parallel and the diagram says so.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.graph import (
    finishes_with_first,
    predecessors,
    reachable,
    successors,
    topological_order,
)
from . import style
from .flow import Modules, RenderError, dom_id, inner_scope, look_of, new_digraph
from .labels import Scope, actor_line, loaded_definition, scenario_title

if TYPE_CHECKING:
    import graphviz

Policy = Literal["all", "one"]


@dataclass
class Leaf:
    """A maneuver, condition or collapsed module use."""

    node: EObject


@dataclass
class Wait:
    """A synchronisation leaf standing for a cut join: wait until all/one of `on` have finished."""

    join: EObject
    policy: Policy
    on: list[EObject]


@dataclass
class Parallel:
    """Children run together; it finishes when all (or one) of them have."""

    policy: Policy
    children: list[list[Item]]


@dataclass
class Module:
    """An expanded module use: its inner tree, framed under the use's name."""

    use: scm.ModuleUse
    definition: scm.ModuleDefinition
    body: list[Item]
    scope: Scope


Item = Leaf | Wait | Parallel | Module


@dataclass
class Tree:
    """The behavior tree of one graph: a sequence of items, and whether the graph was series-parallel."""

    items: list[Item]
    series_parallel: bool = True
    left_out: list[EObject] = field(default_factory=list)


@dataclass
class _Edge:
    source: EObject
    target: EObject
    items: list[Item]
    # Where the edge's first flow sits in the model, so parallel branches keep the model's order.
    rank: int


def _policy(node: EObject) -> Policy:
    return "one" if finishes_with_first(node) else "all"


def tree_of(graph: scm.Graph, modules: Modules = "collapsed", scope: Scope | None = None) -> Tree:
    """Reduce a scenario (or module definition) to a behavior tree; RenderError if it is cyclic."""
    source, sink = _terminals(graph)
    _, cyclic = topological_order(graph)
    if cyclic:
        names = ", ".join(sorted(str(n.name) for n in cyclic))
        raise RenderError(f"the behavior-tree view needs an acyclic graph; cycle through {names}")
    on_path = reachable([source]) & reachable([sink], backwards=True)
    left_out = [node for node in graph.nodes if node not in on_path]
    nodes = [n for n in graph.nodes if n in on_path]
    reducer = _Reducer(source, sink, nodes, modules, scope or Scope())
    return Tree(reducer.reduce(), reducer.series_parallel, left_out)


def _terminals(graph: scm.Graph) -> tuple[EObject, EObject]:
    kinds = (scm.InPort, scm.OutPort) if isinstance(graph, scm.ModuleDefinition) else None
    start_kind, stop_kind = kinds or (scm.RootNode, scm.EndNode)
    source = next((n for n in graph.nodes if isinstance(n, start_kind)), None)
    sink = next((n for n in graph.nodes if isinstance(n, stop_kind)), None)
    if source is None or sink is None:
        raise RenderError(
            f"the behavior-tree view needs a {start_kind.__name__} and an {stop_kind.__name__}"
        )
    return source, sink


class _Reducer:
    """Series-parallel reduction over edges that carry partial trees."""

    def __init__(
        self, source: EObject, sink: EObject, nodes: list[EObject], modules: Modules, scope: Scope
    ) -> None:
        self.source, self.sink, self.nodes = source, sink, nodes
        self.modules, self.scope = modules, scope
        self.series_parallel = True
        members = set(nodes)
        self.edges = [
            _Edge(node, after, [], rank)
            for rank, (node, after) in enumerate(
                (node, after) for node in nodes for after in successors(node) if after in members
            )
        ]

    def reduce(self) -> list[Item]:
        while not self._done():
            if self._series() or self._parallel():
                continue
            self._cut()
        return self.edges[0].items if self.edges else []

    def _done(self) -> bool:
        return len(self.edges) <= 1

    def _series(self) -> bool:
        for node in self.nodes:
            if node is self.source or node is self.sink:
                continue
            into = [e for e in self.edges if e.target is node]
            out = [e for e in self.edges if e.source is node]
            if len(into) == 1 and len(out) == 1:
                first, second = into[0], out[0]
                merged = [*first.items, *self._items_of(node), *second.items]
                self.edges.remove(first)
                self.edges.remove(second)
                rank = min(first.rank, second.rank)
                self.edges.append(_Edge(first.source, second.target, merged, rank))
                self.nodes.remove(node)
                return True
        return False

    def _parallel(self) -> bool:
        groups: dict[tuple[int, int], list[_Edge]] = {}
        for edge in self.edges:
            groups.setdefault((id(edge.source), id(edge.target)), []).append(edge)
        for group in groups.values():
            if len(group) > 1:
                for edge in group:
                    self.edges.remove(edge)
                group.sort(key=lambda edge: edge.rank)
                children = [edge.items for edge in group if edge.items]
                items: list[Item] = [Parallel(_policy(group[0].target), children)]
                if len(children) <= 1:
                    items = children[0] if children else []
                rank = group[0].rank
                self.edges.append(_Edge(group[0].source, group[0].target, items, rank))
                return True
        return False

    def _cut(self) -> None:
        self.series_parallel = False
        stuck = next(
            node
            for node in self.nodes
            if node is not self.sink and sum(e.target is node for e in self.edges) > 1
        )
        for edge in [e for e in self.edges if e.target is stuck]:
            edge.target = self.sink
        waiting = Wait(stuck, _policy(stuck), predecessors(stuck))
        rank = min(e.rank for e in self.edges if e.source is stuck)
        self.edges.append(_Edge(self.source, stuck, [waiting], rank))

    def _items_of(self, node: EObject) -> list[Item]:
        if isinstance(node, scm.JoiningPolicy):
            return []
        if isinstance(node, scm.ModuleUse) and self.modules == "expanded":
            definition = loaded_definition(node)
            if definition is None or any(definition is seen for seen in self.scope.chain):
                return [Leaf(node)]
            scope = inner_scope(node, definition, self.scope, f"{dom_id(node, self.scope.prefix)}/")
            inner = tree_of(definition, self.modules, scope)
            self.series_parallel &= inner.series_parallel
            return [Module(node, definition, inner.items, scope)]
        return [Leaf(node)]


def bt_diagram(
    root: scm.Scenario | scm.ModuleDefinition,
    *,
    modules: Modules = "collapsed",
    legend: bool = False,
) -> graphviz.Digraph:
    """Draw a behavior tree: the scenario (or module) name on top, composite nodes as symbols.

    `legend` adds the behavior-tree view's legend (not the flow view's).
    """
    tree = tree_of(root, modules)
    graph = new_digraph("sceml_bt")
    graph.attr(ordering="out")
    if isinstance(root, scm.ModuleDefinition):
        title = f"module {root.name}"
    else:
        title = scenario_title(root)
    if not tree.series_parallel:
        title += " (not series-parallel: cut joins are shown as wait leaves)"
    graph.node("bt-root", label=title, **{**style.ROOT.attrs(), "class": "sceml-bt-root"})
    _Painter(graph, graph, Scope()).sequence(tree.items, "bt-root", "bt")
    if legend:
        style.add_legend(graph, style.BT_LEGEND_ENTRIES)
    return graph


class _Painter:
    """Adds tree nodes to a Graphviz graph; ids are positional (`bt.0.1`) and stable.

    Edges always go into the top-level graph: an edge written inside a module's frame would pull
    its parent node into the frame too.
    """

    def __init__(self, graph: graphviz.Digraph, top: graphviz.Digraph, scope: Scope) -> None:
        self.graph, self.top, self.scope = graph, top, scope

    def sequence(self, items: list[Item], parent: str, path: str) -> None:
        if len(items) == 1:
            self.item(items[0], parent, f"{path}.0")
            return
        node_id = f"{path}.seq"
        self._composite(node_id, style.BT_SEQUENCE, "Sequence")
        self.top.edge(parent, node_id)
        for index, item in enumerate(items):
            self.item(item, node_id, f"{path}.{index}")

    def item(self, item: Item, parent: str, path: str) -> None:
        if isinstance(item, Parallel):
            one = item.policy == "one"
            look = style.BT_PARALLEL_ONE if one else style.BT_PARALLEL_ALL
            self._composite(path, look, "Parallel: " + ("one" if one else "all"))
            self.top.edge(parent, path)
            for index, child in enumerate(item.children):
                self.sequence(child, path, f"{path}.{index}")
        elif isinstance(item, Module):
            self._module(item, parent, path)
        elif isinstance(item, Wait):
            self._wait(item, parent, path)
        else:
            self._leaf(item.node, parent, path)

    def _composite(self, node_id: str, look: style.Look, tooltip: str) -> None:
        self.graph.node(node_id, tooltip=tooltip, **look.attrs())

    def _leaf(self, node: EObject, parent: str, path: str) -> None:
        attributes = look_of(node).attrs()
        if isinstance(node, scm.ActionNode):
            lines = [actor_line(node, self.scope)]
            attributes["label"] = style.html_label(
                node.eClass.name, lines, subtitle=str(node.name) if node.name else None
            )
        elif isinstance(node, scm.ModuleUse):
            definition = loaded_definition(node)
            title = str(definition.name) if definition is not None else "definition not found"
            attributes["label"] = style.html_label(title, [str(node.name)])
        attributes.setdefault("label", str(node.name))
        attributes["id"] = f"{path}/{dom_id(node, self.scope.prefix)}"
        self.graph.node(attributes["id"], **attributes)
        self.top.edge(parent, attributes["id"])

    def _wait(self, item: Wait, parent: str, path: str) -> None:
        names = ", ".join(str(n.name) for n in item.on)
        attributes = style.BT_WAIT.attrs()
        attributes["label"] = f"wait for {item.policy} of\n{names}"
        self.graph.node(path, **attributes)
        self.top.edge(parent, path)

    def _module(self, item: Module, parent: str, path: str) -> None:
        with self.graph.subgraph(name=f"cluster_{path}") as frame:
            label = f"{item.use.name}: {item.definition.name}"
            frame.attr(label=label, **style.CLUSTER_ATTRIBUTES)
            _Painter(frame, self.top, item.scope).sequence(item.body, parent, path)

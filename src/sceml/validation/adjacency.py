"""A graph's own flows read once per validation run, for every rule that walks them.

The structure rules (S006 reachable from the start, S007 reaching the end, S008 no cycle) and
the map rules' departures (R006, R007: an actor's earlier nodes) each walked a scenario's flows
through pyecore's descriptors, node by node, several times per run: a tenth of a large
scenario's validation. The neighbours of every node are read here once per run and graph
(`Context.memo`) and shared; the walks themselves are unchanged.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.graph import predecessors, successors
from ..model.traversal import single_value, stored
from .context import Context


class OwnAdjacency:
    """A scenario's or module definition's nodes in reading order and each node's neighbours
    along its Flow objects, in flow order, dangling flows skipped: what `model.graph`'s
    `predecessors` and `successors` answer, read once. A `model.graph.Flows`.

    Neighbours outside the graph are kept (a flow may wrongly join two graphs, which S011
    reports); the walks that stay inside the graph filter by `members`.
    """

    __slots__ = ("_predecessors", "_successors", "members", "nodes")

    def __init__(self, graph: scm.Graph) -> None:
        self.nodes: Sequence[scm.GraphElement] = list(graph.nodes)
        self.members: set[EObject] = set(self.nodes)
        self._successors = {node: _ends(node, "outgoing", "target") for node in self.nodes}
        self._predecessors = {node: _ends(node, "incoming", "source") for node in self.nodes}

    def successors(self, node: EObject) -> list[EObject]:
        """Nodes `node` has a flow to (a node of another graph is read from its flows)."""
        found = self._successors.get(node)
        return found if found is not None else successors(node)

    def predecessors(self, node: EObject) -> list[EObject]:
        """Nodes with a flow into `node` (a node of another graph is read from its flows)."""
        found = self._predecessors.get(node)
        return found if found is not None else predecessors(node)


def _ends(node: EObject, flows: str, end: str) -> list[EObject]:
    held = stored(node, flows)
    if not held:
        return []
    return [other for flow in held if (other := single_value(flow, end)) is not None]


def own_adjacency(graph: scm.Graph, context: Context) -> OwnAdjacency:
    """The graph's `OwnAdjacency`, read once per validation run."""
    return context.memo(("own adjacency", graph), lambda: OwnAdjacency(graph))


def reached(adjacency: OwnAdjacency, starts: Iterable[EObject], *, backwards: bool) -> set[EObject]:
    """Nodes of the graph reachable from `starts` (included); flows leaving the graph are not
    followed."""
    step = adjacency.predecessors if backwards else adjacency.successors
    members = adjacency.members
    seen = set(starts)
    queue = deque(seen)
    while queue:
        for neighbour in step(queue.popleft()):
            if neighbour in members and neighbour not in seen:
                seen.add(neighbour)
                queue.append(neighbour)
    return seen


def left_by_kahn(adjacency: OwnAdjacency) -> set[EObject]:
    """The nodes Kahn's algorithm cannot order, because they lie on or after a cycle: the
    second part of `model.graph.topological_order`'s answer."""
    members = adjacency.members
    indegree = dict.fromkeys(adjacency.nodes, 0)
    for node in adjacency.nodes:
        for successor in adjacency.successors(node):
            if successor in members:
                indegree[successor] += 1
    queue = deque(node for node in adjacency.nodes if indegree[node] == 0)
    ordered: set[EObject] = set()
    while queue:
        node = queue.popleft()
        ordered.add(node)
        for successor in adjacency.successors(node):
            if successor in members:
                indegree[successor] -= 1
                if indegree[successor] == 0:
                    queue.append(successor)
    return members - ordered

"""Graph queries over scenarios and module definitions, shared by validation, export and render."""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Sequence
from typing import Any, Protocol, TypeVar

import scemlmodel as scm

N = TypeVar("N")


def predecessors(node: scm.GraphElement) -> list[scm.GraphElement]:
    """Nodes with a flow into `node`, in flow order; dangling flows are skipped."""
    return [flow.source for flow in node.incoming if flow.source is not None]


def successors(node: scm.GraphElement) -> list[scm.GraphElement]:
    """Nodes `node` has a flow to, in flow order; dangling flows are skipped."""
    return [flow.target for flow in node.outgoing if flow.target is not None]


def finishes_with_first(node: object) -> bool:
    """Whether `node` goes on once its first predecessor has finished, not all of them.

    True for a JoinOneFinished and for an end node with the joinOne policy; every other node
    waits for all its predecessors. The one statement of that rule: export, simulation, the
    diagrams, the editor and the player check all read it from here.
    """
    if isinstance(node, scm.EndNode):
        return node.policy is scm.JoinPolicy.joinOne
    return isinstance(node, scm.JoinOneFinished)


def nodes_of(graph: scm.Graph, kind: type[N]) -> list[N]:
    """The nodes of a graph that are instances of `kind`."""
    return [node for node in graph.nodes if isinstance(node, kind)]


def root_node(scenario: scm.Scenario) -> scm.RootNode | None:
    """The scenario's first RootNode, or None."""
    return next(iter(nodes_of(scenario, scm.RootNode)), None)


#: The level of a root node that names none, and of a new scenario: the metamodel's default.
DEFAULT_LEVEL = str(scm.RootNode.level.get_default_value().name)

#: How a level is shown where there is none to show (a scenario without a root node).
NO_LEVEL_TEXT = "?"


def root_level(root: scm.RootNode) -> str:
    """A root node's abstraction level: `functional`, `logical` or `concrete`.

    One set to nothing has the metamodel's default (`RootNode.level`, functional), as a file
    that leaves the attribute out does.
    """
    return str(root.level.name) if root.level is not None else DEFAULT_LEVEL


def scenario_level(scenario: scm.Scenario) -> str | None:
    """The scenario's abstraction level (its root node's), or None when it has no root node.

    The one reading of the level: validation, export, the preview, sampling, the diagrams and
    the editor all read it from here.
    """
    root = root_node(scenario)
    return root_level(root) if root is not None else None


def level_text(scenario: scm.Scenario) -> str:
    """The scenario's level as diagrams, messages and reports show it: NO_LEVEL_TEXT for none."""
    return scenario_level(scenario) or NO_LEVEL_TEXT


def end_node(scenario: scm.Scenario) -> scm.EndNode | None:
    """The scenario's first EndNode, or None."""
    return next(iter(nodes_of(scenario, scm.EndNode)), None)


def actors(scenario: scm.Scenario) -> list[scm.Actor]:
    """The actors declared in the scenario's root node."""
    root = root_node(scenario)
    return list(root.actors) if root is not None else []


class Flows(Protocol):
    """A graph to walk: its nodes in reading order, and each node's neighbours along flows.

    A scenario or module definition is one (`OwnFlows`); so is a scenario with its module uses
    expanded (`sceml.modules.expansion.Expansion`), whose flows are not Flow objects.
    """

    @property
    def nodes(self) -> Sequence[Any]: ...

    def predecessors(self, node: Any) -> list[Any]: ...

    def successors(self, node: Any) -> list[Any]: ...


class OwnFlows:
    """A scenario's or module definition's own nodes and flows, as `Flows`."""

    def __init__(self, graph: scm.Graph) -> None:
        self.nodes: Sequence[scm.GraphElement] = graph.nodes

    predecessors = staticmethod(predecessors)
    successors = staticmethod(successors)


def reachable(
    starts: Iterable[Any], *, backwards: bool = False, flows: Flows | None = None
) -> set[Any]:
    """Every node reachable from `starts` along flows (against them if `backwards`), starts
    included; along the nodes' own Flow objects unless another graph's `flows` are given."""
    if flows is not None:
        step = flows.predecessors if backwards else flows.successors
    else:
        step = predecessors if backwards else successors
    seen = set(starts)
    queue = deque(seen)
    while queue:
        for neighbour in step(queue.popleft()):
            if neighbour not in seen:
                seen.add(neighbour)
                queue.append(neighbour)
    return seen


def topological_order(graph: scm.Graph) -> tuple[list[scm.GraphElement], set[scm.GraphElement]]:
    """Kahn's order of the graph's nodes, and the nodes left over because they lie on cycles."""
    members = set(graph.nodes)
    indegree = {node: 0 for node in graph.nodes}
    for node in graph.nodes:
        for successor in successors(node):
            if successor in members:
                indegree[successor] += 1
    queue = deque(node for node in graph.nodes if indegree[node] == 0)
    order = []
    while queue:
        node = queue.popleft()
        order.append(node)
        for successor in successors(node):
            if successor in members:
                indegree[successor] -= 1
                if indegree[successor] == 0:
                    queue.append(successor)
    return order, members - set(order)

"""Structure rules: one root and one end, flows wired, every node on a path from start to end, no cycles."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator

import scemlmodel as scm

from ..diagnostics import Severity
from ..model.graph import nodes_of
from ..model.traversal import single_value
from .adjacency import left_by_kahn, own_adjacency
from .adjacency import reached as reached_from
from .context import Context
from .reads import SELF, SHAPE, Reads
from .registry import Finding, constraint

ERROR, WARNING = Severity.ERROR, Severity.WARNING
PAPER = "paper §Language Validation"


def _names(nodes: list[scm.GraphElement]) -> str:
    shown = ", ".join(repr(str(node.name)) for node in nodes[:5])
    return shown + (f" and {len(nodes) - 5} more" if len(nodes) > 5 else "")


@constraint(
    "SCEML-S001",
    ERROR,
    "Scenario",
    "a scenario has exactly one RootNode",
    source=PAPER,
    reads=Reads(aspects=SHAPE),
)
def one_root_node(scenario: scm.Scenario, context: Context) -> Iterator[Finding]:
    roots = nodes_of(scenario, scm.RootNode)
    if not roots:
        yield scenario, "the scenario has no RootNode"
    for extra in roots[1:]:
        yield extra, f"second RootNode {extra.name!r}: a scenario has exactly one"


@constraint(
    "SCEML-S002",
    ERROR,
    "Scenario",
    "a scenario has exactly one EndNode",
    source=PAPER,
    reads=Reads(aspects=SHAPE),
)
def one_end_node(scenario: scm.Scenario, context: Context) -> Iterator[Finding]:
    ends = nodes_of(scenario, scm.EndNode)
    if not ends:
        yield scenario, "the scenario has no EndNode"
    for extra in ends[1:]:
        yield extra, f"second EndNode {extra.name!r}: a scenario has exactly one"


@constraint(
    "SCEML-S003",
    ERROR,
    "RootNode",
    "the root node has no incoming flow",
    paper_rule="1",
    # its incoming flows
    reads=Reads(SELF),
)
def root_has_no_input(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    if len(root.incoming):
        yield root, f"root node {root.name!r} has {len(root.incoming)} incoming flow(s)"


@constraint(
    "SCEML-S004",
    ERROR,
    "JoiningPolicy",
    "a join has at least two incoming flows",
    paper_rule="3",
    reads=Reads(SELF),
)
def join_has_two_inputs(join: scm.JoiningPolicy, context: Context) -> Iterator[Finding]:
    count = len(join.incoming)
    if count < 2:
        yield join, f"join {join.name!r} has {count} incoming flow(s); a join needs at least two"


@constraint(
    "SCEML-S005",
    ERROR,
    "EndNode",
    "the end node has no outgoing flow",
    paper_rule="1",
    reads=Reads(SELF),
)
def end_has_no_output(end: scm.EndNode, context: Context) -> Iterator[Finding]:
    if len(end.outgoing):
        yield end, f"end node {end.name!r} has {len(end.outgoing)} outgoing flow(s)"


def _starts_and_ends(
    graph: scm.Graph,
) -> tuple[list[scm.GraphElement], list[scm.GraphElement]]:
    if isinstance(graph, scm.ModuleDefinition):
        return nodes_of(graph, scm.InPort), nodes_of(graph, scm.OutPort)
    return nodes_of(graph, scm.RootNode), nodes_of(graph, scm.EndNode)


@constraint(
    "SCEML-S006",
    ERROR,
    "Graph",
    "every node is reachable from the root node (in a module: the InPort)",
    source=PAPER,
    reads=Reads(aspects=SHAPE),
)
def nodes_reachable_from_start(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    starts, _ = _starts_and_ends(graph)
    if not starts:
        return  # S001 or M007 says so
    reached = reached_from(own_adjacency(graph, context), starts, backwards=False)
    start = "the in-port" if isinstance(graph, scm.ModuleDefinition) else "the root node"
    for node in graph.nodes:
        if node not in reached and node not in starts:
            yield node, f"node {node.name!r} cannot be reached from {start}"


@constraint(
    "SCEML-S007",
    ERROR,
    "Graph",
    "every node reaches the end node (in a module: the OutPort)",
    source=PAPER,
    reads=Reads(aspects=SHAPE),
)
def nodes_reach_the_end(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    _, ends = _starts_and_ends(graph)
    if not ends:
        return
    reached = reached_from(own_adjacency(graph, context), ends, backwards=True)
    end = "the out-port" if isinstance(graph, scm.ModuleDefinition) else "the end node"
    for node in graph.nodes:
        if node not in reached and node not in ends:
            yield node, f"node {node.name!r} has no path to {end}"


@constraint(
    "SCEML-S008",
    ERROR,
    "Graph",
    "the flows form no cycle",
    reads=Reads(aspects=SHAPE),
)
def no_cycles(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    left = left_by_kahn(own_adjacency(graph, context))
    if not left:
        return
    # Kahn's leftovers include nodes merely downstream of a cycle; peeling those whose
    # successors are all gone leaves the nodes on (or between) cycles.
    on_cycle = set(left)
    changed = True
    while changed:
        changed = False
        for node in list(on_cycle):
            if not any(flow.target in on_cycle for flow in node.outgoing):
                on_cycle.discard(node)
                changed = True
    members = [node for node in graph.nodes if node in on_cycle]
    if members:
        yield members[0], f"the flows form a cycle through {_names(members)}"


@constraint(
    "SCEML-S009",
    ERROR,
    ("ActionNode", "ModuleUse"),
    "only joins and the end node merge flows: other nodes have at most one incoming flow",
    # its incoming flows, and whether each has a source
    reads=Reads(SELF),
)
def merges_only_at_joins(node: scm.GraphElement, context: Context) -> Iterator[Finding]:
    incoming = node.incoming
    if len(incoming) < 2:
        return  # most nodes: no flows to count
    count = sum(1 for flow in incoming if flow.source is not None)
    if count > 1:
        yield (
            node,
            f"node {node.name!r} has {count} incoming flows; merge them with a "
            "JoinAllFinished or JoinOneFinished",
        )


@constraint(
    "SCEML-S010",
    ERROR,
    "Flow",
    "a flow has both a source and a target",
    # the name of the end it has
    reads=Reads(SELF),
)
def flow_has_both_ends(flow: scm.Flow, context: Context) -> Iterator[Finding]:
    missing = [end for end in ("source", "target") if single_value(flow, end) is None]
    if missing:
        present = flow.target if flow.source is None else flow.source
        near = f" (the other end is {present.name!r})" if present is not None else ""
        yield flow, f"dangling flow: it has no {' and no '.join(missing)}{near}"


@constraint(
    "SCEML-S011",
    ERROR,
    "Flow",
    "a flow joins two nodes of its own graph",
    # the graphs of its ends
    reads=Reads(SELF),
)
def flow_stays_in_its_graph(flow: scm.Flow, context: Context) -> Iterator[Finding]:
    graph = flow.eContainer()
    for end in ("source", "target"):
        node = single_value(flow, end)
        if node is not None and node.eContainer() is not graph:
            yield flow, f"the flow's {end} {node.name!r} belongs to another graph"


@constraint(
    "SCEML-S012",
    WARNING,
    "Graph",
    "no two flows join the same pair of nodes",
    source="engineer",
    reads=Reads(aspects=SHAPE),
)
def no_duplicate_flows(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    seen: set[tuple[object, object]] = set()
    for flow in graph.flows:
        if flow.source is None or flow.target is None:
            continue
        pair = (flow.source, flow.target)
        if pair in seen:
            yield (
                flow,
                f"a second flow from {flow.source.name!r} to {flow.target.name!r}",
            )
        seen.add(pair)


@constraint(
    "SCEML-S013",
    WARNING,
    "Graph",
    "node names are present and unique within a graph",
    source="engineer",
    reads=Reads(aspects=SHAPE),
)
def node_names_unique(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    counts = Counter(node.name for node in graph.nodes)
    reported: set[object] = set()
    for node in graph.nodes:
        if not node.name:
            yield node, f"a {node.eClass.name} has no name"
        elif counts[node.name] > 1 and node.name not in reported:
            reported.add(node.name)
            yield node, f"{counts[node.name]} nodes are named {node.name!r}"


def _repeatable(kind_name: str) -> bool:
    # Imported here, where a node repeats, not with the rules: the export's planners agree on
    # which kinds can.
    from ..xosc.support import repeatable

    return repeatable(kind_name)


@constraint(
    "SCEML-S014",
    ERROR,
    "ActionNode",
    "a node runs at least once, and more than once only if it is a maneuver players repeat",
    source="engineer",
    reads=Reads(SELF),
)
def runs_are_possible(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    runs = single_value(node, "maxRuns")
    if runs == 1:
        return  # nearly every node: the checks below are for the other counts
    if runs < 1:
        yield node, f"{node.name!r} may run {runs} times: a node runs at least once (maxRuns 1)"
    elif runs > 1 and isinstance(node, scm.Condition):
        # A condition finishes once it holds; players have no condition that holds again.
        yield (
            node,
            (
                f"condition {node.name!r} may run {runs} times: a condition finishes once it "
                "holds; repeat the maneuver after it instead"
            ),
        )
    elif runs > 1 and not _repeatable(node.eClass.name):
        yield (
            node,
            (
                f"{node.eClass.name} {node.name!r} may run {runs} times, but it is written as an "
                "event and the event of its finish, which players cannot repeat together"
            ),
        )

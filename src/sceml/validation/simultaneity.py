"""Simultaneity (paper rule 4): one actor never runs two maneuvers of the same category at once.

Node b is *ordered after* node a when b can only be activated once a has finished. That holds when
b is a, or b's predecessor is ordered after a, or b is a JoinAllFinished with any predecessor
ordered after a. A JoinOneFinished finishes with its first predecessor while the others may still
run, so it is ordered after a only when *every* one of its predecessors is. Two maneuvers that
are not ordered either way can run at the same time, which is allowed when one of them
interrupts (`Maneuver.interrupts`, release 1.5): it is meant to start while the other runs, and
ends it (`xosc.meaning`), as players end a running action of the domain another one takes.

The maneuvers of one actor and one category (longitudinal or lateral; a composite maneuver counts
as both, but a FollowTrajectory only as lateral: `model.axes`) are conflict-free exactly when they form a chain under this order, and a set forms a
chain exactly when each member, taken in topological order, is ordered after the previous one.
One pass over the topological order carries, for every node, the set of maneuvers it is ordered
after as a bitset (a Python int), so the check is linear in nodes times a machine-word fraction of
the maneuvers, with no enumeration of pairs. Bitsets are dropped as soon as their last successor
has been visited.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Iterator, Sequence

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from ..diagnostics import Severity
from ..model.axes import maneuver_axes
from ..model.traversal import single_value
from .context import Context
from .reads import EXPANSION, Reads
from .registry import Finding, constraint

Conflict = tuple[scm.Maneuver, scm.Maneuver, str]


def _previous_in_group(
    order: list[EObject],
) -> tuple[dict[EObject, int], dict[EObject, list[tuple[EObject, str]]]]:
    """Bit index of every maneuver, and for each the previous member of each of its groups."""
    bit: dict[EObject, int] = {}
    previous: dict[EObject, list[tuple[EObject, str]]] = {}
    last: dict[tuple[EObject, str], EObject] = {}
    for node in order:
        if not isinstance(node, scm.Maneuver):
            continue
        # Read through the holder, not pyecore's descriptor: this visits every maneuver of the
        # expanded graph, and the descriptor was half of this function's time at 10k nodes.
        actor = single_value(node, "referenceActor")
        if actor is None:
            continue
        for category in _sorted_axes(node):
            key = (actor, category)
            if key in last:
                previous.setdefault(node, []).append((last[key], category))
            last[key] = node
        bit[node] = len(bit)
    return bit, previous


#: `maneuver_axes` of each maneuver class, sorted: they depend on the class alone (its name),
#: so they are worked out once per class rather than once per maneuver.
_AXES: dict[type, tuple[str, ...]] = {}


def _sorted_axes(node: EObject) -> tuple[str, ...]:
    kind = type(node)
    axes = _AXES.get(kind)
    if axes is None:
        axes = tuple(sorted(maneuver_axes(node)))
        if kind is not EProxy:  # a proxy's type says nothing of the class it stands for
            _AXES[kind] = axes
    return axes


def _adjacency(
    nodes: Sequence[EObject], flows: Iterable[tuple[EObject | None, EObject | None]]
) -> tuple[list[EObject], dict[EObject, list[EObject]], dict[EObject, int]]:
    """Kahn's order, predecessors per node and successor counts, from the graph's own flows.

    Read from the graph's flows rather than the nodes' incoming/outgoing lists, so that flows
    that are dangling or leave the graph are simply not part of the order.
    """
    members = set(nodes)
    sources: dict[EObject, list[EObject]] = {node: [] for node in nodes}
    targets: dict[EObject, list[EObject]] = {node: [] for node in nodes}
    for source, target in flows:
        if source in members and target in members:
            sources[target].append(source)
            targets[source].append(target)
    waiting = {node: len(sources[node]) for node in nodes}
    queue = deque(node for node in nodes if waiting[node] == 0)
    order = []
    while queue:
        node = queue.popleft()
        order.append(node)
        for target in targets[node]:
            waiting[target] -= 1
            if waiting[target] == 0:
                queue.append(target)
    return order, sources, {node: len(targets[node]) for node in nodes}


def conflicts(
    nodes: Sequence[EObject], flows: Iterable[tuple[EObject | None, EObject | None]]
) -> list[Conflict]:
    """Pairs of same-actor, same-category maneuvers that can run at the same time, in the graph
    of `nodes` and `flows` (source, target): a scenario's or module's, or an expanded one."""
    order, sources, pending = _adjacency(nodes, flows)
    if len(order) < len(pending):
        return []  # S008 reports the cycle; the order is undefined there
    bit, previous = _previous_in_group(order)
    after: dict[EObject, int] = {}
    found: list[Conflict] = []
    seen: set[tuple[EObject, EObject]] = set()
    for node in order:
        inputs = sources[node]
        # Most nodes have one predecessor, whose set they take as it is (what `_combine` gives).
        bits = after[inputs[0]] if len(inputs) == 1 else _combine(node, [after[s] for s in inputs])
        if node in bit:
            bits |= 1 << bit[node]
        for earlier, category in previous.get(node, ()):
            if (
                not (bits >> bit[earlier]) & 1
                and not (earlier.interrupts or node.interrupts)
                and (earlier, node) not in seen
            ):
                seen.add((earlier, node))
                found.append((earlier, node, category))
        after[node] = bits
        for source in sources[node]:
            pending[source] -= 1
            if pending[source] == 0:
                del after[source]
        if pending[node] == 0:
            del after[node]
    return found


def overlapping(
    nodes: Sequence[EObject], flows: Iterable[tuple[EObject | None, EObject | None]]
) -> set[EObject]:
    """The maneuvers that can run at the same time as another of their actor and category
    (whatever their `interrupts`): those not ordered either way with every other member of
    their group. The import marks them as interrupting (`importer.overlaps`), as players run
    them. One pass carries the bitsets as `conflicts` does, then per group a suffix AND of
    them: a member is ordered with all after it when each of those has its bit."""
    order, sources, _ = _adjacency(nodes, flows)
    if len(order) < len(nodes):
        return set()
    bit: dict[EObject, int] = {}
    after: dict[EObject, int] = {}
    groups: dict[tuple[EObject, str], list[EObject]] = {}
    for node in order:
        bits = _combine(node, [after[source] for source in sources[node]])
        if isinstance(node, scm.Maneuver) and node.referenceActor is not None:
            bit[node] = len(bit)
            bits |= 1 << bit[node]
            for category in maneuver_axes(node):
                groups.setdefault((node.referenceActor, category), []).append(node)
        after[node] = bits
    found: set[EObject] = set()
    for members in groups.values():
        if len(members) < 2:
            continue
        below = 0  # the bits of the members before, in topological order
        masks = [below := below | (1 << bit[m]) for m in members]
        suffix = -1  # all ones: the AND over no bitsets
        ordered_later = [0] * len(members)
        for index in range(len(members) - 1, -1, -1):
            ordered_later[index] = suffix
            suffix &= after[members[index]]
        for index, member in enumerate(members):
            before_all = after[member] & masks[index] == masks[index]
            after_all = (ordered_later[index] >> bit[member]) & 1
            if not (before_all and after_all):
                found.add(member)
    return found


def _combine(node: EObject, inputs: list[int]) -> int:
    if not inputs:
        return 0
    if isinstance(node, scm.JoinOneFinished) and len(inputs) > 1:
        combined = inputs[0]
        for bits in inputs[1:]:
            combined &= bits
        return combined
    combined = 0
    for bits in inputs:
        combined |= bits
    return combined


@constraint(
    "SCEML-C001",
    Severity.ERROR,
    ("Scenario", "ModuleDefinition"),
    "two maneuvers of the same actor and category (longitudinal or lateral; composite counts as "
    "both, but a FollowTrajectory, followed at the actor's speed, as lateral) cannot run at the "
    "same time: one must be ordered after the other, or one of them interrupt (when it "
    "starts, the other ends). A path through a "
    "JoinOneFinished orders only if all of the join's branches are ordered. Module uses are "
    "checked expanded",
    paper_rule="4",
    reads=Reads(aspects=EXPANSION),
)
def no_simultaneous_maneuvers(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    if isinstance(graph, scm.ModuleDefinition) and not isinstance(context.root, scm.Library):
        return  # a used definition is checked expanded, inside the scenario that uses it
    flat = context.flat() if isinstance(graph, scm.Scenario) else None
    if flat is not None:
        found = conflicts(flat.nodes, flat.flows())
    else:
        found = conflicts(graph.nodes, [(flow.source, flow.target) for flow in graph.flows])
    for earlier, later, category in found:
        actor = later.referenceActor.name
        element = flat.origin(later) if flat else later
        yield (
            element,
            f"{earlier.name!r} and {later.name!r} are both {category} maneuvers of {actor!r} "
            "and can run at the same time",
        )

"""One maneuver of a kind at a time per actor (SPEC §6, simultaneity), as SceML requires.

In OpenSCENARIO a later longitudinal (or lateral) action of an actor overrides the one running;
SceML has no overriding, and two maneuvers of one actor and category must not be able to run
together. So when a maneuver could start while an earlier one of the same actor and category
may still run, it also waits for that one to finish (a JoinAllFinished before it); the report
says so, because the original would have cut the earlier one short.
"""

from __future__ import annotations

import math
from collections import deque

import scemlmodel as scm

from ..model import catalog, graph, params
from ..xosc.flows import is_condition_element
from .context import Build

_AXES = {
    "longitudinal": {"longitudinal"},
    "lateral": {"lateral"},
    "composite": {"longitudinal", "lateral"},
}


def separate(build: Build) -> None:
    """Make every pair of same-actor, same-category maneuvers run one after the other.

    The maneuvers of one actor and axis are taken in the order they can first start
    (`_by_earliest_start`): an event whose condition may hold at 1 s goes before one that
    waits for a clock of 8 s, however many nodes each waits through (`keep_lateral_distance`:
    its first lane change, on a distance after the act's start, waited for the two timed ones
    and started at 15 s instead of 2.75 s). Once each waits for the one before it, it follows
    all of them, so each needs at most one new join: the whole pass is near linear in the
    number of events, where comparing every pair was cubic (issue 26).
    """
    order = _by_earliest_start(build.scenario.nodes)
    lines: dict[tuple[int, str], list[scm.Maneuver]] = {}
    for node in sorted(
        (n for n in build.scenario.nodes if isinstance(n, scm.Maneuver)),
        key=lambda n: order[id(n)],
    ):
        for axis in sorted(_axes(node)):
            lines.setdefault((id(node.referenceActor), axis), []).append(node)
    for line in lines.values():
        for earlier, later in zip(line, line[1:], strict=False):
            if not _reaches(earlier, later, order):
                join = _wait(build, earlier, later)
                order[id(later.incoming[0].source)] = order[id(later)] - 0.5
                order[id(join)] = order[id(later)] - 0.75


def _axes(node: scm.Maneuver) -> set[str]:
    return _AXES.get(catalog.category(node) or "", set())


def _by_earliest_start(nodes: list[scm.GraphElement]) -> dict[int, float]:
    """Node id -> its place in a topological order that sorts by the earliest time a node can
    start (waits add up from the root; a condition or maneuver may finish at once, so it adds
    nothing), then by the plain topological order (document order). The earliest start never
    decreases along a flow, so this is still a topological order (`_reaches` relies on it)."""
    plain = _topological(nodes)
    ranked = sorted(nodes, key=lambda n: plain[id(n)])
    finish: dict[int, float] = {}
    for node in ranked:
        before = [finish.get(id(f.source), 0.0) for f in node.incoming if f.source is not None]
        start = (min if graph.finishes_with_first(node) else max)(before, default=0.0)
        finish[id(node)] = start + _wait_of(node)
    earliest = {id(n): finish[id(n)] - _wait_of(n) for n in nodes}
    ranked.sort(key=lambda n: (earliest[id(n)], plain[id(n)]))
    return {id(n): float(place) for place, n in enumerate(ranked)}


def _wait_of(node: scm.GraphElement) -> float:
    """How long a wait lasts at the least (0 for anything else, or a wait not yet concrete)."""
    if not isinstance(node, scm.TimeElapsed):
        return 0.0
    try:
        return max(params.concrete(node, "duration"), 0.0)
    except ValueError:
        return 0.0


def _topological(nodes: list[scm.GraphElement]) -> dict[int, float]:
    """Node id -> its place in a topological order of the flows (Kahn, first in first out)."""
    waiting = {id(n): sum(1 for f in n.incoming if f.source is not None) for n in nodes}
    ready = deque(n for n in nodes if waiting[id(n)] == 0)
    order: dict[int, float] = {}
    while ready:
        node = ready.popleft()
        order[id(node)] = float(len(order))
        for flow in node.outgoing:
            target = flow.target
            if target is None or id(target) not in waiting:
                continue
            waiting[id(target)] -= 1
            if waiting[id(target)] == 0:
                ready.append(target)
    for node in nodes:  # a cycle (refused earlier) would leave some: after the rest
        order.setdefault(id(node), float(len(order)))
    return order


def _reaches(start: scm.GraphElement, goal: scm.GraphElement, order: dict[int, float]) -> bool:
    """Whether flows lead from `start` to `goal`; nodes after `goal` in `order` are not
    searched (no path from them leads back to it)."""
    limit = order.get(id(goal), math.inf)
    seen, todo = {id(start)}, [start]
    while todo:
        node = todo.pop()
        if node is goal:
            return True
        for flow in node.outgoing:
            target = flow.target
            if (
                target is not None
                and id(target) not in seen
                and order.get(id(target), math.inf) <= limit
            ):
                seen.add(id(target))
                todo.append(target)
    return False


def _wait(build: Build, earlier: scm.Maneuver, later: scm.Maneuver) -> scm.JoinAllFinished:
    """`later` also waits for `earlier`: a join before it, or, where `later` is started by a
    condition of its own, before that condition. The condition is then evaluated once both
    have finished and stays the only thing `later` waits for, so the export writes it into
    `later`'s StartTrigger (`xosc.flows.inlined`) and `later` starts in the step it holds,
    as in the original; a join after the condition would make it a marker, a step late."""
    target: scm.GraphElement = later
    sources = [flow.source for flow in later.incoming]
    if (
        len(sources) == 1
        and _is_condition(sources[0])
        and len(sources[0].outgoing) == 1
        and len(sources[0].incoming) == 1
    ):
        target = sources[0]
    join = build.add(scm.JoinAllFinished(), f"{later.name}_after_{earlier.name}")
    for flow in list(target.incoming):
        # Moved through the opposite list: setting `flow.target` would leave the flow in
        # `target.incoming` too (pyecore keeps the old side of an opposite on a set).
        target.incoming.remove(flow)
        join.incoming.append(flow)
    build.flow(earlier, join)
    build.flow(join, target)
    build.report.add(
        "guessed",
        f"{later.name} also waits for {earlier.name} to finish (in OpenSCENARIO it would cut "
        f"{earlier.name} short; SceML runs one maneuver of an actor and kind at a time)"
        + (f"; {target.name} is evaluated once both have finished" if target is not later else ""),
        node=str(later.name),
    )
    return join


def _is_condition(node: scm.GraphElement | None) -> bool:
    if isinstance(node, scm.TimeElapsed):
        return False
    return isinstance(node, scm.Condition) or (node is not None and is_condition_element(node))

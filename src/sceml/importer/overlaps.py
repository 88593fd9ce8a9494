"""One maneuver of a kind at a time per actor (SPEC §6, simultaneity), as players run them.

In OpenSCENARIO a later longitudinal (or lateral) action of an actor ends the one running:
players end a running action of the entity whose control domain the new one shares, whatever
the event's priority, and an event of priority overwrite/override ends the running events of
its Maneuver (`xosc.meaning`, "one maneuver of a part at a time"). So two maneuvers of one
actor and category that may run at the same time both *interrupt* (`Maneuver.interrupts`,
release 1.5): whichever starts while the other runs ends it, and the ended one counts as
finished, as in the original. They are the maneuvers simultaneity (SCEML-C001) judges
unordered with another (`validation.simultaneity.overlapping`), so the model passes it.

A turn (TurnLeft, TurnRight, Cross) is exported as a route, which players run in no control
domain and so end nothing: a turn and a maneuver it may overlap still run one after the other,
the later waiting for the earlier (a JoinAllFinished before it; the report says so, because
the original would run them together).
"""

from __future__ import annotations

import heapq
import math

import scemlmodel as scm

from ..model.axes import maneuver_axes
from ..validation.simultaneity import overlapping
from ..xosc.flows import is_condition_element
from .context import Build


def separate(build: Build) -> None:
    """Order each turn after a maneuver of its actor and category it may overlap (or that
    maneuver after the turn), then make every other maneuver that may overlap one of its
    actor and category interrupt."""
    _order_turns(build)
    flows = [(flow.source, flow.target) for flow in build.scenario.flows]
    found = overlapping(build.scenario.nodes, flows)
    for node in build.scenario.nodes:  # in document order, for the report
        if node in found and not isinstance(node, scm.RoutedManeuver):
            _interrupt(build, node)


def _order_turns(build: Build) -> None:
    """Make a turn and a maneuver of the same actor and axis run one after the other.

    The maneuvers of one actor and axis are taken in the graph's topological order, document
    order between unrelated ones (`_topological`): files list an actor's events in the order
    they happen, however many nodes each waits through. Once each waits for the one before
    it, it follows all of them, so each needs at most one new join: the whole pass is near
    linear in the number of events, where comparing every pair was cubic (issue 26).
    """
    order = _topological(build.scenario.nodes, build.event_order)
    lines: dict[tuple[int, str], list[scm.Maneuver]] = {}
    for node in sorted(
        (n for n in build.scenario.nodes if isinstance(n, scm.Maneuver)),
        key=lambda n: order[id(n)],
    ):
        for axis in sorted(_axes(node)):
            lines.setdefault((id(node.referenceActor), axis), []).append(node)
    for line in lines.values():
        for earlier, later in zip(line, line[1:], strict=False):
            routed = isinstance(earlier, scm.RoutedManeuver) or isinstance(
                later, scm.RoutedManeuver
            )
            if routed and not _reaches(earlier, later, order):
                join = _wait(build, earlier, later)
                order[id(later.incoming[0].source)] = order[id(later)] - 0.5
                order[id(join)] = order[id(later)] - 0.75


def _interrupt(build: Build, node: scm.Maneuver) -> None:
    """`node` may start while another maneuver of its actor and category runs: it ends it."""
    node.interrupts = True
    axes = " and ".join(sorted(maneuver_axes(node)))
    build.report.add(
        "mapped",
        f"{node.name} may start while another {axes} maneuver of {node.referenceActor.name} "
        "runs: it interrupts it (players end a running action of the entity's domain when "
        "another starts)",
        node=str(node.name),
    )


def _axes(node: scm.Maneuver) -> frozenset[str]:
    return maneuver_axes(node)


def _topological(nodes: list[scm.GraphElement], events: dict[int, int]) -> dict[int, float]:
    """Node id -> its place in a topological order of the flows: of the nodes ready, always
    the one that leads to the event first in the file (`_first_event`), then the one made
    first. Not breadth first: that put an event behind every event that waits through fewer
    nodes (`keep_lateral_distance`: its first lane change, on a distance and a delay, waited
    for the lane change at 8 s and the one after it, and started at 15.05 s instead of
    2.75 s). Not the order made alone: an event a trigger refers to is made before the
    events between (`parking_demo`: Target5's slow-down, made for a light event's trigger,
    went before the unparking above it in the file, which then waited for it forever)."""
    first = _first_event(nodes, events)
    made = {id(n): (first[id(n)], index) for index, n in enumerate(nodes)}
    waiting = {id(n): sum(1 for f in n.incoming if f.source is not None) for n in nodes}
    ready = [(made[id(n)], n) for n in nodes if waiting[id(n)] == 0]
    heapq.heapify(ready)
    order: dict[int, float] = {}
    while ready:
        _, node = heapq.heappop(ready)
        order[id(node)] = float(len(order))
        for flow in node.outgoing:
            target = flow.target
            if target is None or id(target) not in waiting:
                continue
            waiting[id(target)] -= 1
            if waiting[id(target)] == 0:
                heapq.heappush(ready, (made[id(target)], target))
    for node in nodes:  # a cycle (refused earlier) would leave some: after the rest
        order.setdefault(id(node), float(len(order)))
    return order


def _first_event(nodes: list[scm.GraphElement], events: dict[int, int]) -> dict[int, float]:
    """Node id -> the least document place (`events`) of the events it leads to (itself
    included); infinite where it leads to none."""
    first: dict[int, float] = {}

    def visit(node: scm.GraphElement) -> float:
        # Iterative: a chain of thousands of events (issue 26) is deeper than Python's stack.
        stack = [(node, False)]
        while stack:
            current, expanded = stack.pop()
            if id(current) in first:
                continue
            after = [f.target for f in current.outgoing if f.target is not None]
            if not expanded:
                stack.append((current, True))
                stack.extend((t, False) for t in after if id(t) not in first)
                continue
            own = float(events.get(id(current), math.inf))
            first[id(current)] = min([own, *(first.get(id(t), math.inf) for t in after)])
        return first[id(node)]

    for node in nodes:
        visit(node)
    return first


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
    condition of its own (directly or through that condition's delay), before that
    condition. The condition is then evaluated once both have finished and stays the only
    thing `later` waits for, so the export writes it (and its delay) into `later`'s
    StartTrigger (`xosc.flows.inlined`) and `later` starts in the step it holds, as in the
    original; a join after the condition would make it a marker, a step late
    (`traffic_lights`' DriveOnGreenEvent, on a green light with a delay of 0.5 s)."""
    target = _own_condition(later) or later
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
        f"{later.name} also waits for {earlier.name} to finish (in OpenSCENARIO they may run "
        "together: a turn is a route, which ends no running action; SceML runs one maneuver "
        "of an actor and kind at a time)"
        + (f"; {target.name} is evaluated once both have finished" if target is not later else ""),
        node=str(later.name),
    )
    return join


def _own_condition(later: scm.GraphElement) -> scm.GraphElement | None:
    """The condition that alone starts `later`, directly or through one wait (its delay),
    each feeding only the next; None when there is none."""
    node = _only_source(later)
    if isinstance(node, scm.TimeElapsed) and int(node.maxRuns) == 1:
        node = _only_source(node)
    if node is None or not _is_condition(node) or len(node.incoming) != 1:
        return None
    return node


def _only_source(node: scm.GraphElement) -> scm.GraphElement | None:
    """The one node `node` waits for, if it feeds nothing else."""
    sources = [flow.source for flow in node.incoming]
    if len(sources) != 1 or sources[0] is None or len(sources[0].outgoing) != 1:
        return None
    return sources[0]


def _is_condition(node: scm.GraphElement | None) -> bool:
    if isinstance(node, scm.TimeElapsed):
        return False
    return isinstance(node, scm.Condition) or (node is not None and is_condition_element(node))

"""The StopTrigger to the end node and the maximum duration.

Groups that are only `SimulationTime > T` give the maximum duration; the others are what the end
node waits for (one group: join-all over its elements; one per element: join-one). Every node
must reach the end in SceML, so branches the StopTrigger does not name also flow into it, through
a join-all with the stop (which then alone decides when the run ends, as in OpenSCENARIO).
A StopTrigger without a time limit gets `UNLIMITED_RUN`, not SceML's default of 60 s: the
original runs until its StopTrigger holds, however late.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from . import traced
from .context import Build
from .positions import number
from .storyboard import Storyboard
from .triggers import Group, Trigger, first_holds

#: The maximum duration of a scenario whose StopTrigger sets no time limit. OpenSCENARIO then
#: runs until the StopTrigger holds; a SceML run needs a limit, and SceML's default (60 s)
#: cut `acc-toggle` (117.8 s) and `cut-in_sloppy` (218.65 s) short. 1200 s is the limit
#: esmini's own scenarios give a run that has no other end, and the preview records it for up
#: to 83 actors at 0.05 s (`simulate.limits.MAX_SAMPLES`).
UNLIMITED_RUN = 1200.0


def read_stop(build: Build, storyboard: Storyboard) -> None:
    """Wire the end node and set the root's maximum duration."""
    stop = build.source.root.find("Storyboard/StopTrigger")
    trigger = Trigger(build, storyboard.resolve, build.root, build.default_actor())
    limits, groups = [], []
    #: When each limit first holds (`> T` a step after T: `triggers.first_holds`).
    holds: list[float] = []
    for element in [] if stop is None else stop.iterchildren("ConditionGroup"):
        limit = _time_limit(element)
        if limit is not None:
            limits.append(limit)
            holds.append(first_holds(element.find("Condition/ByValueCondition/*")))
        else:
            groups.append(trigger.read(element))
    if limits:
        build.root.maxDuration = traced.value(min(limits))
        build.report.add(
            "mapped", f"StopTrigger: maximum duration {min(limits):g} s", build.where(stop)
        )
    else:
        build.root.maxDuration = scm.Value(value=UNLIMITED_RUN)
        build.report.add(
            "guessed",
            "no SimulationTime limit in the StopTrigger: a maximum duration of "
            f"{UNLIMITED_RUN:g} s (the original runs until its StopTrigger holds)",
        )
    ends = _ends(build, trigger, groups)
    others = [n for n in _sinks(build) if all(n is not e for e in ends)]
    if not groups:
        if limits:
            # Only a time limit: the run lasts that long even when every branch is done early.
            ends = [
                trigger.timed(build.root, min(holds), "stop_time", "TimeElapsed", trigger.actor)
            ]
        build.report.add(
            "guessed",
            "the StopTrigger names no storyboard element: the end waits for every branch"
            + (f" and {min(limits):g} s" if limits else ""),
        )
    elif others:
        ends = _stop_or_rest(build, ends, others)
        build.report.add(
            "guessed",
            "the end comes when the StopTrigger holds; "
            f"{', '.join(str(n.name) for n in others)} (which it does not name) reach the end "
            "through a join with it: every SceML branch must reach the end",
            build.where(stop),
        )
    for node in [*ends, *([] if groups else others)] or [build.root]:
        build.flow(node, build.end)


def _stop_or_rest(
    build: Build, ends: list[scm.GraphElement], others: list[scm.GraphElement]
) -> list[scm.GraphElement]:
    """The end's inputs when the StopTrigger does not name every branch: the stop, and the
    other branches joined with the stop.

    OpenSCENARIO stops when the StopTrigger holds, whatever else is running or has finished.
    The other branches must reach the end in SceML; met in a join-all with the stop itself,
    they can neither end the run earlier (as a join-one with them would) nor keep it going
    (as a join-all at the end would), so the end comes exactly when the stop holds.
    """
    stop = ends[0]
    if len(ends) > 1:
        kind = (
            scm.JoinOneFinished
            if build.end.policy is scm.JoinPolicy.joinOne
            else scm.JoinAllFinished
        )
        stop = build.add(kind(), "stop_holds")
        for end in ends:
            build.flow(end, stop)
    rest = build.add(scm.JoinAllFinished(), "branches_done")
    for other in [*others, stop]:
        build.flow(other, rest)
    build.end.policy = scm.JoinPolicy.joinOne
    return [stop, rest]


def _time_limit(group: etree._Element) -> float | None:
    conditions = group.findall("Condition")
    clocks = [c.find("ByValueCondition/SimulationTimeCondition") for c in conditions]
    if (
        len(conditions) != 1
        or clocks[0] is None
        or clocks[0].get("rule") not in ("greaterThan", "greaterOrEqual")
    ):
        return None
    value = number(clocks[0], "value")
    return value if value > 0 and float(conditions[0].get("delay", "0")) == 0 else None


def _ends(build: Build, trigger: Trigger, groups: list[Group]) -> list[scm.GraphElement]:
    """What the end node waits for, setting its policy."""
    # Plain: only elements to wait for, none of them delayed (a delayed one, as the export
    # writes a wait inlined into the end, needs its TimeElapsed: `group_node` makes it).
    plain = all(not g.conditions and all(d == 0 for _, d in g.after) for g in groups)
    if len(groups) == 1 and plain:
        return [n for n, _ in groups[0].after]
    if groups and plain and all(len(g.after) == 1 for g in groups):
        build.end.policy = scm.JoinPolicy.joinOne
        return [g.after[0][0] for g in groups]
    if len(groups) == 1:
        return [trigger.group_node(groups[0], None, "stop")]
    if groups:
        nodes = [trigger.group_node(g, None, f"stop_{i}") for i, g in enumerate(groups, 1)]
        build.end.policy = scm.JoinPolicy.joinOne
        return nodes
    return []


def _sinks(build: Build) -> list[scm.GraphElement]:
    return [
        node
        for node in build.scenario.nodes
        if node is not build.end and not node.outgoing and not isinstance(node, scm.RootNode)
    ]

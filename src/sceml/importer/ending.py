"""The StopTrigger to the end node and the maximum duration.

Groups that are only `SimulationTime > T` give the maximum duration; the others are what the end
node waits for (one group: join-all over its elements; one per element: join-one). Every node
must reach the end in SceML, so branches the StopTrigger does not name also flow into it.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from . import traced
from .context import Build
from .positions import number
from .storyboard import Storyboard
from .triggers import Group, Trigger


def read_stop(build: Build, storyboard: Storyboard) -> None:
    """Wire the end node and set the root's maximum duration."""
    stop = build.source.root.find("Storyboard/StopTrigger")
    trigger = Trigger(build, storyboard.resolve, build.root, build.default_actor())
    limits, groups = [], []
    for element in [] if stop is None else stop.iterchildren("ConditionGroup"):
        limit = _time_limit(element)
        if limit is not None:
            limits.append(limit)
        else:
            groups.append(trigger.read(element))
    if limits:
        build.root.maxDuration = traced.value(min(limits))
        build.report.add(
            "mapped", f"StopTrigger: maximum duration {min(limits):g} s", build.where(stop)
        )
    else:
        build.report.add(
            "guessed", "no SimulationTime limit in the StopTrigger: the default maximum duration"
        )
    ends = _ends(build, trigger, groups)
    others = [n for n in _sinks(build) if all(n is not e for e in ends)]
    if groups and others:
        names = ", ".join(str(n.name) for n in others)
        build.report.add(
            "guessed",
            f"the end also waits for {names} (the StopTrigger does not name them)",
            build.where(stop),
        )
    if not groups:
        build.report.add(
            "guessed", "the StopTrigger names no storyboard element: the end waits for every branch"
        )
    if build.end.policy is scm.JoinPolicy.joinOne and others:
        join = build.add(scm.JoinOneFinished(), "stop_any")
        for end in ends:
            build.flow(end, join)
        ends = [join]
        build.end.policy = scm.JoinPolicy.joinAll
    for node in [*ends, *others] or [build.root]:
        build.flow(node, build.end)


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
    plain = all(not g.conditions and g.delay == 0 for g in groups)
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

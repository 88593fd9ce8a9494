"""Triggers to graph structure (SPEC §3 in reverse): what a StartTrigger or StopTrigger waits for.

A trigger is ConditionGroups (OR) of Conditions (AND). In each group a StoryboardElementState
condition is a flow from that element's node, a SimulationTime condition at 0 a flow from the
start, a later SimulationTime a TimeElapsed after the root; several of these meet in a
JoinAllFinished. Every other condition is a condition node after them (or an opaque one); two or
more are evaluated side by side and meet in a JoinAllFinished (a group, never a chain), and a
delay is a TimeElapsed. Several groups meet in a JoinOneFinished.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from lxml import etree

import scemlmodel as scm

from . import traced
from .conditions import condition_after
from .context import Build
from .positions import number

#: Finds the node of a StoryboardElementStateCondition (it may import the element first).
Resolver = Callable[[etree._Element], scm.GraphElement]


@dataclass
class Group:
    """One ConditionGroup read: the nodes it waits for, its other conditions, its delays."""

    after: list[tuple[scm.GraphElement, float]] = field(default_factory=list)
    conditions: list[tuple[etree._Element, float]] = field(default_factory=list)

    @property
    def delay(self) -> float:
        """The delay every condition of the group shares (0.0 when they differ)."""
        delays = {d for _, d in self.after} | {d for _, d in self.conditions}
        return delays.pop() if len(delays) == 1 else 0.0


@dataclass
class Trigger:
    """How one trigger is read: where its groups start and how its delays become nodes."""

    build: Build
    resolve: Resolver
    start: scm.GraphElement
    #: The actor of TimeElapsed nodes made for delays (the event's actor).
    actor: scm.Actor
    #: What a marker's delay stands for: TimeElapsed, or KeepVelocity in a SceML export.
    delay_kind: str = "TimeElapsed"

    def read(self, element: etree._Element) -> Group:
        """One ConditionGroup: waits and conditions."""
        group = Group()
        for condition in element.iterchildren("Condition"):
            delay = number(condition, "delay", 0.0) if condition.get("delay") else 0.0
            state = condition.find("ByValueCondition/StoryboardElementStateCondition")
            clock = condition.find("ByValueCondition/SimulationTimeCondition")
            if state is not None:
                group.after.append((self.resolve(state), delay))
            elif clock is not None and clock.get("rule") in ("greaterThan", "greaterOrEqual"):
                group.after.append((self._clock(number(clock, "value")), delay))
            else:
                group.conditions.append((condition, delay))
        return group

    def _clock(self, seconds: float) -> scm.GraphElement:
        if seconds <= 0:
            return self.start
        node = self.timed(
            self.build.root,
            seconds,
            f"after_{seconds:g}s",
            "TimeElapsed",
            self.build.default_actor(),
        )
        return node

    def timed(
        self, before: scm.GraphElement, seconds: float, wanted: str, kind: str, actor: scm.Actor
    ) -> scm.GraphElement:
        """A TimeElapsed (or KeepVelocity) of `seconds` after `before`."""
        node: scm.ActionNode = getattr(scm, kind)(duration=traced.value(seconds))
        node.referenceActor = actor
        self.build.add(node, wanted)
        self.build.flow(before, node)
        self.build.report.add(
            "mapped", f"{node.name}: a wait of {seconds:g} s -> {kind}", node=str(node.name)
        )
        return node

    def node(
        self, trigger: etree._Element | None, final: str | None, wanted: str
    ) -> scm.GraphElement:
        """The node that finishes when the trigger holds; the last node made is named `final`."""
        groups = (
            []
            if trigger is None
            else [self.read(g) for g in trigger.iterchildren("ConditionGroup")]
        )
        if not groups:
            return self.start
        if len(groups) == 1:
            return self.group_node(groups[0], final, wanted)
        ends = _distinct(
            [self.group_node(g, None, f"{wanted}_{i}") for i, g in enumerate(groups, 1)]
        )
        if len(ends) == 1:
            return ends[0]
        join = self.build.add(scm.JoinOneFinished(), final or f"{wanted}_any")
        for end in ends:
            self.build.flow(end, join)
        return join

    def group_node(self, group: Group, final: str | None, wanted: str) -> scm.GraphElement:
        """The node that finishes when every condition of the group has held."""
        shared = group.delay
        after = _distinct([self._delayed(n, d - shared, wanted) for n, d in group.after]) or [
            self.start
        ]
        last_step = "conditions" if group.conditions else "delay" if shared > 0 else "join"
        if len(after) == 1:
            node = after[0]
        else:
            name = final if last_step == "join" and final else f"{wanted}_all"
            node = self.build.add(scm.JoinAllFinished(), name)
            for before in after:
                self.build.flow(before, node)
        if len(group.conditions) == 1:
            condition, delay = group.conditions[0]
            name = final if shared <= 0 and final else str(condition.get("name") or wanted)
            node = condition_after(self.build, condition, node, name)
            node = self._delayed(node, delay - shared, name)
        elif group.conditions:
            node = self._all_hold(group, node, final if shared <= 0 else None, wanted)
        if shared > 0:
            node = self.timed(node, shared, final or f"{wanted}_delay", self.delay_kind, self.actor)
        return node

    def _all_hold(
        self, group: Group, start: scm.GraphElement, final: str | None, wanted: str
    ) -> scm.GraphElement:
        """Several conditions of one group: evaluated side by side from `start` and met in one
        JoinAllFinished, so the AND reads as a group, not as a sequence (issue 24). `start` is
        what the group's state and time conditions wait for (they stay true once reached)."""
        shared = group.delay
        ends = []
        for condition, delay in group.conditions:
            name = str(condition.get("name") or wanted)
            made = condition_after(self.build, condition, start, name)
            ends.append(self._delayed(made, delay - shared, name))
        join = self.build.add(scm.JoinAllFinished(), final or f"{wanted}_all_hold")
        for end in _distinct(ends):
            self.build.flow(end, join)
        return join

    def _delayed(self, node: scm.GraphElement, delay: float, wanted: str) -> scm.GraphElement:
        if delay <= 0:
            return node
        return self.timed(node, delay, f"{wanted}_delay", "TimeElapsed", self.actor)


def _distinct(nodes: list[scm.GraphElement]) -> list[scm.GraphElement]:
    seen: list[scm.GraphElement] = []
    for node in nodes:
        if all(node is not other for other in seen):
            seen.append(node)
    return seen

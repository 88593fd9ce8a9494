"""Triggers to graph structure (SPEC §3 in reverse): what a StartTrigger or StopTrigger waits for.

A trigger is ConditionGroups (OR) of Conditions (AND). In each group a StoryboardElementState
condition is a flow from that element's node, a SimulationTime condition that holds at 0
(`>= 0`) a flow from the start, a later one (`> 0` a step later, `> v` a step after v:
`xosc.PLAYER_STEP`) a TimeElapsed after the root; several of these meet in a
JoinAllFinished. Every other condition is a condition node after them (or an opaque one); two or
more are evaluated side by side and meet in a JoinAllFinished (a group, never a chain), and a
delay is a TimeElapsed. Several groups meet in a JoinOneFinished.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from lxml import etree

import scemlmodel as scm

from ..xosc import PLAYER_STEP
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
    #: What the trigger's element waits for before its trigger is evaluated (its act's start):
    #: the node, or what makes it, called only when a group needs it (a clock that holds
    #: after it does not, so an act start nothing uses is not made).
    waits_for: scm.GraphElement | Callable[[], scm.GraphElement]
    #: The actor of TimeElapsed nodes made for delays (the event's actor).
    actor: scm.Actor
    #: What a marker's delay stands for: TimeElapsed, or KeepVelocity in a SceML export.
    delay_kind: str = "TimeElapsed"
    #: When what it waits for has surely finished, from the run's start, if a clock alone
    #: says so (`clock_start`); None when that depends on the run.
    started_at: float | None = None
    #: The name of a repeated event (maximumExecutionCount above 1) whose trigger this is: its
    #: conditions are its own nodes, not shared with other triggers (see `condition`).
    repeated: str | None = None

    @property
    def start(self) -> scm.GraphElement:
        if callable(self.waits_for):
            self.waits_for = self.waits_for()
        return self.waits_for

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
                # The clock counts from the run's start, but it is evaluated only once the
                # act runs, and its delay counts from when it is first seen to hold: it waits
                # for whichever of the two is later (both when the act's start is not known).
                seconds = first_holds(clock)
                if self._started_by(seconds):
                    group.after.append((self._clock(seconds), delay))
                elif self.started_at is not None:
                    group.after.append((self.start, delay))
                else:
                    group.after += [(self._clock(seconds), delay), (self.start, delay)]
            else:
                group.conditions.append((condition, delay))
        return group

    def _started_by(self, seconds: float) -> bool:
        """Whether what the trigger's element waits for (its act's start) has surely
        finished by `seconds` from the run's start: it is the root, or a clock alone that
        holds by then (`started_at`)."""
        if self.waits_for is self.build.root:
            return True
        return self.started_at is not None and self.started_at <= seconds

    def _clock(self, seconds: float) -> scm.GraphElement:
        """What a SimulationTime condition that first holds at `seconds` waits for: the
        start (the root's successors start at t = 0), or a TimeElapsed after the root."""
        if seconds <= 0:
            return self.start
        return self.timed(
            self.build.root,
            seconds,
            f"after_{round(seconds, 6):g}s",
            "TimeElapsed",
            self.build.default_actor(),
            share=True,
        )

    def timed(
        self,
        before: scm.GraphElement,
        seconds: float,
        wanted: str,
        kind: str,
        actor: scm.Actor,
        share: bool = False,
    ) -> scm.GraphElement:
        """A TimeElapsed (or KeepVelocity) of `seconds` after `before`; with `share`, the one
        already made for the same wait after the same node (see `condition`)."""
        key = (id(before), f"{kind} {seconds!r}".encode())
        if share and key in self.build.conditions:
            return self.build.conditions[key]
        node: scm.ActionNode = getattr(scm, kind)(duration=traced.value(seconds))
        node.referenceActor = actor
        self.build.add(node, wanted)
        self.build.flow(before, node)
        self.build.report.add(
            "mapped", f"{node.name}: a wait of {seconds:g} s -> {kind}", node=str(node.name)
        )
        if share:
            self.build.conditions[key] = node
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
        return self._join(scm.JoinOneFinished, ends, final, f"{wanted}_any")

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
            name = final if last_step == "join" else None
            node = self._join(scm.JoinAllFinished, after, name, f"{wanted}_all")
        if len(group.conditions) == 1:
            condition, delay = group.conditions[0]
            name = final if shared <= 0 and final else str(condition.get("name") or wanted)
            node = self.condition(condition, node, name)
            node = self._delayed(node, delay - shared, name)
        elif group.conditions:
            node = self._all_hold(group, node, final if shared <= 0 else None, wanted)
        if shared > 0:
            name = final or f"{wanted}_delay"
            node = self.timed(node, shared, name, self.delay_kind, self.actor, final is None)
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
            made = self.condition(condition, start, name)
            ends.append(self._delayed(made, delay - shared, name))
        return self._join(scm.JoinAllFinished, _distinct(ends), final, f"{wanted}_all_hold")

    def _join(
        self, kind: type, inputs: list[scm.GraphElement], final: str | None, wanted: str
    ) -> scm.GraphElement:
        """A join of `inputs`: the one already made of the same kind and inputs, unless it is
        to be named `final` (a SceML export's marker event: a node of its own)."""
        key = (id(kind), " ".join(str(id(n)) for n in inputs).encode())
        if final is None and key in self.build.conditions:
            return self.build.conditions[key]
        join = self.build.add(kind(), final or wanted)
        for before in inputs:
            self.build.flow(before, join)
        if final is None:
            self.build.conditions[key] = join
        return join

    def condition(
        self, condition: etree._Element, before: scm.GraphElement, wanted: str
    ) -> scm.GraphElement:
        """The node of a condition activated by `before`; the same one for the same condition
        after the same node in another trigger (an event with several actions, or a SceML
        export that wrote one condition node into each of its successors' triggers): each
        waiting event starts at the first instant it holds, so one node means the same.

        Not for a repeated event: a player evaluates each event's trigger anew after each
        run, and SceML checks a repeated node's condition again after each run, so a shared
        condition would restart (or hold) for the other events too; and an event that waits
        for more than the condition (another actor's maneuver before it, `importer.overlaps`)
        would make the shared condition a marker event whose completion lasts, and the
        repeated event run all its runs at once (`lane_change_simple`'s teleport, three runs
        at 35.7 s, beside a speed change on the same end-of-road condition)."""
        key = (id(before), _content(condition) + (self.repeated or "").encode())
        found = self.build.conditions.get(key)
        if found is None:
            found = condition_after(self.build, condition, before, wanted)
            self.build.conditions[key] = found
        return found

    def _delayed(self, node: scm.GraphElement, delay: float, wanted: str) -> scm.GraphElement:
        if delay <= 0:
            return node
        return self.timed(node, delay, f"{wanted}_delay", "TimeElapsed", self.actor, share=True)


def first_holds(clock: etree._Element) -> float:
    """When a SimulationTimeCondition (`>` or `>=`) first holds: `>= v` at v, `> v` a step
    after v (`xosc.PLAYER_STEP`)."""
    seconds = number(clock, "value")
    if clock.get("rule") == "greaterThan" and seconds >= 0:
        seconds += PLAYER_STEP
    return seconds


def clock_start(trigger: etree._Element | None) -> float | None:
    """When a StartTrigger holds, from the run's start, if it is one SimulationTime condition
    (`>` or `>=`, with its delay) alone: the start of an act it starts, known without
    reading its nodes. No trigger: 0. None when it depends on the run."""
    if trigger is None:
        return 0.0
    conditions = trigger.findall("ConditionGroup/Condition")
    clock = trigger.find("ConditionGroup/Condition/ByValueCondition/SimulationTimeCondition")
    if len(conditions) != 1 or clock is None:
        return None
    if clock.get("rule") not in ("greaterThan", "greaterOrEqual"):
        return None
    delay = number(conditions[0], "delay", 0.0) if conditions[0].get("delay") else 0.0
    return max(first_holds(clock), 0.0) + delay


def _distinct(nodes: list[scm.GraphElement]) -> list[scm.GraphElement]:
    seen: list[scm.GraphElement] = []
    for node in nodes:
        if all(node is not other for other in seen):
            seen.append(node)
    return seen


def _content(condition: etree._Element) -> bytes:
    """What a condition tests, with its delay and edge, without its name."""
    body = b"".join(etree.tostring(child, with_tail=False) for child in condition)
    return b"%s|%s|%s" % (
        str(condition.get("delay", "0")).encode(),
        str(condition.get("conditionEdge", "none")).encode(),
        body,
    )

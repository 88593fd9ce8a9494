"""The Storyboard to the graph: each Event to nodes, in the order their triggers need them.

Events are imported on demand: reading a StartTrigger that waits for another element imports
that element first, so a trigger that (through others) waits for itself is found and refused as
circular. A SceML export's marker and extra events are folded back (`markers.py`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from lxml import etree

import scemlmodel as scm

from ..model import params
from ..model.axes import maneuver_axes
from ..xosc.support import repeatable
from . import markers, traced
from .actions import Motion, Request, map_action
from .context import Build, last_name
from .opaque import opaque_node
from .standing import left_standing, on_same_trigger, stands_at_start
from .triggers import Trigger, clock_start

#: States that mean "has finished" and "has started" (the others are read as started).
FINISHED = ("completeState", "endTransition", "stopTransition", "skipTransition")


@dataclass
class Event:
    """One Event with where it sits: its actors and the act whose start it waits for."""

    element: etree._Element
    name: str
    actors: list[scm.Actor]
    act: str


@dataclass
class Storyboard:
    """The import of the Storyboard's events, one node (or a few) per event."""

    build: Build
    motion: Motion = field(default_factory=Motion)
    events: dict[str, Event] = field(default_factory=dict)
    #: Element name (action, maneuver, group, act, story) -> the events it holds.
    holds: dict[str, list[str]] = field(default_factory=dict)
    #: Action name, and `Event::Action`, -> (its event, its index among the event's actions).
    actions: dict[str, tuple[str, int]] = field(default_factory=dict)
    finish: dict[str, scm.GraphElement] = field(default_factory=dict)
    started: dict[str, scm.GraphElement] = field(default_factory=dict)
    by_action: dict[tuple[str, int], scm.GraphElement] = field(default_factory=dict)
    act_start: dict[str, scm.GraphElement] = field(default_factory=dict)
    acts: dict[str, etree._Element] = field(default_factory=dict)
    _busy: list[str] = field(default_factory=list)
    _joins: dict[str, scm.GraphElement] = field(default_factory=dict)

    def collect(self) -> None:
        """Index every story element by name; each actor starts at its initial speed."""
        for node in self.build.scenario.nodes:  # Init's, made before any event: first
            if isinstance(node, scm.ActionNode):
                self.build.event_order.setdefault(id(node), -1)
        for actor in self.build.actors.values():
            name = str(actor.name)
            self.motion.speed[name] = self.build.init_speeds.get(
                name, params.concrete(actor, "initialSpeed")
            )
        storyboard = self.build.source.root.find("Storyboard")
        assert storyboard is not None
        for story in storyboard.iterchildren("Story"):
            if self.build.root.scenarioName is None:
                self.build.root.scenarioName = story.get("name")
            for act in story.iterchildren("Act"):
                self.acts[str(act.get("name"))] = act
                self._act(str(story.get("name")), act)
                stop = act.find("StopTrigger")
                if stop is not None and len(stop):
                    self.build.report.add(
                        "not represented",
                        f"act {act.get('name')!r}: its StopTrigger (SceML nodes are not cancelled)",
                        self.build.where(stop),
                    )

    def _act(self, story: str, act: etree._Element) -> None:
        act_name = str(act.get("name"))
        for group in act.iterchildren("ManeuverGroup"):
            actors = self._actors(group)
            for maneuver in group.iterchildren("Maneuver"):
                for event in maneuver.iterchildren("Event"):
                    name = self._unique(str(event.get("name")), maneuver, event)
                    self.events[name] = Event(event, name, actors, act_name)
                    for holder in (story, act_name, group.get("name"), maneuver.get("name")):
                        self.holds.setdefault(str(holder), []).append(name)
                    for index, action in enumerate(event.iterchildren("Action")):
                        self.actions.setdefault(str(action.get("name")), (name, index))
                        # A reference may name the action within its event, `Event::Action`
                        # (`cut-in_cr`: every event's action is called `Action`).
                        qualified = f"{event.get('name')}::{action.get('name')}"
                        self.actions.setdefault(qualified, (name, index))

    def _unique(self, name: str, maneuver: etree._Element, event: etree._Element) -> str:
        """The event's name, or, when an earlier event has it, `name_in_<maneuver>[_n]`.

        esmini accepts one event name in several maneuvers; a reference by the bare name means
        the first of them (reported).
        """
        if name not in self.events:
            return name
        unique, number = f"{name}_in_{maneuver.get('name')}", 1
        while unique in self.events:  # a catalog maneuver used twice repeats its names
            number += 1
            unique = f"{name}_in_{maneuver.get('name')}_{number}"
        self.build.report.add(
            "guessed",
            f"a second event named {name!r} (in maneuver {maneuver.get('name')!r}) is "
            f"{unique!r}; references by the name mean the first",
            self.build.where(event),
        )
        return unique

    def _actors(self, group: etree._Element) -> list[scm.Actor]:
        refs = group.findall("Actors/EntityRef")
        if refs:
            return [self.build.actor(ref.get("entityRef"), ref) for ref in refs]
        self.build.report.add(
            "guessed",
            f"maneuver group {group.get('name')!r} names no actor: its actions are given to the ego",
            self.build.where(group),
        )
        return [self.build.default_actor()]

    def run(self) -> None:
        """Import every event, in document order (triggers pull in what they wait for)."""
        for name in list(self.events):
            self.event(name)

    # --- one event --------------------------------------------------------------------------

    def event(self, name: str) -> scm.GraphElement:
        """The node whose finish is the event's completion (importing the event if needed)."""
        if name in self.finish:
            return self.finish[name]
        info = self.events[name]
        if name in self._busy:
            chain = " -> ".join([*self._busy[self._busy.index(name) :], name])
            raise self.build.source.error(
                f"circular trigger: {chain}", info.element.find("StartTrigger")
            )
        self._busy.append(name)
        try:
            node = self._import(info)
        finally:
            self._busy.pop()
        self.finish[name] = node
        return node

    def _import(self, info: Event) -> scm.GraphElement:
        folded = markers.base_of(
            self.build, info.name, {n: e.element for n, e in self.events.items()}
        )
        if folded is not None:
            return self.event(folded[0])
        actor = info.actors[0]
        kind = markers.hint(self.build, info.name)
        # Only a marker's delay is a KeepVelocity's duration; a delay in a KeepVelocity's own
        # StartTrigger is a wait before it (written there by the export, xosc.flows).
        marker = markers.is_marker(self.build, info.element)
        trigger = Trigger(
            self.build,
            self.resolve,
            lambda: self._act_start(info.act),
            actor,
            "KeepVelocity" if kind == "KeepVelocity" and marker else "TimeElapsed",
            clock_start(self.acts[info.act].find("StartTrigger")),
            info.name if int(info.element.get("maximumExecutionCount", "1")) > 1 else None,
        )
        start = info.element.find("StartTrigger")
        if marker:
            node = trigger.node(start, info.name, info.name)
            self.started[info.name] = node
            self._report_marker(info, node)
            return node
        activation = trigger.node(start, None, f"{info.name}_start")
        self.started[info.name] = activation
        # Only a speed change is read from the speed before; the last speed set stays for the
        # events read after this one, which need not follow it in time.
        if info.element.find("Action//SpeedAction") is not None:
            for each in info.actors:
                if stands_at_start(self.build, start, each):
                    self._standing(
                        each,
                        f"{info.name}: {each.name}'s speed before taken as 0 m/s "
                        "(its trigger holds while it stands)",
                        info.element,
                    )
        nodes: list[scm.GraphElement] = []
        #: Per actor, the node a step speed change leaves for the next action to follow.
        after: dict[str, scm.GraphElement] = {}
        for index, action in enumerate(info.element.iterchildren("Action")):
            for each in info.actors:
                made = self._action(info, action, each, kind)
                before = activation
                if not _beside_speed(made, action):
                    before = after.pop(str(each.name), activation)
                if before is not activation:
                    nodes.remove(before)
                    self.build.report.add(
                        "guessed",
                        f"{made.name}: after {before.name}, an instantaneous speed change of the "
                        "same event (SceML runs one longitudinal maneuver of an actor at a time)",
                        self.build.where(action),
                    )
                self.build.flow(before, made)
                self.by_action[(info.name, index)] = made
                nodes.append(made)
                if _is_step_speed(action):
                    after[str(each.name)] = made
        self._runs(info, nodes)
        self._left_standing(info)
        place = list(self.events).index(info.name)
        for made in nodes:
            self.build.event_order[id(made)] = place
        if len(nodes) == 1:
            return nodes[0]
        join = self.build.add(scm.JoinAllFinished(), f"{info.name}_done")
        for made in nodes:
            self.build.flow(made, join)
        return join

    def _left_standing(self, info: Event) -> None:
        """Once the last event on a standing trigger has been read, the actors it leaves
        standing (`standing.left_standing`) have 0 m/s before their next speed change."""
        if info.element.find("StartTrigger//EndOfRoadCondition") is None:
            return  # the common case, without a look at every other event
        everything = [(e.element, e.actors) for e in self.events.values()]
        for each in info.actors:
            same = on_same_trigger(self.build, everything, info.element, each)
            unread = [e for e in same if e is not info.element and not self._read(e)]
            if same and not unread and left_standing(same):
                self._standing(
                    each,
                    f"{each.name} stands at the end of its road after {info.name}'s last run "
                    "(an event on the same trigger with no speed change runs more often)",
                    info.element,
                )

    def _standing(self, actor: scm.Actor, why: str, element: etree._Element) -> None:
        """`actor` has 0 m/s before its next speed change: a guess, reported with `why`."""
        self.motion.speed[str(actor.name)] = 0.0
        self.build.report.add("guessed", why, self.build.where(element))

    def _read(self, element: etree._Element) -> bool:
        return any(e.element is element and n in self.finish for n, e in self.events.items())

    def _runs(self, info: Event, nodes: list[scm.GraphElement]) -> None:
        """The event's maximumExecutionCount as its nodes' maxRuns (one action, or controller
        changes only, of kinds the export writes as one event); otherwise reported: SceML
        repeats nodes one by one, not a group, and players cannot repeat an event together
        with the event of its finish."""
        count = int(info.element.get("maximumExecutionCount", "1"))
        if count <= 1:
            return
        # Controller changes complete at once: each repeating on the event's trigger runs
        # with the others, as the event's actions do (`acc-toggle` assigns and activates).
        together = len(nodes) == 1 or all(isinstance(n, scm.ControllerManeuver) for n in nodes)
        if together and all(
            isinstance(n, scm.ActionNode) and repeatable(n.eClass.name) for n in nodes
        ):
            for node in nodes:
                node.maxRuns = count
                self.build.report.add(
                    "mapped",
                    f"{node.name}: maximumExecutionCount {count} -> maxRuns",
                    self.build.where(info.element),
                    str(node.name),
                )
            return
        self.build.report.add(
            "not represented",
            f"event {info.name!r} may run {count} times; SceML repeats only a node of one "
            "action that is written back as one event",
            self.build.where(info.element),
        )

    def _report_marker(self, info: Event, node: scm.GraphElement) -> None:
        told = any(entry.node == node.name for entry in self.build.report.entries)
        if node.name == info.name and not told:
            self.build.report.add(
                "mapped",
                f"{node.name}: SceML marker event -> {node.eClass.name}",
                self.build.where(info.element),
                str(node.name),
            )

    def _action(
        self, info: Event, action: etree._Element, actor: scm.Actor, kind: str | None
    ) -> scm.GraphElement:
        request = Request(action, actor, info.name, kind)
        extras = {
            suffix: self.events[f"{info.name}__{suffix}"].element
            for suffix in markers.SUFFIXES
            if f"{info.name}__{suffix}" in self.events and self.build.from_sceml
        }
        made: scm.ActionNode | str | None = None
        if kind == "DriveDistance" and "driven" in extras:
            made = markers.drive_distance(self.build, request, extras["driven"], self.motion)
        elif kind == "KeepVelocity" and "kept" in extras:
            made = markers.keep_velocity(self.build, request, extras["kept"])
        elif kind == "Overtake" and "back" in extras:
            made = markers.overtake(self.build, info.element, request, extras["back"], self.motion)
        if made is None:
            made = map_action(self.build, request, self.motion)
        if isinstance(made, str):
            return opaque_node(self.build, action, actor, info.name, made)
        arrival = extras.get("arrived")
        limit = None if arrival is None else markers.tolerance(arrival)
        if limit is not None and made.eClass.findEStructuralFeature("tolerance") is not None:
            made.tolerance = traced.value(limit)
        return made

    def _act_start(self, act: str) -> scm.GraphElement:
        if act not in self.act_start:
            element = self.acts[act]
            trigger = Trigger(self.build, self.resolve, self.build.root, self.build.default_actor())
            self.act_start[act] = trigger.node(element.find("StartTrigger"), None, f"{act}_start")
        return self.act_start[act]

    # --- what a StoryboardElementStateCondition waits for -----------------------------------

    def resolve(self, state: etree._Element) -> scm.GraphElement:
        """The node a state condition refers to: finished, or (other states) started."""
        full = str(state.get("storyboardElementRef"))
        ref = last_name(full)
        kind = state.get("storyboardElementType")
        done = state.get("state") in FINISHED
        if kind == "action" and "::".join(full.split("::")[-2:]) in self.actions:
            ref = "::".join(full.split("::")[-2:])
        if kind == "event" and ref in self.events:
            node = self.event(ref)
            return node if done else self._started(ref, state)
        if kind == "action" and ref in self.actions:
            event, index = self.actions[ref]
            self.event(event)
            return (
                self.by_action.get((event, index), self.finish[event])
                if done
                else self._started(event, state)
            )
        if ref in self.holds and kind in ("maneuver", "maneuverGroup", "act", "story"):
            names = self.holds[ref]
            if not done:
                return self._container_started(kind, self.events[names[0]].act, state)
            return self._all_of(ref, [self.event(n) for n in names])
        raise self.build.source.error(
            f"the condition refers to an unknown {kind} {ref!r} (dangling storyboard reference)",
            state,
        )

    def _container_started(
        self, kind: str | None, act: str, state: etree._Element
    ) -> scm.GraphElement:
        """When a story, act, maneuver group or maneuver is running: its act started (a story
        at the start). Not its first event's activation: an event of it may wait for this."""
        self.build.report.add(
            "mapped",
            f"'{state.get('state')}' of {kind} {state.get('storyboardElementRef')!r}: when "
            + ("the scenario starts" if kind == "story" else f"act {act!r} starts"),
            self.build.where(state),
        )
        return self.build.root if kind == "story" else self._act_start(act)

    def _started(self, event: str, state: etree._Element) -> scm.GraphElement:
        self.event(event)
        self.build.report.add(
            "guessed",
            f"'{state.get('state')}' of {state.get('storyboardElementRef')!r} read as: when it is activated",
            self.build.where(state),
        )
        return self.started[event]

    def _all_of(self, holder: str, nodes: list[scm.GraphElement]) -> scm.GraphElement:
        unique = [n for i, n in enumerate(nodes) if all(n is not m for m in nodes[:i])]
        if len(unique) == 1:
            return unique[0]
        if holder not in self._joins:
            join = self.build.add(scm.JoinAllFinished(), f"{holder}_done")
            for node in unique:
                self.build.flow(node, join)
            self._joins[holder] = join
        return self._joins[holder]


def _is_step_speed(action: etree._Element) -> bool:
    """A speed action that changes the speed at once (it completes as soon as it starts)."""
    dynamics = action.find("PrivateAction/LongitudinalAction/SpeedAction/SpeedActionDynamics")
    return dynamics is not None and dynamics.get("dynamicsShape") == "step"


def _beside_speed(node: scm.GraphElement, action: etree._Element) -> bool:
    """A maneuver that leaves the speed alone (a lane change, a FollowTrajectory: `model.axes`)
    runs beside a step speed change of its event, as players run them, not after it; so does
    an opaque trajectory followed without timing (a clothoid: `trailer_connect`'s reverse
    started a step after its speed, and esmini then left the car standing)."""
    if isinstance(node, scm.OpaqueAction):
        return action.find(_UNTIMED_TRAJECTORY) is not None
    return isinstance(node, scm.Maneuver) and "longitudinal" not in maneuver_axes(node)


#: A FollowTrajectoryAction followed at the actor's speed: players leave the speed alone.
_UNTIMED_TRAJECTORY = "PrivateAction/RoutingAction/FollowTrajectoryAction/TimeReference/None"

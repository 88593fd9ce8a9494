"""The scheduler: SPEC §3 on a concrete scenario, one fixed time step after another.

At t = 0 the root finishes and actors stand at their starts. A node that finishes makes each
successor whose incoming flows are satisfied (one predecessor finished for an ordinary node,
all for JoinAllFinished and a join-all end, one for JoinOneFinished and a join-one end) ready;
a ready node is activated one time step later (`xosc.meaning.FLOW_DELAY_STEPS`), as players
evaluate a trigger in the step after the event it waits for completed, and is checked at once;
a node after one the export writes into its trigger (`xosc.flows.inlined`) is activated in
the same instant, as the player starts it in the step the condition holds.
Each step begins by activating the nodes due at its end instant (so a maneuver acts in the
step its node starts, as a player's action does), then all actors move, each speed decided
from the same state, then every active node is checked. The run ends when the end node
finishes or at the maximum duration.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.graph import finishes_with_first, predecessors, successors
from ..xosc import meaning
from ..xosc.flows import flow_steps, inlined
from . import global_values, trailers
from .behaviours import Behaviour, behaviour_for
from .conditions import Test, condition_for
from .run import END_NODE, MAX_DURATION, NodeRecord
from .world import SimulationError, World

#: Steps between two calls of a progress callback.
PROGRESS_EVERY = 200


@dataclass(eq=False)
class NodeState:
    """One node while the scenario runs."""

    node: EObject
    name: str
    kind: str
    actor: str | None
    needs_all: bool
    predecessors: list[NodeState] = field(default_factory=list)
    successors: list[NodeState] = field(default_factory=list)
    started: float | None = None
    finished: float | None = None
    behaviour: Behaviour | None = None
    test: Test | None = None
    note: str = ""
    #: When a trigger that holds in the instant started it (`xosc.flows.inlined`); its
    #: behaviour begins at the next step.
    since: float | None = None
    #: How many times the node may run (`maxRuns`), and the runs finished so far.
    max_runs: int = 1
    runs: int = 0
    #: When its first run started (the timeline shows the first start and the last finish).
    first_started: float | None = None
    #: When a maneuver that took its part started: it finished then (`xosc.meaning`).
    ended_by_other: float | None = None

    def ready(self) -> bool:
        done = [p.finished is not None for p in self.predecessors]
        return bool(done) and (all(done) if self.needs_all else any(done))

    def record(self) -> NodeRecord:
        started = self.started if self.first_started is None else self.first_started
        return NodeRecord(self.name, self.kind, self.actor, started, self.finished, self.note)


class Scheduler:
    """The flow semantics over a world; `advance` runs one step, `ended` says when to stop."""

    def __init__(self, nodes: list[EObject], world: World) -> None:
        self.world = world
        self.states = {node: _state(node) for node in nodes}
        for node, state in self.states.items():
            state.predecessors = [self.states[p] for p in predecessors(node) if p in self.states]
            state.successors = [self.states[s] for s in successors(node) if s in self.states]
        self.active: list[NodeState] = []
        #: Nodes whose predecessors have finished, with the instant they are activated at.
        self.ready: list[tuple[float, NodeState]] = []
        #: Nodes whose outgoing flow costs no step (`xosc.flows.inlined`).
        self.inline = inlined(nodes)
        self.owners: dict[tuple[str, str], NodeState] = {}
        self.ended = False

    def begin(self) -> None:
        """The root nodes finish at t = 0 and what follows them is activated."""
        self._settle([s for s in self.states.values() if isinstance(s.node, scm.RootNode)])

    def activate_due(self) -> None:
        """Activate the nodes due at the current instant, before the actors move in the step
        it begins (as players start an event's actions in the step its trigger fires)."""
        due = [state for when, state in self.ready if when <= self.world.t + 1e-9]
        self.ready = [(when, state) for when, state in self.ready if when > self.world.t + 1e-9]
        finished: list[NodeState] = []
        for state in due:
            finished.extend(self._activate(state))
        self._settle(finished)

    def check(self) -> None:
        """Check every active node at the current instant and settle what follows."""
        self._settle([state for state in list(self.active) if self._done(state)])

    def stopped_at_road_end(self, actor: str) -> None:
        """Note that an actor stopped at the end of its road, on the run and on every maneuver
        of the actor then running."""
        text = f"{actor} stopped at the end of its road at {self.world.t:.2f} s (no road on)"
        self.world.note(text)
        for state in self.active:
            if state.actor == actor and isinstance(state.node, scm.Maneuver):
                state.note = "; ".join(filter(None, [state.note, text]))

    def timeline(self) -> tuple[NodeRecord, ...]:
        return tuple(state.record() for state in self.states.values())

    # --- the flow semantics ------------------------------------------------------------------

    def _settle(self, finished: list[NodeState]) -> None:
        queue = deque(finished)
        while queue:
            state = queue.popleft()
            if state.finished is not None:
                continue
            if state.runs + 1 < state.max_runs:
                queue.extend(self._run_again(state))
                continue
            self._finish(state)
            if isinstance(state.node, scm.EndNode):
                self.ended = True
                return
            for successor in state.successors:
                waiting = any(successor is other for _, other in self.ready)
                if successor.started is None and not waiting and successor.ready():
                    when = self._activated_at(successor)
                    if when > self.world.t + 1e-9:
                        self.ready.append((when, successor))
                    elif isinstance(successor.node, scm.Maneuver):
                        # Started now by a trigger that holds now: it acts from the next
                        # step, as the player's action does (one started after a flow step
                        # acts in the step it starts, the preview's convention).
                        successor.since = self.world.t
                        self.ready.append((round(self.world.t + self.world.dt, 9), successor))
                    else:
                        queue.extend(self._activate(successor))

    def _run_again(self, state: NodeState) -> list[NodeState]:
        """A run of a node with runs left has finished: it waits for its activation to hold
        anew. A condition before it is checked again (the node runs once it holds again); any
        other predecessor stays finished, so the node runs again one step later, as a player
        restarts an event whose trigger still holds. The conditions that hold at once."""
        state.runs += 1
        if state.first_started is None:
            state.first_started = state.started
        if state in self.active:
            self.active.remove(state)
        state.started, state.since, state.test, state.behaviour = None, None, None, None
        state.ended_by_other = None
        for key, owner in list(self.owners.items()):
            if owner is state:
                del self.owners[key]
        conditions = [p for p in state.predecessors if isinstance(p.node, scm.Condition)]
        if not conditions:
            self.ready.append((round(self.world.t + self.world.dt, 9), state))
            return []
        holding = []
        for before in conditions:
            if before.first_started is None:
                before.first_started = before.started
            before.finished = None
            holding.extend(self._activate(before))
        return holding

    def _activated_at(self, state: NodeState) -> float:
        """When a ready node is activated: each finished predecessor's finish plus what its
        flow costs (`xosc.flows.flow_steps`); the last of them, or the first for a
        join-one."""
        times = [
            round(p.finished + flow_steps(p.node, self.inline) * self.world.dt, 9)
            for p in state.predecessors
            if p.finished is not None
        ]
        return max(times) if state.needs_all else min(times)

    def _finish(self, state: NodeState) -> None:
        state.finished = self.world.t if state.ended_by_other is None else state.ended_by_other
        if state.started is None:
            state.started = self.world.t
        if state in self.active:
            self.active.remove(state)
        for key, owner in list(self.owners.items()):
            if owner is state:
                del self.owners[key]

    def _activate(self, state: NodeState) -> list[NodeState]:
        """Start a node; the nodes that finish because of it (itself, superseded ones)."""
        state.started = self.world.t if state.since is None else state.since
        node = state.node
        if isinstance(node, scm.Condition):
            state.test = condition_for(node, self.world)
            if isinstance(node, scm.TrafficSignalCondition):
                state.note = global_values.NO_SIGNALS.format(what="it never holds")
            elif state.test is None:
                state.note = "this condition kind is not simulated: it never holds"
        elif isinstance(node, scm.Maneuver):
            return self._start_maneuver(state)
        elif isinstance(node, scm.GlobalAction):
            # Players complete a global action in the step it starts.
            state.note = global_values.apply(node, self.world) or ""
            return [state]
        elif not isinstance(node, scm.EndNode | scm.JoiningPolicy | scm.InPort | scm.OutPort):
            state.note = f"a {state.kind} is not simulated: it finishes at once"
            return [state]
        else:
            return [state]  # joins and ports finish when activated; so does a ready end node
        self.active.append(state)
        return [state] if self._done(state) else []

    def _start_maneuver(self, state: NodeState) -> list[NodeState]:
        if meaning.completes_at_once(state.kind):
            state.note = (
                f"{state.kind}, a controller change, finishes at once; the preview runs no "
                "controller and ignores what it would do"
            )
            return [state]
        behaviour = behaviour_for(state.node, self.world)
        if behaviour is None:
            state.note = f"{state.kind} is not simulated: it finishes at once"
            return [state]
        superseded = []
        for part in behaviour.claims:
            previous = self.owners.get((behaviour.actor.name, part))
            if previous is not None and previous.finished is None:
                # Ended when the other started (players end the running action of the
                # domain then), a step before the other acts if a trigger started it.
                how = "interrupted" if state.node.interrupts else "superseded"
                previous.note = f"{how} by {state.name}"
                previous.ended_by_other = state.started
                if previous.behaviour is not None:
                    previous.behaviour.release(self.world)
                superseded.append(previous)
            self.owners[(behaviour.actor.name, part)] = state
        state.behaviour = behaviour
        behaviour.started_at = state.started
        behaviour.start(self.world)
        self.active.append(state)
        return [*superseded, state] if behaviour.done(self.world) else superseded

    def _done(self, state: NodeState) -> bool:
        if state.behaviour is not None:
            return state.behaviour.done(self.world)
        return state.test is not None and state.test(self.world)


def _state(node: EObject) -> NodeState:
    actor = getattr(node, "referenceActor", None)
    needs_all = not finishes_with_first(node)
    return NodeState(
        node,
        str(node.name),
        node.eClass.name,
        str(actor.name) if actor is not None else None,
        needs_all,
        max_runs=max(1, int(getattr(node, "maxRuns", 1))),
    )


def run_schedule(
    scheduler: Scheduler,
    max_duration: float,
    record: Callable[[], None],
    progress: Callable[[int, int], None] | None = None,
) -> str:
    """Step until the end node finishes or the maximum duration; the reason it ended.

    `record` is called with no arguments after each instant settles; `progress`, if given,
    with (steps done, most steps) every `PROGRESS_EVERY` steps.
    """
    world = scheduler.world
    if world.dt <= 0:
        raise SimulationError(f"the time step must be positive, got {world.dt:g} s")
    steps = round(max_duration / world.dt)
    scheduler.begin()
    record()
    actors = list(world.actors.values())
    for k in range(1, steps + 1):
        if scheduler.ended:
            return END_NODE
        world.t = round(k * world.dt, 9)
        scheduler.activate_due()
        speeds = [actor.control.next_speed(actor, world.actors, world.dt) for actor in actors]
        for actor, speed in zip(actors, speeds, strict=True):
            if not actor.towed and actor.advance_to(speed, world.dt):
                scheduler.stopped_at_road_end(actor.name)
        trailers.drag(world.actors, world.couplings)
        scheduler.check()
        record()
        if progress is not None and k % PROGRESS_EVERY == 0:
            progress(k, steps)
    return END_NODE if scheduler.ended else MAX_DURATION

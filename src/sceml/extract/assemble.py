"""Events and explanations made into a SceML graph, one branch (or a few) per actor.

Each actor's maneuvers follow each other in the order they started. A maneuver is chained to
the node of the actor that finished last before it had to start; when it started noticeably
later, the explanation (`sync.explain`) goes between them as a condition node. A turn or a
crossing is followed by its arrival check (InLocationRadius at its destination), which is how
the export knows it has finished (SPEC §7). When every node of the actor is still running at
a maneuver's start (a lane change during a speed change), the maneuver gets a branch of its
own from the root, with its wait in front.

Timing follows the players (docs/simulate.md): every flow costs a step
(`players.meaning.FLOW_DELAY_STEPS`), and a maneuver acts in the step its node starts, so a
recording shows its motion change a step before the node's start. A maneuver right after
another therefore shows at its predecessor's finish, as recorded. A wait adds a flow: its
condition is aimed at when it must hold for the maneuver to show at its recorded start, and
a timed wait is shorter than the gap it fills by what the flows cost beyond that step.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, cast

import numpy as np

import scemlmodel as scm

from ..build import ScenarioBuilder, world
from ..params import value
from ..players.meaning import FLOW_DELAY_STEPS
from ..simulate import DEFAULT_STEP
from .events import Event
from .motion import Motion
from .sync import Explanation, explain
from .thresholds import Thresholds

#: How long (s) a flow delays its successor in a replay, which runs at the preview's step.
FLOW_DELAY = FLOW_DELAY_STEPS * DEFAULT_STEP
#: How long (s) before its node's start a maneuver shows: it acts in the step it starts.
SHOWS_EARLY = DEFAULT_STEP


@dataclass(frozen=True)
class Inferred:
    """A condition the extraction put before a maneuver, and why."""

    node: str
    maneuver: str
    actor: str
    start: float
    explanation: Explanation


@dataclass
class _Tail:
    node: scm.GraphElement
    finish: float


def add_actor_graph(
    builder: ScenarioBuilder,
    actor: scm.Actor,
    events: list[Event],
    motions: dict[str, Motion],
    actors: dict[str, scm.Actor],
    ego: str | None,
    thresholds: Thresholds,
    speed_changes: dict[str, list[Event]],
) -> list[Inferred]:
    """Add one actor's maneuvers (with their waits) from the root to the end node;
    `speed_changes` are every actor's extracted speed changes (for speed conditions)."""
    name = str(actor.name)
    own = motions[name]
    begin = _Tail(builder.root, float(own.times[0]))
    tails = [begin]
    inferred: list[Inferred] = []
    for event in sorted(events, key=lambda e: e.start):
        tail = _tail_for(event, tails, begin, thresholds)
        why = None
        if not event.flexible and event.start - tail.finish > _least_wait(event, thresholds):
            driving = own.at(own.speed, event.start) > thresholds.standing_speed
            driving = driving and not _speed_changing(events, tail.finish, event.start)
            why = _explain_start(
                event, tail.finish, motions, ego, thresholds, driving, speed_changes, own.step
            )
        node = builder.add(event.kind, actor, **_node_parameters(event.parameters, event))
        if why is not None:
            condition = _condition(builder, why, actors)
            builder.chain(tail.node, condition, node)
            inferred.append(Inferred(str(condition.name), str(node.name), name, event.start, why))
        else:
            builder.flow(tail.node, node)
        tails.append(_Tail(_arrival(builder, actor, node, event), max(event.finish, event.start)))
    for tail in tails:
        if tail.node is not builder.root:
            builder.flow(tail.node, builder.end)
    return inferred


#: The order in which explanations are preferred: the simplest first (`sync.explain`).
_SIMPLEST = ("InVehicleRadius", "SpeedCondition", "InLocationRadius")


def _explain_start(
    event: Event,
    activation: float,
    motions: dict[str, Motion],
    ego: str | None,
    thresholds: Thresholds,
    driving: bool,
    speed_changes: dict[str, list[Event]],
    step: float,
) -> Explanation:
    """Why `event` started after waiting since `activation` (when the node before finished).

    The condition starts a flow after that node finished, and holds a flow before the
    maneuver's node starts (which is when the maneuver shows, plus SHOWS_EARLY). On a noisy
    recording a speed change's start is known only within its `start_range`: each start in
    it (nearest the fitted one first) is tried, the simplest explanation found anywhere in it
    is taken, and the change is retimed to start where that explanation puts it.
    """
    starts = [event.start]
    if event.start_range is not None:
        low, high = event.start_range
        others = np.arange(max(low, activation + step), high + 1e-9, step)
        starts += sorted((float(s) for s in others), key=lambda s: abs(s - event.start))

    def explained(start: float) -> Explanation:
        return explain(
            event.actor,
            start + SHOWS_EARLY - FLOW_DELAY,
            activation + FLOW_DELAY,
            motions,
            ego,
            thresholds,
            driving=driving,
            speed_changes=speed_changes,
        )

    found = [(start, explained(start)) for start in starts]
    rank = {kind: k for k, kind in enumerate(_SIMPLEST)}
    best_start, best = min(found, key=lambda pair: rank.get(pair[1].kind, len(rank)))
    if best_start != event.start:
        event.retime(best_start)
    return best


def _tail_for(event: Event, tails: list[_Tail], begin: _Tail, thresholds: Thresholds) -> _Tail:
    """The node a maneuver follows: the actor's node that finished last before it started.

    A turn or a walk may start later than it shows, so it follows the latest node in any case;
    any other maneuver that started while all the actor's nodes ran gets a branch of its own.
    """
    slack = max(thresholds.sync_tolerance, _least_wait(event, thresholds))
    ready = [t for t in tails if t.finish <= event.start + slack]
    if not ready and not event.flexible:
        return _Tail(begin.node, begin.finish)
    tail = max(ready or tails, key=lambda t: t.finish)
    tails.remove(tail)
    return tail


def _arrival(
    builder: ScenarioBuilder, actor: scm.Actor, node: scm.ActionNode, event: Event
) -> scm.GraphElement:
    """After a turn or crossing, the check that it arrived; the node itself otherwise."""
    if event.destination is None:
        return node
    arrived = builder.add(
        "InLocationRadius",
        actor,
        position=_place(event.destination),
        radius=event.parameters.get("tolerance", 2.0),
    )
    builder.flow(node, arrived)
    return arrived


def _least_wait(event: Event, thresholds: Thresholds) -> float:
    """The shortest gap that needs a wait: a crossing's start (its bend, judged only once the
    actor is under way) is known only to within the smoothing window, the others to within
    `min_wait`."""
    if event.kind == "Cross":
        return max(thresholds.min_wait, thresholds.smoothing_window)
    return thresholds.min_wait


def _speed_changing(events: list[Event], begin: float, end: float) -> bool:
    """Whether a speed change of the actor runs during [begin, end] (KeepVelocity would stop it)."""
    return any(e.longitudinal and e.start < end and e.finish > begin for e in events)


def _position(point: tuple[float, float, float]) -> scm.WorldPosition:
    x, y, h = point
    return world(round(x, 3), round(y, 3), h=round(h, 4))


def _place(point: tuple[float, float, float]) -> scm.WorldPosition:
    """A place a condition waits for: no heading, which a circle about it does not have (and a
    heading against the lane's traffic, of an actor overtaking, would be flagged)."""
    x, y, _ = point
    return scm.WorldPosition(x=value(round(x, 3)), y=value(round(y, 3)))


def _node_parameters(parameters: dict[str, object], event: Event | None = None) -> dict[str, Any]:
    """Parameters as the builder takes them: points (x, y, heading) become world positions
    (a condition's `position` a place without heading)."""
    made: dict[str, Any] = {}
    for key, item in parameters.items():
        if isinstance(item, tuple):
            point = cast(tuple[float, float, float], item)
            made[key] = _place(point) if key == "position" else _position(point)
        else:
            made[key] = item
    if event is not None and event.destination is not None:
        made["destination"] = _position(event.destination)
    return made


def _condition(
    builder: ScenarioBuilder, why: Explanation, actors: dict[str, scm.Actor]
) -> scm.ActionNode:
    target = actors[why.target] if why.target else None
    return builder.add(
        why.kind, actors[why.actor], target=target, **_node_parameters(why.parameters)
    )

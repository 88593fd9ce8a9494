"""Events and explanations made into a SceML graph, one branch (or a few) per actor.

Each actor's maneuvers follow each other in the order they started. A maneuver is chained to
the node of the actor that finished last before it had to start; when it started noticeably
later, the explanation (`sync.explain`) goes between them as a condition node. A turn or a
crossing is followed by its arrival check (InLocationRadius at its destination), which is how
the export knows it has finished (SPEC §7). When every node of the actor is still running at
a maneuver's start (a lane change during a speed change), the maneuver gets a branch of its
own from the root, with its wait in front.
"""

from __future__ import annotations

from dataclasses import dataclass

import scemlmodel as scm

from ..build import ScenarioBuilder, world
from .events import Event
from .motion import Motion
from .sync import Explanation, explain
from .thresholds import Thresholds


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
) -> list[Inferred]:
    """Add one actor's maneuvers (with their waits) from the root to the end node."""
    name = str(actor.name)
    own = motions[name]
    t0 = float(own.times[0])
    tails = [_Tail(builder.root, t0)]
    inferred: list[Inferred] = []
    for event in sorted(events, key=lambda e: e.start):
        ready = [t for t in tails if t.finish <= event.start + thresholds.sync_tolerance]
        if ready or event.flexible:
            # A turn or a walk may start later than it shows: it goes after the latest node.
            tail = max(ready or tails, key=lambda t: t.finish)
            tails.remove(tail)
        else:
            tail = _Tail(builder.root, t0)  # a branch of its own
        parameters = dict(event.parameters)
        if event.destination is not None:
            x, y, h = event.destination
            parameters["destination"] = world(round(x, 3), round(y, 3), h=round(h, 4))
        node = builder.add(event.kind, actor, **parameters)
        wait = event.start - tail.finish
        if not event.flexible and wait > thresholds.min_wait:
            driving = own.at(
                own.speed, event.start
            ) > thresholds.standing_speed and not _speed_changing(events, tail.finish, event.start)
            why = explain(name, event.start, tail.finish, motions, ego, thresholds, driving=driving)
            condition = _condition(builder, why, actors)
            builder.chain(tail.node, condition, node)
            inferred.append(Inferred(str(condition.name), str(node.name), name, event.start, why))
        else:
            builder.flow(tail.node, node)
        last: scm.GraphElement = node
        if event.destination is not None:
            last = builder.add(
                "InLocationRadius",
                actor,
                position=parameters["destination"],
                radius=event.parameters.get("tolerance", thresholds.arrival_tolerance),
            )
            builder.flow(node, last)
        tails.append(_Tail(last, max(event.finish, event.start)))
    for tail in tails:
        if tail.node is not builder.root:
            builder.flow(tail.node, builder.end)
    return inferred


def _speed_changing(events: list[Event], begin: float, end: float) -> bool:
    """Whether a speed change of the actor runs during [begin, end] (KeepVelocity would stop it)."""
    return any(e.longitudinal and e.start < end and e.finish > begin for e in events)


def _condition(
    builder: ScenarioBuilder, why: Explanation, actors: dict[str, scm.Actor]
) -> scm.ActionNode:
    parameters = dict(why.parameters)
    if "position" in parameters:
        x, y, h = parameters["position"]  # type: ignore[misc]
        parameters["position"] = world(round(x, 3), round(y, 3), h=round(h, 4))
    target = actors[why.target] if why.target else None
    return builder.add(why.kind, actors[why.actor], target=target, **parameters)

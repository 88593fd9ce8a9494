"""Which nodes the export writes into their successor's trigger, and what a flow costs.

A player sees an event's completion in the step after it completes, so a node that is its own
(marker) event costs its successors one step (`meaning.FLOW_DELAY_STEPS`). The export writes
some nodes without an event of their own: their condition goes into the StartTrigger (or the
StopTrigger) of their only successor, ANDed with what activates them, so that the successor
starts in the step the condition holds. A flow *out of* such an *inlined* node costs no step.
The root's finish is written the same way (`SimulationTime >= 0`, true at t = 0), so a flow
out of the root costs no step either. The export, the preview, the run checker and the
comparison all ask this module which nodes are inlined, so that they keep step with each
other.

Inlining must not change what the graph means (SPEC §3): a condition finishes at the first
instant after its activation at which it holds, and stays finished. Written into a trigger it
is evaluated again at every step, so it may only stand where "holds now" and "has held" agree:

- joins and ports: what they wait for stays true once true (completions, simulation time,
  delays of those), so they go into the trigger of each successor;
- TimeElapsed: its activation delayed, true from then on, likewise;
- any other condition (SpeedCondition, InLocationRadius, an opaque Condition, ...): only into
  successors that have no other predecessor and use their activation once, as the StartTrigger
  of one event (`_USES_ACTIVATION_ONCE`), and into the end node's StopTrigger where any one
  predecessor ends the run (or it has only this one); into each of them when there are
  several (an imported event with several actions): each starts at the first instant it
  holds; likewise through a TimeElapsed whose successors are such (an original's condition
  with a delay: the wait is the condition's delay in their triggers), and through a join-one
  whose successors are such and run once (an original's trigger of several ConditionGroups:
  one group each). An arrival's finish
  marker (`__arrived`) waits for the arrival's event to have started, so it too uses the
  activation once; so does a Follow's or an Approach's (`__gap_reached`). Another maneuver
  with a finish marker (`__driven`, ...)
  ANDs its activation with its goal, another condition ANDs it with its own test, a join
  combines it with other branches: there "held once" and "holds now" differ, so the condition
  keeps its marker event.
"""

from __future__ import annotations

from collections.abc import Iterable

import scemlmodel as scm

from ..model import graph
from .meaning import FLOW_DELAY_STEPS
from .support import REPEATABLE_KINDS

#: Kinds whose export uses the activation exactly once, unchanged, as one event's StartTrigger:
#: those written as one event (`support.REPEATABLE_KINDS`: speed changes, lane changes and
#: offsets, controller changes, parameter, variable and traffic signal actions), Overtake,
#: whose first event starts on it, and the arrivals, whose finish marker waits for their event
#: to have started, not for the activation again (`export.actions._arrival_marker`). (Before,
#: a traffic signal state after a condition kept the condition's marker event:
#: `traffic_lights`' signals changed a step late, every one; its walkers, a FollowTrajectory
#: each, two steps late.)
_ARRIVAL_KINDS = frozenset({"TurnLeft", "TurnRight", "Cross", "FollowTrajectory"})
#: Follow and Approach likewise: their `__gap_reached` marker waits for their event to have
#: started (`export.distance_keeping`).
_DISTANCE_KINDS = frozenset({"Follow", "Approach"})
_USES_ACTIVATION_ONCE = REPEATABLE_KINDS | {"Overtake"} | _ARRIVAL_KINDS | _DISTANCE_KINDS
#: Kinds that only pass activation on (a marker with the activation as its trigger).
_PASSING = (scm.JoinAllFinished, scm.JoinOneFinished, scm.InPort, scm.OutPort)


def is_condition_element(node: scm.GraphElement) -> bool:
    """Whether an opaque node keeps a Condition (rather than an Action)."""
    return isinstance(node, scm.OpaqueAction) and str(node.xml or "").lstrip().startswith(
        "<Condition"
    )


def _uses_activation_once(node: scm.GraphElement) -> bool:
    if isinstance(node, scm.OpaqueAction):
        return not is_condition_element(node)
    return node.eClass.name in _USES_ACTIVATION_ONCE


def inlined(nodes: Iterable[scm.GraphElement]) -> set[scm.GraphElement]:
    """Of a (flattened) graph's nodes, those the export writes into their successor's trigger
    instead of a marker event."""
    found: set[scm.GraphElement] = set()
    for node in nodes:
        after = graph.successors(node)
        if after and (
            _passes_latched(node) or all(_holds_now_for(node, successor) for successor in after)
        ):
            found.add(node)
    return found


def _passes_latched(node: scm.GraphElement) -> bool:
    """Joins, ports and waits: what they write stays true once true."""
    return isinstance(node, (*_PASSING, scm.TimeElapsed))


def _holds_now_for(node: scm.GraphElement, successor: scm.GraphElement) -> bool:
    """A condition whose successor waits for it alone and starts one event on it, or is the
    end node (`_starts_on`); or waits for it alone through a TimeElapsed that does the same
    (the wait is the condition's `delay` in the successor's trigger, which players count from
    each instant it held, as SceML counts from its finish: an original's condition with a
    delay keeps its step)."""
    if not (isinstance(node, scm.Condition) or is_condition_element(node)):
        return False
    if _absorbed_by_end(node, successor):
        return True
    if isinstance(successor, scm.TimeElapsed) and int(getattr(successor, "maxRuns", 1)) == 1:
        after = graph.successors(successor)
        return (
            len(graph.predecessors(successor)) == 1
            and bool(after)
            and all(_starts_on_first(s) for s in after)
        )
    return _starts_on_first(successor)


def _starts_on_first(successor: scm.GraphElement) -> bool:
    """`_starts_on`, or a join-one whose successors each start once on it (`_starts_on`, one
    run): a join-one finishes with its first input, so each input may stand as it holds now
    in a ConditionGroup of its own (OR) of their triggers. An original's event with several
    ConditionGroups of conditions started a step late on their marker events."""
    if not isinstance(successor, scm.JoinOneFinished):
        return _starts_on(successor)
    after = graph.successors(successor)
    return bool(after) and all(
        _starts_on(s) and int(getattr(s, "maxRuns", 1)) == 1 and not isinstance(s, scm.EndNode)
        for s in after
    )


def _absorbed_by_end(node: scm.GraphElement, successor: scm.GraphElement) -> bool:
    """A join-all of `node` and other branches that leads only to end nodes which `node` also
    ends on its own (any one predecessor ends the run): whatever the join adds, the run has
    stopped by then, so `node` may stand in the StopTrigger as it holds now (an imported
    StopTrigger's condition, which the import also joins with the branches it does not name,
    `importer.ending`)."""
    if not isinstance(successor, scm.JoinAllFinished):
        return False
    after = graph.successors(successor)
    return bool(after) and all(
        isinstance(end, scm.EndNode)
        and graph.finishes_with_first(end)
        and node in graph.predecessors(end)
        for end in after
    )


def _starts_on(successor: scm.GraphElement) -> bool:
    """Whether `successor` acts at the first instant its activation holds, once: a node that
    waits for one predecessor and starts one event on it, or the end node when any one
    predecessor ends the run (or it has one): the StopTrigger stops the run in the step one
    of its groups holds, so "holds now" and "has held" agree there too (a condition as a
    marker event before it stopped `pedestrian_traj_synch` two steps late)."""
    if isinstance(successor, scm.EndNode):
        return graph.finishes_with_first(successor) or len(graph.predecessors(successor)) == 1
    return len(graph.predecessors(successor)) == 1 and _uses_activation_once(successor)


def is_passing(node: scm.GraphElement) -> bool:
    """Joins and ports: they finish as soon as they are activated."""
    return isinstance(node, _PASSING)


def flow_steps(source: scm.GraphElement, inline: set[scm.GraphElement]) -> int:
    """How many time steps a flow out of `source` costs: none out of the root (its finish is
    written as `SimulationTime >= 0`, which holds at t = 0, so what follows it starts at
    t = 0 as SPEC §3 has it and as an original's `>= 0` trigger or Init action does) and none
    out of an inlined node (its successor's trigger holds its condition), else
    `meaning.FLOW_DELAY_STEPS`."""
    if source in inline or isinstance(source, scm.RootNode):
        return 0
    return FLOW_DELAY_STEPS

"""Whether a player's run of an exported scenario kept its meaning (SPEC §3, `xosc.meaning`).

Checked against the flattened graph and the exported document:
  order      a node's events start only after its predecessors finished (all of them, or the
             first one for JoinOneFinished);
  finished   every node the end node waits for finished by itself before the stop;
  end        the storyboard was stopped by the end node's trigger, not by the time-out;
  goals      each maneuver's and condition's goal held when it finished (`goals`);
  teleports  no actor jumped between two samples of the trace;
  cut short  the player stopped no action of a node before the node finished, and stopped no
             actor dead (as esmini does where a road ends: the scenario drove it off the map);
             a node ended when an interrupting maneuver of its actor took its part is not cut
             short but finished (`Maneuver.interrupts`, `xosc.meaning`), and its goal is not
             asked for.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np
from lxml import etree

import scemlmodel as scm

from ..export.names import SEPARATOR
from ..maps import RoadMap
from ..model import graph, params
from ..xosc import meaning
from ..xosc.flows import flow_steps, inlined, is_passing
from .goals import goal_problems
from .record import EventRun, PlayerRun

#: A step longer than the speed allows by this much (m) is a jump, not a move.
TELEPORT_MARGIN = 0.5
#: A speed lost faster than this (m/s2) is no braking any vehicle does: the player stopped the
#: actor (esmini does at the end of a road without a link).
ABRUPT_DECELERATION = 20.0


@dataclass
class NodeCheck:
    """One node of the flattened graph, its times in the run and what is wrong with it."""

    name: str
    kind: str
    after: list[str]
    one: bool
    start: float | None
    finish: float | None
    problems: list[str] = field(default_factory=list)
    #: Unfinished at the stop, but the end node did not wait for it (SPEC §3: join-one).
    pending: bool = False
    #: Written into its successor's trigger (`xosc.flows.inlined`): its times are derived.
    inlined: bool = False


@dataclass
class RunReport:
    """The verdict on one run."""

    scenario: str
    player: str
    osc_version: str
    nodes: list[NodeCheck]
    ending: str
    stop_time: float | None
    problems: list[str]

    @property
    def ok(self) -> bool:
        """Whether the run kept the scenario's meaning."""
        return not self.problems and not any(node.problems for node in self.nodes)

    def violations(self) -> list[str]:
        """Every problem, each with the node it concerns."""
        found = [f"{node.name}: {problem}" for node in self.nodes for problem in node.problems]
        return [*found, *self.problems]


def check_run(
    flat: scm.Scenario,
    tree: etree._ElementTree,
    events_of: dict[str, tuple[str, str]],
    run: PlayerRun,
    road_map: RoadMap | None = None,
    name: str = "scenario",
) -> RunReport:
    """Check a player's run against the flattened scenario and the document it played."""
    stop = run.stop_time
    events = _events_by_node(tree, (first for first, _ in events_of.values()))
    finish: dict[str, float | None] = {}
    checks: dict[str, NodeCheck] = {}
    order, _ = graph.topological_order(flat)
    inline = inlined(flat.nodes)
    takeovers = _takeovers(flat, events_of, run)
    for node in order:
        node_name = str(node.name)
        if isinstance(node, scm.RootNode):
            finish[node_name] = 0.0
            continue
        if isinstance(node, scm.EndNode):
            continue
        check = NodeCheck(
            name=node_name,
            kind=node.eClass.name,
            after=[str(p.name) for p in graph.predecessors(node)],
            one=isinstance(node, scm.JoinOneFinished),
            start=None,
            finish=None,
            inlined=node in inline,
        )
        if check.inlined:
            check.start, check.finish = _inlined_times(node, inline, events_of, run, finish)
            first = None
        else:
            first, finish_event = events_of[node_name]
            starts = [run.events.get(e, EventRun()).start for e in events[first]]
            end = run.events.get(finish_event, EventRun()).end
            check.start = min((s for s in starts if s is not None), default=None)
            check.finish = end
        if check.finish is not None and stop is not None and check.finish > stop:
            check.finish = None
        finish[node_name] = check.finish
        checks[node_name] = check
        _check_order(check, finish)
        ended = _ended_by_other(node, check, takeovers, run.step)
        if first is not None and not ended:
            _check_cut_short(check, events[first], run)
        if run.traces and check.start is not None and check.finish is not None and not ended:
            ready = required([finish[p] for p in check.after], check.one)
            activated = check.start if ready is None else ready
            check.problems.extend(
                goal_problems(node, (activated, check.start), check.finish, run, road_map)
            )
    end_node = graph.end_node(flat)
    assert end_node is not None
    needed = _needed(end_node, finish)
    for node_name, check in checks.items():
        if check.finish is None and node_name not in needed:
            check.pending = True
        elif check.finish is None:
            check.problems.append("never finished" if check.start is not None else "never started")
    ending, problems = _check_end(end_node, tree, run, finish)
    problems.extend(teleports(run))
    problems.extend(abrupt_stops(run))
    version = run.osc_version or "?"
    return RunReport(
        name, f"{run.player} {run.version}", version, list(checks.values()), ending, stop, problems
    )


def _inlined_times(
    node: scm.GraphElement,
    inline: set[scm.GraphElement],
    events_of: dict[str, tuple[str, str]],
    run: PlayerRun,
    finish: dict[str, float | None],
) -> tuple[float | None, float | None]:
    """Start and finish of a node the export wrote into its successor's trigger (it has no
    event of its own): activated when its predecessors' finishes reach it
    (`xosc.flows.flow_steps`); a join or port finishes then, a wait its duration later, and
    a condition when its successors (whose only predecessor it is) started."""
    one = isinstance(node, scm.JoinOneFinished)
    reached = []
    for before in graph.predecessors(node):
        done = finish[str(before.name)]
        reached.append(None if done is None else done + flow_steps(before, inline) * run.step)
    activated = required(reached, one)
    if activated is None:
        return None, None
    activated = round(activated, 9)
    if is_passing(node):
        return activated, activated
    if isinstance(node, scm.TimeElapsed):
        return activated, round(activated + float(params.concrete(node, "duration")), 9)
    starts = [
        start
        for successor in graph.successors(node)
        for start in _started_after(successor, events_of, run)
    ]
    return activated, min((s for s in starts if s is not None), default=None)


def _started_after(
    successor: scm.GraphElement, events_of: dict[str, tuple[str, str]], run: PlayerRun
) -> list[float | None]:
    """When the successor of an inlined condition started, which is when the condition held
    (the end node: when the StopTrigger stopped the run); through an inlined wait (the condition's delay): its successors' starts less the wait."""
    if isinstance(successor, scm.TimeElapsed) and str(successor.name) not in events_of:
        wait = float(params.concrete(successor, "duration"))
        return [
            None if start is None else round(start - wait, 9)
            for after in graph.successors(successor)
            for start in _started_after(after, events_of, run)
        ]
    if isinstance(successor, scm.EndNode):  # written into the StopTrigger: the run's stop
        return [run.stop_time if run.stop_how == "stop" else None]
    if is_passing(successor) and str(successor.name) not in events_of:
        # A join written into the StopTrigger after the condition (`xosc.flows`).
        return [
            start
            for after in graph.successors(successor)
            for start in _started_after(after, events_of, run)
        ]
    return [run.events.get(events_of[str(successor.name)][0], EventRun()).start]


def _events_by_node(tree: etree._ElementTree, first_events: Iterable[str]) -> dict[str, list[str]]:
    """Every Event of the document under the node it belongs to (`<node>__<suffix>`)."""
    owners = set(first_events)
    events: dict[str, list[str]] = {first: [] for first in owners}
    for element in tree.getroot().iter("Event"):
        event = str(element.get("name"))
        owner = event.split(SEPARATOR, 1)[0]
        if owner in owners:
            events[owner].append(event)
    return events


def required(times: list[float | None], one: bool) -> float | None:
    """When the predecessors with these finish times have finished (None: not yet)."""
    known = [t for t in times if t is not None]
    if one:
        return min(known, default=None)
    return max(known) if len(known) == len(times) else None


def _check_order(check: NodeCheck, finish: dict[str, float | None]) -> None:
    ready = required([finish[p] for p in check.after], check.one)
    if check.start is None:
        return
    if ready is None:
        waits = "any" if check.one else "all"
        check.problems.append(
            f"started at {check.start:.2f} s before {waits} of its predecessors finished"
        )
    elif check.start < ready - 1e-6:
        check.problems.append(
            f"started at {check.start:.2f} s, before its activation at {ready:.2f} s"
        )


#: (actor, part) -> (when, node) of each start of an interrupting maneuver in the run.
Takeovers = dict[tuple[str, str], list[tuple[float, str]]]


def _takeovers(
    flat: scm.Scenario, events_of: dict[str, tuple[str, str]], run: PlayerRun
) -> Takeovers:
    """When each interrupting maneuver started in the run, by its actor and each part it takes."""
    found: Takeovers = {}
    for node in flat.nodes:
        if not (isinstance(node, scm.Maneuver) and node.interrupts and node.referenceActor):
            continue
        first = events_of.get(str(node.name), (None, None))[0]
        start = run.events.get(first, EventRun()).start if first else None
        if start is None:
            continue
        for part in meaning.controls(node.eClass.name):
            key = (str(node.referenceActor.name), part)
            found.setdefault(key, []).append((start, str(node.name)))
    return found


def _ended_by_other(
    node: scm.GraphElement, check: NodeCheck, takeovers: Takeovers, step: float
) -> bool:
    """Whether the node finished when an interrupting maneuver of its actor took a part of it:
    in that step, or, for a node whose finish is an event of its own (Follow's and Approach's
    `__gap_reached`), in the next, when that event sees the ended action's completion."""
    actor = getattr(node, "referenceActor", None)
    if check.finish is None or actor is None or not isinstance(node, scm.Maneuver):
        return False
    late = step if isinstance(node, scm.Follow | scm.Approach) else 0.0
    return any(
        -1e-6 < check.finish - when < late + 1e-6 and other != check.name
        for part in meaning.controls(node.eClass.name)
        for when, other in takeovers.get((str(actor.name), part), ())
    )


def _check_cut_short(check: NodeCheck, events: list[str], run: PlayerRun) -> None:
    """An action of the node stopped by the player while the node had not finished."""
    for cut in run.cut_short:
        if cut.event in events and (check.finish is None or cut.time < check.finish):
            check.problems.append(f"cut short by the player at {cut.time:.2f} s ({cut.reason})")


def _needed(end: scm.EndNode, finish: dict[str, float | None]) -> set[str]:
    """Names of the nodes the end node waits for: every predecessor, except that a join-one
    (or a join-one end node) waits only for the predecessor that finished first."""
    needed: set[str] = set()
    stack: list[scm.GraphElement] = [end]
    while stack:
        node = stack.pop()
        before = [p for p in graph.predecessors(node) if not isinstance(p, scm.RootNode)]
        one = graph.finishes_with_first(node)
        done = [p for p in before if finish.get(str(p.name)) is not None]
        if one and done:
            before = [min(done, key=lambda p: finish[str(p.name)] or 0.0)]
        for predecessor in before:
            if str(predecessor.name) not in needed:
                needed.add(str(predecessor.name))
                stack.append(predecessor)
    return needed


def _stop_trigger(tree: etree._ElementTree) -> tuple[list[list[str]], set[str]]:
    """The StopTrigger's groups of condition names, and the names of its time-out conditions."""
    groups, timeouts = [], set()
    for group in tree.getroot().iterfind("Storyboard/StopTrigger/ConditionGroup"):
        names = [str(condition.get("name")) for condition in group.iterfind("Condition")]
        groups.append(names)
        for condition in group.iterfind("Condition"):
            if _is_time_out(condition.find(".//SimulationTimeCondition")):
                timeouts.add(str(condition.get("name")))
    return groups, timeouts


def _is_time_out(clock: etree._Element | None) -> bool:
    """Whether a SimulationTimeCondition is the maximum duration's (`> max`), not the root's
    finish (`>= 0`, 1.0: `> -1`), which a condition written into the StopTrigger is ANDed
    with (`xosc.flows`)."""
    if clock is None or clock.get("rule") != "greaterThan":
        return False
    try:
        return float(str(clock.get("value"))) >= 0
    except ValueError:  # a parameter: only the maximum duration is written so
        return True


def _check_end(
    end: scm.EndNode, tree: etree._ElementTree, run: PlayerRun, finish: dict[str, float | None]
) -> tuple[str, list[str]]:
    """How the storyboard stopped, and what is wrong with that."""
    if run.stop_time is None:
        return "did not stop", ["the storyboard never completed"]
    if run.stop_how != "stop":
        return f"{run.stop_how}Transition", [
            "the storyboard completed by itself, not by its StopTrigger"
        ]
    one = end.policy is scm.JoinPolicy.joinOne
    ready = required([finish[str(p.name)] for p in graph.predecessors(end)], one)
    groups, timeouts = _stop_trigger(tree)
    held = [bool(group) and all(value for _, value in group) for group in run.stop_groups]
    fired = [names for names, fire in zip(groups, held, strict=False) if fire]
    by_timeout = any(set(names) & timeouts for names in fired)
    by_end = any(not set(names) & timeouts for names in fired)
    at = f"{run.stop_time:.2f} s"
    if by_end or (not fired and ready is not None and not by_timeout):
        if ready is None or ready > run.stop_time:
            return f"end node at {at}", [
                "the StopTrigger fired before the end node's predecessors finished"
            ]
        return f"end node at {at}", []
    if by_timeout:
        return f"time-out at {at}", [
            "stopped by the maximum-duration time-out, not by the end node"
        ]
    return f"unknown at {at}", ["cannot tell from the log which StopTrigger group fired"]


def teleports(run: PlayerRun) -> list[str]:
    """Every jump of an actor between two samples farther than its speed allows."""
    found = []
    for actor, trace in run.traces.items():
        if len(trace.times) < 3:
            continue
        # The first row is before the Init's teleport has settled everywhere; start at the second.
        steps = np.hypot(np.diff(trace.x[1:]), np.diff(trace.y[1:]))
        dt = np.diff(trace.times[1:])
        allowed = np.maximum(trace.speed[1:-1], trace.speed[2:]) * dt * 1.5 + TELEPORT_MARGIN
        jumps = np.nonzero(steps > allowed)[0]
        if jumps.size:
            k = int(jumps[0]) + 2
            found.append(
                f"{actor} jumped {steps[jumps[0]]:.2f} m at {trace.times[k]:.2f} s "
                f"(a teleport; {jumps.size} jump(s) in all)"
            )
    return found


def abrupt_stops(run: PlayerRun) -> list[str]:
    """Every actor the player stopped dead: from speed to standing in one sample."""
    found = []
    for actor, trace in run.traces.items():
        if len(trace.times) < 2:
            continue
        lost = -np.diff(trace.speed) / np.maximum(np.diff(trace.times), 1e-9)
        stops = np.nonzero((lost > ABRUPT_DECELERATION) & (trace.speed[1:] < 0.01))[0]
        for k in stops[:1]:
            x, y, t = trace.x[k + 1], trace.y[k + 1], trace.times[k + 1]
            found.append(
                f"the player stopped {actor} dead at ({x:.1f}, {y:.1f}) at {t:.2f} s from "
                f"{trace.speed[k]:.1f} m/s (the end of its road?): a maneuver cut short"
            )
    return found

"""Whether each node's goal held when the player finished it (`xosc.meaning`), from the trace.

A player samples every time step, so each test allows what one or two steps can change: the
distance the actor moves in them, or the speed change of its rate.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from pyecore.ecore import EObject

from ..maps import RoadMap
from ..maps.positions import centre
from ..model.params import concrete
from ..xosc import meaning
from .record import PlayerRun, Trace

#: How far a speed may be off its goal at the finish (m/s): one step of a typical rate.
SPEED_SLACK = 0.2
#: How far a position may be off, beyond the distance moved in a step (m).
POSITION_SLACK = 0.1

Goal = Callable[[EObject, "Moment"], str | None]
_GOALS: dict[str, Goal] = {}


class Moment:
    """The run at a node's activation, start and finish, as the goals need it. A condition's
    marker event starts when the condition holds, so its activation is when its predecessors
    finished."""

    def __init__(
        self,
        run: PlayerRun,
        activated: float,
        start: float,
        finish: float,
        road_map: RoadMap | None,
    ) -> None:
        self.run, self.activated, self.start, self.finish = run, activated, start, finish
        self.road_map = road_map

    def trace(self, actor: EObject | None) -> Trace | None:
        return self.run.traces.get(str(getattr(actor, "name", "")))

    def reach(self, trace: Trace) -> float:
        """How far the actor can move in two steps around the finish, plus the slack."""
        k = trace.at(self.finish)
        return float(trace.speed[k]) * self.run.step * 2 + POSITION_SLACK

    def point(self, position: EObject | None) -> tuple[float, float] | None:
        located = centre(position, self.road_map)
        return None if located is None else (located.x, located.y)


def goal(*kinds: str) -> Callable[[Goal], Goal]:
    """Register the goal test of node kinds."""

    def register(test: Goal) -> Goal:
        for kind in kinds:
            _GOALS[kind] = test
        return test

    return register


def goal_problems(
    node: EObject,
    began: tuple[float, float],
    finish: float,
    run: PlayerRun,
    road_map: RoadMap | None,
) -> list[str]:
    """What was wrong with the node's goal when it finished (nothing for joins, ports and
    kinds without a goal test, or when the trace lacks the actor). `began` is (activation,
    first event's start)."""
    test = _GOALS.get(node.eClass.name)
    if test is None:
        return []
    problem = test(node, Moment(run, *began, finish, road_map))
    return [] if problem is None else [f"at its finish ({finish:.2f} s) {problem}"]


@goal("Accelerate", "Decelerate", "Stop")
def _speed_reached(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    if trace is None:
        return None
    target = 0.0 if node.eClass.name == "Stop" else concrete(node, "targetSpeed")
    speed = float(trace.speed[trace.at(at.finish)])
    # A player's trace may show the speed of the step before the one that reached it.
    slack = max(SPEED_SLACK, concrete(node, "rate") * at.run.step + 1e-6)
    if abs(speed - target) > slack:
        return f"the speed was {speed:.2f} m/s, not the target {target:g} m/s"
    return None


@goal("KeepVelocity")
def _speed_kept(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    if trace is None:
        return None
    before, after = trace.speed[trace.at(at.start)], trace.speed[trace.at(at.finish)]
    if abs(after - before) > SPEED_SLACK:
        return f"the speed changed from {before:.2f} to {after:.2f} m/s"
    return None


@goal("DriveDistance")
def _distance_driven(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    if trace is None:
        return None
    i, j = trace.at(at.start), trace.at(at.finish)
    driven = float(np.sum(np.hypot(np.diff(trace.x[i : j + 1]), np.diff(trace.y[i : j + 1]))))
    wanted = concrete(node, "distance")
    if abs(driven - wanted) > at.reach(trace) + concrete(node, "speed") * at.run.step:
        return f"{driven:.2f} m were driven since its start, not {wanted:g} m"
    return None


def _gap(trace: Trace, lead: Trace, t: float) -> float:
    k, m = trace.at(t), lead.at(t)
    heading = float(trace.heading[k])
    dx, dy = lead.x[m] - trace.x[k], lead.y[m] - trace.y[k]
    return float(dx * math.cos(heading) + dy * math.sin(heading))


@goal("Follow", "Approach")
def _gap_reached(node: EObject, at: Moment) -> str | None:
    trace, lead = at.trace(node.referenceActor), at.trace(node.targetActor)
    if trace is None or lead is None:
        return None
    if node.freespace or node.timeGap is not None or node.displacement.name == "leading":
        # The traces hold reference points only, not the boxes (nor, for a time gap, the
        # target's speed at the finish as the marker read it): that goal is not checked here.
        return None
    gap, distance = _gap(trace, lead, at.finish), concrete(node, "distance")
    slack = at.reach(trace)
    if node.eClass.name == "Follow":
        if gap >= distance + meaning.follow_slack(distance) + slack:
            return f"the gap was {gap:.2f} m, not below {distance:g} m + its slack"
    elif abs(gap - distance) >= meaning.APPROACH_REACHED + slack:
        return f"the gap was {gap:.2f} m, not {distance:g} m"
    return None


@goal("LaneChange")
def _lane_changed(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    # Into another actor's lane or an absolute lane, the actor may already be there: only a
    # change of lanes >= 1 from its own lane must leave it.
    relative = node.targetActor is None and node.targetLane is None and node.lanes >= 1
    if trace is None or not relative:
        return None
    before, after = trace.lane[trace.at(at.start)], trace.lane[trace.at(at.finish)]
    if before and after and before == after:
        return f"the actor was still on lane {after}"
    return None


@goal("Overtake")
def _back_in_lane(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    if trace is None:
        return None
    before, after = trace.lane[trace.at(at.start)], trace.lane[trace.at(at.finish)]
    if before and after and before != after:
        return f"the actor was on lane {after}, not back on lane {before}"
    return None


def _near(node: EObject, at: Moment, position: EObject | None, radius: float) -> str | None:
    trace, point = at.trace(node.referenceActor), at.point(position)
    if trace is None or point is None:
        return None
    k = trace.at(at.finish)
    off = math.hypot(trace.x[k] - point[0], trace.y[k] - point[1])
    if off > radius + at.reach(trace):
        return (
            f"the actor was {off:.2f} m from ({point[0]:g}, {point[1]:g}), not within {radius:g} m"
        )
    return None


@goal("TurnLeft", "TurnRight", "Cross")
def _arrived(node: EObject, at: Moment) -> str | None:
    return _near(node, at, node.destination, concrete(node, "tolerance"))


@goal("FollowTrajectory")
def _trajectory_done(node: EObject, at: Moment) -> str | None:
    points = list(node.waypoints)
    return _near(node, at, points[-1], concrete(node, "tolerance")) if points else None


@goal("InLocationRadius")
def _inside(node: EObject, at: Moment) -> str | None:
    return _near(node, at, node.position, concrete(node, "radius"))


@goal("InVehicleRadius")
def _close(node: EObject, at: Moment) -> str | None:
    trace, other = at.trace(node.referenceActor), at.trace(node.targetActor)
    if trace is None or other is None:
        return None
    if (node.rule.name, node.relativeDistanceType.name, node.freespace) != (
        "lessThan",
        "euclidean",
        False,
    ):
        # The traces hold reference points only, not the boxes and headings another measure
        # needs: that goal is not checked here.
        return None
    k, m = trace.at(at.finish), other.at(at.finish)
    off = math.hypot(trace.x[k] - other.x[m], trace.y[k] - other.y[m])
    radius = concrete(node, "radius")
    if off > radius + at.reach(trace) + at.reach(other):
        return f"the actors were {off:.2f} m apart, not within {radius:g} m"
    return None


@goal("TimeElapsed")
def _waited(node: EObject, at: Moment) -> str | None:
    duration = concrete(node, "duration")
    waited = at.finish - at.activated
    if abs(waited - duration) > 2 * at.run.step + 1e-6:
        return f"{waited:.2f} s had passed since its start, not {duration:g} s"
    return None


@goal("SpeedCondition")
def _speed_rule(node: EObject, at: Moment) -> str | None:
    trace = at.trace(node.referenceActor)
    if trace is None:
        return None
    speed, threshold = float(trace.speed[trace.at(at.finish)]), concrete(node, "speed")
    rule = getattr(node.rule, "name", "greaterThan")
    held = {
        "greaterThan": speed > threshold - SPEED_SLACK,
        "lessThan": speed < threshold + SPEED_SLACK,
        "equalTo": abs(speed - threshold) <= SPEED_SLACK,
        "greaterOrEqual": speed > threshold - SPEED_SLACK,
        "lessOrEqual": speed < threshold + SPEED_SLACK,
    }.get(rule, True)
    return None if held else f"the speed was {speed:.2f} m/s, not {rule} {threshold:g} m/s"


@goal(
    "ActivateController",
    "AssignController",
    "OverrideController",
    "ConnectTrailer",
    "DisconnectTrailer",
)
def _at_once(node: EObject, at: Moment) -> str | None:
    """A controller change or a trailer coupling completes in the step it starts
    (`meaning.completes_at_once`, esmini's TrailerAction)."""
    took = at.finish - at.start
    if took > at.run.step + 1e-6:
        return f"it took {took:.2f} s after its start; a controller change completes at once"
    return None

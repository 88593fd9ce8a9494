"""The events of each node kind: which actions it performs and which event marks it finished.

Each planner takes the node's activation (ConditionGroups) and returns its events plus the name
of its *finish event*, whose completeState its successors wait for. Planners are registered by
metaclass name in PLANNERS; `support.py` derives the list of mapped kinds from it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import Any

import scemlmodel as scm

from ..maps.resolve import is_relative
from ..model.departure import departure
from ..model.graph import OwnFlows, reachable
from ..xosc import meaning
from ..xosc.support import MAPPED_KINDS, REPEATABLE_KINDS
from .context import Action, Context, Event
from .speeds import speed_dynamics
from .triggers import Condition, Finish, Group, delayed, finished, has_started, with_extra
from .values import number

#: A node's events, and its finish: the event its successors wait for, or (for a node written
#: into its successor's trigger, `xosc.flows.inlined`) the groups that hold once it finished.
Plan = tuple[list[Event], Finish]
Planner = Callable[[Context, scm.GraphElement, list[Group]], Plan]

PLANNERS: dict[str, Planner] = {}
#: Kinds written as one event: only they can run more than once (maximumExecutionCount is an
#: event's; a node written as an event and its finish marker cannot repeat them together).
ONE_EVENT: set[str] = set()


def planner(*kinds: str, one_event: bool = False) -> Callable[[Planner], Planner]:
    """Register a planner for node kinds; each must be listed in `support.MAPPED_KINDS`, and a
    kind written as one event (`one_event`) in `support.REPEATABLE_KINDS` too."""

    def register(function: Planner) -> Planner:
        for kind in kinds:
            if kind not in MAPPED_KINDS:
                raise AssertionError(f"{kind} has a planner but is not in MAPPED_KINDS")
            if one_event != (kind in REPEATABLE_KINDS):
                raise AssertionError(
                    f"{kind}: one_event={one_event} disagrees with REPEATABLE_KINDS"
                )
            PLANNERS[kind] = function
            if one_event:
                ONE_EVENT.add(kind)
        return function

    return register


def _single(ctx: Context, node: scm.GraphElement, groups: list[Group], action: Action) -> Plan:
    name = ctx.event_names[node]
    return [Event(name, ctx.entity(node.referenceActor), [action], groups)], name


def action_plan(
    ctx: Context, node: scm.ActionNode, groups: list[Group], kind: str, data: dict[str, Any]
) -> Plan:
    """The node's event: one action of `kind` (a template macro) with `data`, by its actor, the
    node done when the event is."""
    name = ctx.event_names[node]
    return _single(ctx, node, groups, Action(ctx.action_name(name), kind, data))


def marker_plan(
    ctx: Context,
    node: scm.GraphElement,
    groups: list[Group],
    actor: str,
    check: Condition | None = None,
) -> Plan:
    """A marker event that fires once the node is activated (and `check` holds); or, for an
    inlined node, no event: its successor's trigger holds the same groups, the check named
    after the node so that an import gives the node its name back."""
    name = ctx.event_names[node]
    if check is not None and isinstance(node, scm.Condition):
        check = replace(check, edge=node.edge.name)
    if node in ctx.inline:
        own = None if check is None else replace(check, name=name, own=True)
        return [], groups if own is None else with_extra(groups, own)
    if check is not None:
        groups = with_extra(groups, check)
    return [Event(name, actor, [ctx.marker_action(name, name)], groups)], name


def _finish_marker(
    ctx: Context, node: scm.ActionNode, suffix: str, groups: list[Group], extra: Condition
) -> Event:
    """A marker event of `node` that fires once it is activated and `extra` holds."""
    name = ctx.extra_event(node, suffix)
    return Event(
        name,
        ctx.entity(node.referenceActor),
        [ctx.marker_action(name, name)],
        with_extra(groups, extra),
    )


def _arrival_marker(ctx: Context, node: scm.ActionNode, event: str, extra: Condition) -> Event:
    """The finish marker of a node written as `event` and an arrival: it fires once `event`
    has started and `extra` holds. Not "activated and `extra`": a condition before the node,
    written into `event`'s trigger as it holds now (`xosc.flows`), need not hold again on
    arrival (`traffic_lights`' walkers waited for their green light's marker event, a step
    late, two with its delay)."""
    return started_marker(ctx, node, "arrived", event, extra)


def started_marker(
    ctx: Context, node: scm.ActionNode, suffix: str, event: str, extra: Condition
) -> Event:
    """A finish marker of the node written as `event` that fires once `event` has started
    and `extra` holds, so that the node uses its activation once (`xosc.flows`)."""
    name = ctx.extra_event(node, suffix)
    started = has_started(event, name, ctx.profile)
    return Event(
        name,
        ctx.entity(node.referenceActor),
        [ctx.marker_action(name, name)],
        with_extra(started, extra),
    )


@planner("JoinAllFinished", "JoinOneFinished", "InPort", "OutPort")
def plan_join(ctx: Context, node: scm.GraphElement, groups: list[Group]) -> Plan:
    """Joins and ports only pass activation on: a marker event in the ego's group."""
    return marker_plan(ctx, node, groups, ctx.ego)


@planner("Accelerate", "Decelerate", "Stop", one_event=True)
def plan_speed(ctx: Context, node: scm.ActionNode, groups: list[Group]) -> Plan:
    """A SpeedAction to the target speed at the given rate; it completes when the speed is reached."""
    target = "0.0" if isinstance(node, scm.Stop) else ctx.values.text(node, "targetSpeed")
    data = {"target": target, **speed_dynamics(ctx, node)}
    return _single(ctx, node, groups, Action(ctx.action_name(ctx.event_names[node]), "speed", data))


@planner("DriveDistance")
def plan_drive_distance(ctx: Context, node: scm.DriveDistance, groups: list[Group]) -> Plan:
    """A step SpeedAction to the speed; finished distance / speed seconds after the activation
    (`xosc.meaning.drive_distance_duration`): the speed holds, so the distance is driven
    from where the node starts. TraveledDistanceCondition would count from the simulation's
    start, which is wrong once the actor has moved."""
    name = ctx.event_names[node]
    speed = Action(
        ctx.action_name(name),
        "speed",
        {
            "target": ctx.values.text(node, "speed"),
            "shape": "step",
            "dimension": "time",
            "value": "0.0",
        },
    )
    entity = ctx.entity(node.referenceActor)
    event = Event(name, entity, [speed], groups)
    if ctx.profile == "carla":
        # scenario_runner turns a delay into a time-out from the act's start; its DriveDistance
        # counts from the act's start too (docs/openscenario-mapping.md, profile carla).
        traveled = {"entity": entity, "value": ctx.values.text(node, "distance")}
        marker = _finish_marker(
            ctx, node, "driven", groups, Condition(f"{name}_driven", "traveled", traveled)
        )
        return [event, marker], marker.name
    duration = meaning.drive_distance_duration(
        ctx.values.raw(node, "distance"), ctx.values.raw(node, "speed")
    )
    if duration == float("inf"):
        raise ValueError(f"{node.name}: a DriveDistance at 0 m/s never finishes (SCEML-Y001)")
    driven = ctx.extra_event(node, "driven")
    done = Event(
        driven,
        entity,
        [ctx.marker_action(driven, driven)],
        delayed(groups, _drive_time(ctx, node), ctx.traits.expressions),
    )
    return [event, done], driven


def _drive_time(ctx: Context, node: scm.DriveDistance) -> str:
    """distance / speed as written: a number, or where either is a declared parameter an
    expression of them, so the file keeps its meaning when the parameter is changed."""
    distance, speed = ctx.values.text(node, "distance"), ctx.values.text(node, "speed")
    if not (distance.startswith("$") or speed.startswith("$")):
        return number(meaning.drive_distance_duration(float(distance), float(speed)))
    if not ctx.traits.expressions:
        raise ValueError(
            f"{node.name}: a DriveDistance finishes distance / speed after it starts, and "
            "OpenSCENARIO 1.0 has no expressions to write that of parameters; export 1.1 or later"
        )
    return f"${{{distance} / {speed}}}"


@planner("LaneChange", one_event=True)
def plan_lane_change(ctx: Context, node: scm.LaneChange, groups: list[Group]) -> Plan:
    """LaneChangeAction `lanes` lanes to the left (+) or right (-) of the actor's own lane or of
    the target actor's, or into the absolute `targetLane`, shaped as the node says."""
    name = ctx.event_names[node]
    action = _lane_change(ctx, node, name, node.direction.name, ctx.values.text(node, "distance"))
    data = dict(action.data)
    count = int(node.lanes)
    data["lanes"] = str(count if node.direction.name == "left" else -count)
    if node.targetActor is not None:
        data["entity"] = ctx.entity(node.targetActor)
    if node.targetLane is not None:
        data["absolute"] = str(node.targetLane)
    if ctx.profile != "carla":
        data["shape"] = node.shape.name
    if ctx.values.raw(node, "targetOffset") != 0:
        data["offset"] = ctx.values.text(node, "targetOffset")
    if node.duration is not None:
        # Release 1.5: a change given in time stays a time; players stretch it over the speed
        # the actor drives at then (CARLA's parser reads a distance only: SCEML-E008).
        data["dimension"], data["value"] = "time", ctx.values.text(node, "duration")
    return _single(ctx, node, groups, replace(action, data=data))


def _lane_change(
    ctx: Context, node: scm.ActionNode, event: str, side: str, distance: str
) -> Action:
    # CARLA's parser only reads a distance and moves linearly; esmini shapes it sinusoidally.
    shape = "linear" if ctx.profile == "carla" else "sinusoidal"
    data = {
        "entity": ctx.entity(node.referenceActor),
        "lanes": "1" if side == "left" else "-1",
        "shape": shape,
        "dimension": "distance",
        "value": distance,
    }
    return Action(ctx.action_name(event), "lane_change", data)


def arrived(
    ctx: Context, node: scm.ActionNode, name: str, position: dict[str, Any], tolerance: str
) -> Condition:
    """The reference actor is within `tolerance` of `position` (version-specific element)."""
    kind = "reach_position" if ctx.traits.reach_position else "distance"
    data = {"entity": ctx.entity(node.referenceActor), "position": position, "value": tolerance}
    return Condition(name, kind, data)


@planner("TurnLeft", "TurnRight")
def plan_turn(ctx: Context, node: scm.RoutedManeuver, groups: list[Group]) -> Plan:
    """AssignRouteAction from where the actor is when the turn starts to the destination;
    finished by an arrival marker, because players complete routing actions as soon as the
    route is set (SPEC §7). Not AcquirePositionAction: esmini runs that in the longitudinal
    domain and so stops a running speed maneuver of the actor; a route controls no domain
    (`xosc.meaning`)."""
    name = ctx.event_names[node]
    destination = ctx.position(node.destination)
    if ctx.profile == "carla":  # scenario_runner reads no AssignRouteAction
        route = Action(ctx.action_name(name), "acquire", {"position": destination})
    else:
        # Players resolve a route's waypoints when they load the file, so a position relative
        # to the actor would be where it stands at t = 0; the route starts where the graph
        # leaves the actor (its start, or its last destination or InLocationRadius): a route
        # from its start would lie behind an actor that has driven on (`routing-test`).
        start = ctx.position(_where_it_turns(node))
        data = {"route": ctx.names.claim(f"{name}_route"), "waypoints": [start, destination]}
        route = Action(ctx.action_name(name), "route", data)
    event = Event(name, ctx.entity(node.referenceActor), [route], groups)
    here = arrived(ctx, node, f"{name}_arrived", destination, ctx.values.text(node, "tolerance"))
    done = _arrival_marker(ctx, node, name, here)
    return [event, done], done.name


def _where_it_turns(node: scm.RoutedManeuver) -> scm.Position:
    """Where the turn's actor is when it starts (`model.departure`), or its start."""
    flows = OwnFlows(node.eContainer())
    earlier = reachable([node], backwards=True, flows=flows)
    actor = node.referenceActor
    mine = [n for n in flows.nodes if n in earlier and n is not node and _performs(n, actor)]
    place = departure(node, mine, lambda other: reachable([other], backwards=True) - {other})
    # A place relative to an entity would be read where that entity stands at t = 0.
    return place if place is not None and not is_relative(place) else actor.startPosition


def _performs(node: Any, actor: scm.Participant) -> bool:
    return isinstance(node, scm.ActionNode) and node.referenceActor is actor


@planner("Cross", "FollowTrajectory")
def plan_trajectory(ctx: Context, node: scm.ActionNode, groups: list[Group]) -> Plan:
    """FollowTrajectoryAction along a straight polyline from where the actor is (a position
    relative to itself, frozen at start) through the waypoints; crossings are not routable lanes.
    Finished by an arrival marker at the last point."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    points = [node.destination] if isinstance(node, scm.Cross) else list(node.waypoints)
    here = {"kind": "relative_object", "entity": entity, "dx": "0.0", "dy": "0.0"}
    # An imported trajectory begins at its first waypoint, as it did in the original.
    start = [] if getattr(node, "fromFirstWaypoint", False) and len(points) > 1 else [here]
    # No vertex carries a heading: the actor then faces along its path. With a heading on any
    # vertex, esmini keeps the actor's own heading at the start, and a path that starts across
    # it (a pedestrian facing along the kerb, crossing) is taken as driven backwards and ends in
    # the step it starts (docs/openscenario-mapping.md, "Trajectories").
    vertices = [*start, *({**ctx.position(point), "h": None} for point in points)]
    # A Cross has no following mode: players put the actor on its straight path.
    mode = "position" if isinstance(node, scm.Cross) else node.followingMode.name
    data = {"trajectory": ctx.names.claim(f"{name}_path"), "vertices": vertices, "mode": mode}
    event = Event(name, entity, [Action(ctx.action_name(name), "trajectory", data)], groups)
    end = arrived(ctx, node, f"{name}_arrived", vertices[-1], ctx.values.text(node, "tolerance"))
    done = _arrival_marker(ctx, node, name, end)
    return [event, done], done.name


@planner("Overtake")
def plan_overtake(ctx: Context, node: scm.Overtake, groups: list[Group]) -> Plan:
    """Change lane to `side` and speed up; once `gap` metres ahead of the target, change back."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    distance = ctx.values.text(node, "laneChangeDistance")
    side = node.side.name
    out = [
        _lane_change(ctx, node, name, side, distance),
        Action(
            ctx.action_name(name),
            "speed",
            {
                "target": ctx.values.text(node, "speed"),
                "shape": "step",
                "dimension": "time",
                "value": "0.0",
            },
        ),
    ]
    back_name = ctx.extra_event(node, "back")
    ahead_point = {
        "kind": "relative_object",
        "entity": ctx.entity(node.targetActor),
        "dx": ctx.values.text(node, "gap"),
        "dy": "0.0",
    }
    gap = ctx.values.raw(node, "gap")
    tolerance = repr(meaning.overtake_back_tolerance(gap))
    ahead = arrived(ctx, node, f"{back_name}_ahead", ahead_point, tolerance)
    back_groups = [[finished(name, back_name), ahead]]
    other = "right" if side == "left" else "left"
    back = Event(
        back_name, entity, [_lane_change(ctx, node, back_name, other, distance)], back_groups
    )
    return [Event(name, entity, out, groups), back], back_name


@planner("InLocationRadius")
def plan_in_location(ctx: Context, node: scm.InLocationRadius, groups: list[Group]) -> Plan:
    """A marker that fires once activated and the actor is within the radius of the position."""
    name = ctx.event_names[node]
    inside = arrived(
        ctx, node, f"{name}_inside", ctx.position(node.position), ctx.values.text(node, "radius")
    )
    return marker_plan(ctx, node, groups, ctx.entity(node.referenceActor), inside)


@planner("InVehicleRadius")
def plan_in_vehicle(ctx: Context, node: scm.InVehicleRadius, groups: list[Group]) -> Plan:
    """A marker on RelativeDistanceCondition to the target actor, measured as the node says
    (by default between the reference points, in a straight line, closer than the radius)."""
    name = ctx.event_names[node]
    along = measured_along(node)
    data = {
        "entity": ctx.entity(node.referenceActor),
        "target": ctx.entity(node.targetActor),
        "value": ctx.values.text(node, "radius"),
        "rule": node.rule.name,
        # The distance type is required on a RelativeDistanceCondition, so always written.
        "type": along.pop("relative_distance_type", ctx.traits.euclidian),
        "freespace": "true" if node.freespace else "false",
        **along,
    }
    close = Condition(f"{name}_close", "relative_distance", data)
    return marker_plan(ctx, node, groups, ctx.entity(node.referenceActor), close)


@planner("TimeElapsed")
def plan_duration(ctx: Context, node: scm.ActionNode, groups: list[Group]) -> Plan:
    """A marker whose activation conditions carry the duration as their delay."""
    duration = ctx.values.text(node, "duration")
    waited = delayed(groups, duration, ctx.traits.expressions)
    return marker_plan(ctx, node, waited, ctx.entity(node.referenceActor))


@planner("KeepVelocity")
def plan_keep_velocity(ctx: Context, node: scm.KeepVelocity, groups: list[Group]) -> Plan:
    """Hold the speed the actor has (a step SpeedAction by +0 m/s, which also ends a continuous
    longitudinal action such as Follow's), finished by a marker delayed by the duration."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    hold = Action(ctx.action_name(name), "speed_hold", {"entity": entity})
    kept = ctx.extra_event(node, "kept")
    done = Event(
        kept,
        entity,
        [ctx.marker_action(kept, kept)],
        delayed(groups, ctx.values.text(node, "duration"), ctx.traits.expressions),
    )
    return [Event(name, entity, [hold], groups), done], kept


@planner("SpeedCondition")
def plan_speed_condition(ctx: Context, node: scm.SpeedCondition, groups: list[Group]) -> Plan:
    """A marker on SpeedCondition."""
    name = ctx.event_names[node]
    data = {
        "entity": ctx.entity(node.referenceActor),
        "value": ctx.values.text(node, "speed"),
        "rule": node.rule.name,
    }
    check = Condition(f"{name}_speed", "speed", data)
    return marker_plan(ctx, node, groups, ctx.entity(node.referenceActor), check)


@planner("TraveledDistance")
def plan_traveled(ctx: Context, node: scm.TraveledDistance, groups: list[Group]) -> Plan:
    """A marker on TraveledDistanceCondition: the actor's odometer since the simulation started
    (xosc.meaning.TRAVELED_FROM), the same in every version and profile."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    data = {"entity": entity, "value": ctx.values.text(node, "distance")}
    check = Condition(f"{name}_traveled", "traveled", data)
    return marker_plan(ctx, node, groups, entity, check)


@planner("TimeHeadway")
def plan_headway(ctx: Context, node: scm.TimeHeadway, groups: list[Group]) -> Plan:
    """A marker on TimeHeadwayCondition towards the target actor, measured as the node says."""
    name = ctx.event_names[node]
    data = {
        "entity": ctx.entity(node.referenceActor),
        "target": ctx.entity(node.targetActor),
        "value": ctx.values.text(node, "time"),
        "rule": node.rule.name,
        "freespace": "true" if node.freespace else "false",
        **measured_along(node),
    }
    check = Condition(f"{name}_headway", "headway", data)
    return marker_plan(ctx, node, groups, ctx.entity(node.referenceActor), check)


def measured_along(node: Any) -> dict[str, str]:
    """The relativeDistanceType and coordinateSystem attributes of a measuring condition, only
    where they differ from OpenSCENARIO's defaults (euclidean, entity) so that files that never
    set them export as before (`support.unsupported_setting` refuses them for 1.0)."""
    data = {}
    kind = node.relativeDistanceType.name
    if kind != "euclidean":
        data["relative_distance_type"] = kind
    system = node.coordinateSystem.name
    if system != "entity":
        data["coordinate_system"] = system
    return data


@planner("TimeToCollision")
def plan_ttc(ctx: Context, node: scm.TimeToCollision, groups: list[Group]) -> Plan:
    """A marker on TimeToCollisionCondition towards the target actor."""
    name = ctx.event_names[node]
    data = {
        "entity": ctx.entity(node.referenceActor),
        "target": ctx.entity(node.targetActor),
        "value": ctx.values.text(node, "time"),
        "rule": node.rule.name,
    }
    data["freespace"] = "true" if node.freespace else "false"
    data.update(measured_along(node))
    check = Condition(f"{name}_ttc", "ttc", data)
    return marker_plan(ctx, node, groups, ctx.entity(node.referenceActor), check)


#: What match_speed.py and distance_keeping.py use to add a finish marker.
finish_marker = _finish_marker

# Registers the planners of sceml import's OpaqueAction, the controller changes, the global
# kinds, Follow and Approach, LaneOffset, LightState, MatchSpeed, StandStill,
# AccelerationCondition and the trailer couplings.
from . import (  # noqa: E402, F401
    appearance,
    controller_actions,
    coupling,
    distance_keeping,
    global_kinds,
    lane_offset,
    match_speed,
    motion_conditions,
    opaque,
)

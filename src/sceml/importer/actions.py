"""One OpenSCENARIO action of one actor to one SceML maneuver node, or None (kept opaque).

Speed to Accelerate/Decelerate/Stop, a lane change by
one lane to LaneChange, routing to TurnLeft/TurnRight/Cross (`geometry.py`), a polyline
trajectory to FollowTrajectory (Cross for a SceML export's two-point crossing); controller
actions in `controllers.py`, longitudinal distance to Follow/Approach in `distance_keeping.py`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from lxml import etree

import scemlmodel as scm

from ..maps.resolve import is_relative, resolve, start_poses
from ..model import catalog
from ..model.speed_shapes import PEAK_FACTORS
from ..xosc import PLAYER_STEP
from . import traced
from .context import Build, last_name
from .geometry import classify
from .lane_rate import rate_seconds
from .opaque import summary
from .placing import place
from .positions import lane_id, number


@dataclass
class Motion:
    """What the import knows of each actor so far: its last speed and where it last went."""

    speed: dict[str, float] = field(default_factory=dict)
    place: dict[str, scm.Position | None] = field(default_factory=dict)


@dataclass(frozen=True)
class Request:
    """One action to map: the element, its actor, the node name wanted and the kind hint."""

    element: etree._Element
    actor: scm.Actor
    name: str
    #: The node kind a SceML export's event name states (e.g. `Decelerate`), or None.
    hint: str | None = None


Mapper = Callable[[Build, Request, etree._Element, Motion], scm.ActionNode | str]

_MAPPERS: dict[str, Mapper] = {}


def _maps(path: str) -> Callable[[Mapper], Mapper]:
    def register(function: Mapper) -> Mapper:
        _MAPPERS[path] = function
        return function

    return register


def map_action(build: Build, request: Request, motion: Motion) -> scm.ActionNode | str:
    """The node an Action stands for (added to the scenario), or why it has no SceML kind."""
    for path, mapper in _MAPPERS.items():
        found = request.element.find(path)
        if found is not None:
            return mapper(build, request, found, motion)
    what = summary(request.element).split(" ")[-1]
    return f"SceML has no kind for {what}"


def _add(build: Build, request: Request, kind: str, **values: object) -> scm.ActionNode:
    node: scm.ActionNode = getattr(scm, kind)()
    if catalog.performed_by_actor(kind):
        node.referenceActor = request.actor
    numeric = {spec.name for spec in catalog.parameters(kind)}
    for key, value in values.items():
        if value is None:
            continue
        enum = node.eClass.findEStructuralFeature(key).eType
        if isinstance(value, str) and hasattr(enum, "getEEnumLiteral"):
            value = enum.getEEnumLiteral(value)
        node.eSet(key, traced.value(value) if key in numeric else value)  # type: ignore[arg-type]
    build.add(node, request.name)
    build.report.add(
        "mapped",
        f"{node.name}: <{request.element.get('name')}> -> {kind}",
        build.where(request.element),
        str(node.name),
    )
    return node


def _guess(build: Build, request: Request, message: str) -> None:
    build.report.add("guessed", f"{request.name}: {message}", build.where(request.element))


@_maps("PrivateAction/LongitudinalAction/SpeedAction")
def _speed(
    build: Build, request: Request, speed: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    target = speed.find("SpeedActionTarget/AbsoluteTargetSpeed")
    if target is None:
        _relative_speed(build, request, speed, motion)
        return _match_speed(build, request, speed)
    value = number(target, "value")
    actor = str(request.actor.name)
    before = motion.speed.get(actor)
    if request.hint in ("Accelerate", "Decelerate", "Stop") and (
        request.hint != "Stop" or value == 0
    ):
        kind = request.hint
    elif value == 0:
        kind = "Stop"
    else:
        kind = "Decelerate" if before is not None and value < before else "Accelerate"
        if before is None:
            _guess(build, request, "the speed before is unknown: taken as Accelerate")
    shape, rate = _dynamics(build, request, speed.find("SpeedActionDynamics"), before, value)
    rate = _within_performance(build, request, rate, before, value)
    motion.speed[actor] = value
    if kind == "Stop":
        return _add(build, request, kind, rate=rate, shape=shape)
    return _add(build, request, kind, targetSpeed=value, rate=rate, shape=shape)


def _relative_speed(build: Build, request: Request, speed: etree._Element, motion: Motion) -> None:
    """The speed a relative target speed reaches, from the other actor's speed known so far,
    so that later actions given in time (a lane change's duration) get their length."""
    target = speed.find("SpeedActionTarget/RelativeTargetSpeed")
    other = None if target is None else build.actor(target.get("entityRef"), target)
    base = None if other is None else motion.speed.get(str(other.name))
    if target is None or other is None or base is None:
        return
    value = number(target, "value")
    reached = base * value if target.get("speedTargetValueType") == "factor" else base + value
    motion.speed[str(request.actor.name)] = reached
    message = f"the relative target speed taken as {reached:g} m/s, from {other.name}'s"
    _guess(build, request, message)


def _match_speed(build: Build, request: Request, speed: etree._Element) -> scm.ActionNode | str:
    """A speed relative to another actor's: MatchSpeed, at once (a step) or at a linear rate."""
    target = speed.find("SpeedActionTarget/RelativeTargetSpeed")
    dynamics = speed.find("SpeedActionDynamics")
    if target is None or dynamics is None:
        return "this speed target has no SceML form"
    shape, dimension = dynamics.get("dynamicsShape"), dynamics.get("dynamicsDimension")
    amount = number(dynamics, "value", 0.0)
    if shape == "step" or amount == 0:
        rate = None  # at once
    elif shape == "linear" and dimension == "rate":
        rate = abs(amount)  # some files write a deceleration as a negative rate
    else:
        return f"a relative speed reached by a {shape} {dimension} has no SceML form"
    if rate is not None and target.get("continuous") == "true":
        # Its finish (the speed first reached) would need a relative speed condition.
        return "a continuous relative speed reached at a rate has no SceML form"
    factor = target.get("speedTargetValueType") == "factor"
    value = number(target, "value")
    node = _add(
        build,
        request,
        "MatchSpeed",
        relation="factor" if factor else "delta",
        speedFactor=value if factor else None,
        speedDelta=None if factor else value,
        rate=rate,
        continuous=target.get("continuous") == "true",
    )
    node.targetActor = build.actor(target.get("entityRef"), target)
    return node


def _dynamics(
    build: Build,
    request: Request,
    dynamics: etree._Element | None,
    before: float | None,
    after: float,
) -> tuple[str, float | None]:
    """The shape and (peak) rate in m/s² of a speed change; a rate of None is the language
    default (for a step, or when it cannot be read)."""
    if dynamics is None:
        return "linear", None
    shape, dimension = dynamics.get("dynamicsShape", "linear"), dynamics.get("dynamicsDimension")
    # Some files write a deceleration as a negative rate; the rate is a magnitude (a positive
    # one is kept as read, so that a distributed rate is still recognised).
    value = number(dynamics, "value", 0.0)
    value = value if value >= 0 else -value
    if shape not in PEAK_FACTORS and shape != "step":
        _guess(build, request, f"a speed change shaped {shape} read as linear")
        shape = "linear"
    if shape == "step" or value <= 0:  # a zero time or distance is a step too, as players read it
        return "step", None
    if dimension == "rate":
        return shape, value
    if before is None or before == after:
        _guess(
            build,
            request,
            f"the speed before is unknown: the {dimension} is not converted to a rate",
        )
        return shape, None
    if dimension == "time":
        return shape, PEAK_FACTORS[shape] * abs(after - before) / value
    message = f"the rate computed from the distance and the speed before ({before} m/s)"
    if shape != "linear":
        # Players change a speed over a distance with the shape along the distance, not in
        # time: taken as lasting as long as a linear change over that distance would.
        message += f", the {shape} change taken to last as long as a linear one"
    _guess(build, request, message)
    seconds = 2 * value / (after + before)
    return shape, PEAK_FACTORS[shape] * abs(after - before) / seconds


def _within_performance(
    build: Build, request: Request, rate: float | None, before: float | None, after: float
) -> float | None:
    """The rate players drive: one above the Vehicle's maxAcceleration (speeding up) or
    maxDeceleration (slowing down) is slowed down to it, as esmini does."""
    limits = build.performance.get(str(request.actor.name))
    if rate is None or limits is None or isinstance(rate, traced.Traced):
        # A distributed rate keeps its distribution (each sample may or may not be above).
        return rate
    slowing = before is not None and after < before
    limit = limits[1] if slowing else limits[0]
    if limit <= 0 or rate <= limit:
        return rate
    word = "maxDeceleration" if slowing else "maxAcceleration"
    _guess(build, request, f"the rate {rate:g} m/s² taken down to the Vehicle's {word} {limit:g}")
    return limit


#: OpenSCENARIO's dynamicsShape values, SceML's LaneChangeShape literals of the same names.
SHAPES = ("sinusoidal", "linear", "cubic", "step")


def _lane_change_time(seconds: float) -> float:
    """How long a lane change of `seconds` (a dynamicsDimension rate, as a time) is driven
    over, for its length: esmini counts a timed change from the step it starts in and a change over a
    distance from the step after, so the same change in metres is one step
    (`xosc.PLAYER_STEP`) shorter than speed times duration (`follow_reference`: 2 s
    at 13.9 m/s plays the same as 27.1 m, not 27.8 m)."""
    return max(seconds - PLAYER_STEP, PLAYER_STEP) if seconds > 0 else seconds


@_maps("PrivateAction/LateralAction/LaneChangeAction")
def _lane_change(
    build: Build, request: Request, change: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    relative = change.find("LaneChangeTarget/RelativeTargetLane")
    absolute = change.find("LaneChangeTarget/AbsoluteTargetLane")
    dynamics = change.find("LaneChangeActionDynamics")
    shape = "sinusoidal" if dynamics is None else dynamics.get("dynamicsShape", "sinusoidal")
    if shape not in SHAPES:
        return f"a lane change shaped {shape} has no SceML form"
    if relative is None and absolute is None:
        return "a lane change without a target lane has no SceML form"
    distance = duration = None
    if dynamics is not None and dynamics.get("dynamicsDimension") == "distance":
        distance = number(dynamics, "value")
    elif dynamics is not None and dynamics.get("dynamicsDimension") == "time":
        # Kept as a time (release 1.5): players stretch it over whatever speed the actor
        # then drives at, which an import cannot always know (`cut-in_sloppy`'s random driver).
        duration = number(dynamics, "value")
    elif dynamics is not None:
        speed = motion.speed.get(str(request.actor.name))
        value, timed = number(dynamics, "value"), False
        if dynamics.get("dynamicsDimension") == "rate":
            # A peak lateral speed: as long as players take for it (`lane_rate`), as a
            # distance still: that plays the same as the original (ALKS 4.4.x and 4.5.x).
            seconds = rate_seconds(build, request.actor, shape, value)
            value, timed = (value, False) if seconds is None else (seconds, True)
        if speed:
            distance = speed * (_lane_change_time(value) if timed else value)
            _guess(
                build,
                request,
                f"the lane change's {dynamics.get('dynamicsDimension')} taken at {speed} m/s as {distance:g} m",
            )
    offset = number(change, "targetLaneOffset") if change.get("targetLaneOffset") else None
    node = _add(
        build, request, "LaneChange", distance=distance, duration=duration, targetOffset=offset
    )
    node.shape = scm.LaneChangeShape.getEEnumLiteral(shape)
    if absolute is not None:
        node.targetLane = lane_id(absolute, "value")
        return node
    assert relative is not None
    reference = build.actor(relative.get("entityRef"), relative)
    lanes = lane_id(relative, "value")
    node.direction = scm.LaneChangeDirection.getEEnumLiteral("left" if lanes >= 0 else "right")
    node.lanes = abs(lanes)
    if reference is not request.actor:
        node.targetActor = reference
    return node


def _at_the_start(build: Build, position: scm.Position | None) -> scm.Position | None:
    """A relative position as the world pose it names among the starts: enough to tell a turn
    from a crossing (the model keeps the relative position itself)."""
    if not is_relative(position):
        return position
    try:
        pose = resolve(position, build.road_map, start_poses(build.actors.values(), build.road_map))
    except ValueError:
        return None
    if pose is None:
        return None
    return scm.WorldPosition(
        x=scm.Value(value=pose.x), y=scm.Value(value=pose.y), h=scm.Value(value=pose.heading)
    )


@_maps("PrivateAction/RoutingAction/AcquirePositionAction")
def _acquire(
    build: Build, request: Request, acquire: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return _routed(build, request, place(build, acquire, initial=False), motion)


@_maps("PrivateAction/RoutingAction/AssignRouteAction")
def _route(
    build: Build, request: Request, assign: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    waypoints = assign.findall("Route/Waypoint")
    if not waypoints:
        return "a route from a catalog has no SceML kind"
    if len(waypoints) > 2:
        _guess(
            build, request, f"a route of {len(waypoints)} waypoints read as a route to its last one"
        )
    return _routed(build, request, place(build, waypoints[-1], initial=False), motion)


def _routed(
    build: Build, request: Request, destination: scm.Position | None, motion: Motion
) -> scm.ActionNode | str:
    if destination is None:
        return "the destination is not a world or lane position"
    actor = str(request.actor.name)
    start = motion.place.get(actor, request.actor.startPosition)
    turn = classify(_at_the_start(build, start), _at_the_start(build, destination), build.road_map)
    kind = turn.kind
    if request.hint in ("TurnLeft", "TurnRight", "Cross"):
        kind = request.hint
    elif turn.guessed:
        _guess(build, request, f"{kind}: {turn.how}")
    node = _add(build, request, kind)
    node.destination = destination
    motion.place[actor] = destination
    return node


@_maps("PrivateAction/RoutingAction/FollowTrajectoryAction")
def _trajectory(
    build: Build, request: Request, follow: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    shape = follow.find(".//Trajectory/Shape")
    polyline = None if shape is None else shape.find("Polyline")
    if polyline is None:
        return "only polyline trajectories map (FollowTrajectory); clothoids and NURBS do not"
    if follow.find("TimeReference/Timing") is not None:
        # Players then reach each vertex at its time, whatever the actor's speed
        # (`bicycle_fall_over`: 20 m in 2 s, then 5 m in 0.5 s, then standing still).
        return (
            "a trajectory followed in time (TimeReference Timing) has no SceML form: "
            "FollowTrajectory is followed at the actor's speed"
        )
    vertices = polyline.findall("Vertex")
    # SceML's exports start at the actor itself; any other trajectory begins at its first
    # vertex, where players put the actor when the action starts (`pedestrian_traj_synch`: a
    # path from the actor drove 0.5 m apart, its start 0.5 m behind the actor by then).
    from_first = not (vertices and _is_self(vertices[0], request.actor))
    if not from_first:
        vertices = vertices[1:]
    points = [place(build, vertex, initial=False) for vertex in vertices]
    if not points or any(point is None for point in points):
        return "a trajectory vertex is not a world or lane position"
    actor = str(request.actor.name)
    motion.place[actor] = points[-1]
    mode = follow.find("TrajectoryFollowingMode")
    steered = mode is not None and mode.get("followingMode") == "follow"
    tolerance = _trajectory_end(build, request, motion.speed.get(actor))
    # One point after the actor itself is a straight crossing to it (SceML's Cross).
    if len(points) == 1 and request.hint != "FollowTrajectory":
        if steered:
            _guess(build, request, "a one-point trajectory in follow mode read as a Cross")
        node = _add(build, request, "Cross", tolerance=tolerance)
        node.destination = points[0]
        return node
    node = _add(
        build,
        request,
        "FollowTrajectory",
        fromFirstWaypoint=from_first or None,
        tolerance=tolerance,
    )
    node.waypoints.extend(points)
    if steered:
        # Players steer towards the path then (esmini: a little behind it on bends).
        node.followingMode = scm.TrajectoryFollowingMode.follow
    return node


def _trajectory_end(build: Build, request: Request, speed: float | None) -> float | None:
    """The arrival tolerance at which the trajectory finishes when players end the action:
    esmini ends it in the step that leaves less than a step's travel of the path (speed times
    `xosc.PLAYER_STEP`), not at SceML's default 2 m (`parking_demo`'s walker at 2.78 m/s
    finished 0.65 s early, and the event waiting for the end of its walk started 13 steps
    early). None (the default) where the speed is not known or not a number."""
    if request.hint is not None or not isinstance(speed, float) or speed <= 0:
        return None
    if isinstance(speed, traced.Traced):
        return None
    tolerance = round(speed * PLAYER_STEP, 6)
    _guess(
        build,
        request,
        f"finished within {tolerance:g} m of the last point, a step's travel at {speed:g} m/s, "
        "where players end the trajectory",
    )
    return tolerance


def _is_self(vertex: etree._Element, actor: scm.Actor) -> bool:
    """A vertex at the actor's own position (SceML's exports start their polylines there)."""
    here = vertex.find("Position/RelativeObjectPosition")
    return (
        here is not None
        and last_name(str(here.get("entityRef"))) == actor.name
        and float(here.get("dx", "0")) == 0.0
        and float(here.get("dy", "0")) == 0.0
    )


#: LaneOffsetAction's dynamicsShape values, the same names as LaneChangeShape's.
_SHAPES = ("sinusoidal", "linear", "cubic", "step")


@_maps("PrivateAction/LateralAction/LaneOffsetAction")
def _lane_offset(
    build: Build, request: Request, action: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    dynamics = action.find("LaneOffsetActionDynamics")
    absolute = action.find("LaneOffsetTarget/AbsoluteTargetLaneOffset")
    relative = action.find("LaneOffsetTarget/RelativeTargetLaneOffset")
    target = absolute if absolute is not None else relative
    shape = "sinusoidal" if dynamics is None else dynamics.get("dynamicsShape", "sinusoidal")
    if target is None or shape not in _SHAPES:
        return f"a lane offset with this target or shape ({shape}) has no SceML form"
    if relative is not None and last_name(str(relative.get("entityRef"))) == request.actor.name:
        return "a lane offset relative to the actor itself has no SceML form"
    acceleration = None
    if dynamics is not None and dynamics.get("maxLateralAcc") is not None:
        acceleration = number(dynamics, "maxLateralAcc")
    node = _add(
        build,
        request,
        "LaneOffset",
        offset=number(target, "value"),
        maxLateralAcc=acceleration,  # unset: the language default, esmini's 0.5 m/s²
        shape=shape,
        continuous=action.get("continuous") == "true",
    )
    if relative is not None:
        node.targetActor = build.actor(relative.get("entityRef"), relative)
    return node


#: What other modules use to register and add their own kinds (global_kinds.py, lights.py,
#: trailers.py).
maps = _maps
add_node = _add

# Register their actions' mappers.
from . import controllers, distance_keeping, global_kinds, lights, trailers  # noqa: E402, F401

"""What each maneuver means to every player: when it starts, what it does, when it finishes.

SPEC §3 says a maneuver finishes when its goal is reached; this module says exactly how, once,
for the OpenSCENARIO export (which writes it so that a player such as esmini does it), the
preview (`sceml simulate`, which does it itself), the run checker (`sceml check-run`, which
checks a player did it) and the validation rules that refuse what no player can do. The
numbers of a player's own behaviour that the export relies on (esmini 3.6) are named here so
that the preview copies them instead of guessing.

Positions are the actor's reference point, which the export puts at the centre of its box
(BoundingBox Center x = 0), so a start position, a destination and a radius mean the same
point in the file, in the preview and in a player's log. Where a position is (a road
coordinate, a position relative to an actor where that actor is when it is used) is defined
once in `sceml.maps.resolve`, which every stage reads.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..model import catalog

# --- when a node starts --------------------------------------------------------------------------

#: A node starts this many time steps after its predecessors finished. Players evaluate a
#: trigger in the step after the event it waits for completed (esmini 3.6: an event's
#: StartTrigger sees the completeState of the previous step), so a flow from a node that is an
#: event of its own costs one step. A flow out of a node the export writes into its successor's
#: trigger (a condition, wait or join: `xosc.flows.inlined`) costs none: the successor starts
#: in the step the condition holds (`xosc.flows.flow_steps`). The preview does the same, so
#: that it keeps step with a player: root -> SpeedCondition -> Accelerate starts the Accelerate
#: one step after the start, in the step the speed is reached, as the original file would.
FLOW_DELAY_STEPS = 1

# --- who controls what --------------------------------------------------------------------------

#: The parts of its actor a maneuver controls, by its metamodel category: `speed` (the
#: longitudinal domain of OpenSCENARIO), `path` (lateral), both (composite). A turn is lateral:
#: it is routed, not driven, setting where the actor goes at junctions and leaving its speed to
#: whatever maneuver controls it (exported as AssignRouteAction, which players run in no
#: control domain, so a running Accelerate or Follow of the same actor goes on).
_CONTROLS = {"longitudinal": ("speed",), "lateral": ("path",), "composite": ("speed", "path")}


def controls(kind: str) -> tuple[str, ...]:
    """The parts of its actor a maneuver of `kind` controls (none for conditions and controller
    changes)."""
    return _CONTROLS.get(catalog.category(kind) or "", ())


# --- one maneuver of a part at a time --------------------------------------------------------------

# What an interrupting maneuver (`Maneuver.interrupts`, release 1.5) does when it starts: it
# ends the maneuvers of its actor running on a part it controls (`controls`), and each ended
# one counts as finished for its successors from that instant. Players do this to any action:
# esmini 3.6's Event::Start ends every running action of the entity whose control domains
# overlap the new one's (longitudinal, lateral; a routing action has none), with an end
# transition, so its event completes and a trigger waiting for its completeState holds in the
# next step; an event of priority overwrite (1.0, 1.1) or override (1.2+) ends the running
# events of its Maneuver the same way. The preview does the same (`simulate.engine`: a
# maneuver that claims a part supersedes its owner); SceML's flag makes the overlap explicit,
# so that simultaneity (SCEML-C001) accepts it.


# --- controllers ----------------------------------------------------------------------------------

#: Categories whose nodes finish in the step they start. A controller change (ActivateController,
#: AssignController, OverrideController) is an instant action to players (esmini 3.6 completes
#: the ControllerAction and ActivateControllerAction in the step it starts them), so the export
#: takes its event's completion as the node's finish; it controls no part of the actor itself:
#: what the controller then does is the player's, and SceML's preview does not run it.
INSTANT_CATEGORIES = ("controller",)
#: The domains an activation switches, as OpenSCENARIO's ActivateControllerAction attributes
#: (lighting and animation from 1.2) and SceML's ControllerActivation features, in that order.
CONTROLLER_DOMAINS = ("lateral", "longitudinal", "lighting", "animation")
#: OpenSCENARIO's OverrideControllerValueAction element for each ControllerOverrideKind, in the
#: schema's order.
OVERRIDE_ELEMENTS = {
    "throttle": "Throttle",
    "brake": "Brake",
    "clutch": "Clutch",
    "parkingBrake": "ParkingBrake",
    "steeringWheel": "SteeringWheel",
    "gear": "Gear",
}


def completes_at_once(kind: str) -> bool:
    """Whether a node of `kind` finishes as soon as it starts (a controller change)."""
    return catalog.category(kind) in INSTANT_CATEGORIES


# --- speed ----------------------------------------------------------------------------------------

#: A speed counts as reached within this much (m/s): Accelerate, Decelerate, Stop.
SPEED_TOLERANCE = 1e-6
#: Below this speed (m/s) an actor stands still for a StandStill condition (esmini 3.6's
#: STAND_STILL_THRESHOLD).
STAND_STILL_SPEED = 1e-3


def standing_after(standing_for: float | None, speed: float, dt: float) -> float | None:
    """How long an actor has stood still after a step of `dt` ending at `speed`: 0 in the step
    it stops in, one step more for each step after, None while it moves. esmini 3.6 stamps the
    stop with the step's time and a StandStillCondition compares the time since with
    `duration` (strictly greater); it stamps an actor standing from the start only in the
    first step (a stamp of t = 0 counts as none)."""
    if abs(speed) >= STAND_STILL_SPEED:
        return None
    return 0.0 if standing_for is None else standing_for + dt


def light_state_duration(transition_time: float, mode: str) -> float | None:
    """How long a LightState runs: its transition (esmini 3.6 ends a LightStateAction when the
    transition is over), or None, forever, for a flashing light (esmini never ends that
    action; another action on the light overrides it)."""
    return None if mode == "flashing" else transition_time


def measured_acceleration(direction: str, longitudinal: float) -> float:
    """The acceleration an AccelerationCondition compares, from the longitudinal one (the only
    one the preview knows, its lateral and vertical taken as 0): the magnitude without a
    direction (esmini 3.6's GetAcc), else the component."""
    if direction == "total":
        return abs(longitudinal)
    return longitudinal if direction == "longitudinal" else 0.0


def drive_distance_duration(distance: float, speed: float) -> float:
    """How long a DriveDistance lasts: it steps the speed to `speed` and holds it, so `distance`
    is driven from where the node starts after distance / speed seconds. (OpenSCENARIO 1.x has
    no condition that measures a distance from an event's start: TraveledDistanceCondition
    counts from the start of the simulation.) A speed of 0 never gets there: infinity."""
    return math.inf if speed <= 0 else distance / speed


# --- gap keeping (Follow, Approach) -------------------------------------------------------------

#: Gap keeping accelerates and brakes at most this much (m/s2), whatever the actor could do.
GAP_ACCELERATION = 3.0
GAP_DECELERATION = 6.0
#: esmini's LongitudinalDistanceAction: a damped spring whose constant is this factor times the
#: limit in force (the acceleration limit when too close, the deceleration limit when too far),
#: critically damped (damping 2 * sqrt(constant)).
GAP_SPRING = 0.4
#: A non-continuous distance action (Approach) stops driving when the gap is within this much
#: of its distance (esmini's LONGITUDINAL_DISTANCE_THRESHOLD); the actor then holds its speed.
APPROACH_HOLD = 0.1
#: Approach has finished once the gap is within this much of its distance. Wider than the
#: player's own stop: a spring closes the last decimetres slowly, so a finish at 0.1 m would
#: hang on the last centimetres of rounding between two players.
APPROACH_REACHED = 0.5


@dataclass(frozen=True)
class GapLimits:
    """The limits gap keeping drives within (m/s2, m/s2, m/s; the jerks m/s3, infinite: none)."""

    acceleration: float
    deceleration: float
    max_speed: float
    acceleration_rate: float = math.inf
    deceleration_rate: float = math.inf


def gap_limits(max_speed: float, max_acceleration: float, max_deceleration: float) -> GapLimits:
    """The gap-keeping limits of an actor with these performance limits."""
    return GapLimits(
        min(GAP_ACCELERATION, max_acceleration),
        min(GAP_DECELERATION, max_deceleration),
        max_speed,
    )


def gap_acceleration(
    gap: float, distance: float, relative_speed: float, limits: GapLimits
) -> float:
    """The acceleration gap keeping asks for: `gap` is centre to centre along the road,
    `relative_speed` the actor's speed minus the target's. esmini's spring: the tension is the
    acceleration limit when the actor is too close (gap below distance), else the deceleration
    limit, as its code has it."""
    error = gap - distance
    tension = (limits.acceleration if error < 0 else limits.deceleration) * GAP_SPRING
    wanted = error * tension - relative_speed * 2.0 * math.sqrt(tension)
    return min(max(wanted, -limits.deceleration), limits.acceleration)


def jerk_limited(wanted: float, before: float, limits: GapLimits, dt: float) -> float:
    """The acceleration gap keeping applies, `wanted` changed from `before` by at most the
    jerk limits over a step, as esmini's LongitudinalDistanceAction does: growing braking by
    the deceleration rate, growing acceleration by the acceleration rate (easing off is free)."""
    if wanted < 0.0 and wanted < before:
        return max(before - limits.deceleration_rate * dt, wanted)
    if wanted >= 0.0 and wanted > before:
        return min(before + limits.acceleration_rate * dt, wanted)
    return wanted


def requested_gap(distance: float, time_gap: bool, target_speed: float, leading: bool) -> float:
    """The signed gap a distance keeping drives to (positive: the target ahead): `distance` m,
    or `distance` s at the target's speed, on the side the displacement names."""
    gap = abs(target_speed) * distance if time_gap else distance
    return -gap if leading else gap


def free_gap(ahead: float, length: float, target_length: float) -> float:
    """The signed gap between two boxes along the actor's heading (`ahead`: centre to centre,
    positive with the target ahead), 0 while they overlap, as esmini's freespace measures it."""
    reach = (length + target_length) / 2.0
    if ahead >= 0.0:
        return max(0.0, ahead - reach)
    return min(0.0, ahead + reach)


def follow_slack(distance: float) -> float:
    """Follow has reached its gap once the gap is below distance + this slack: a controller
    closes in from above and then holds the gap, so "closer than the distance" may never hold."""
    return max(1.0, distance / 10.0)


def follow_time_slack(time_gap: float) -> float:
    """Follow of a time gap has reached it once the headway is below time_gap + this slack,
    for the same reason as `follow_slack`."""
    return max(0.1, time_gap / 10.0)


#: Approach of a time gap has finished once the headway is within this much of it (s).
APPROACH_REACHED_TIME = 0.1


def follow_reached(gap: float, distance: float) -> bool:
    """Whether Follow has finished (it keeps the gap afterwards)."""
    return gap < distance + follow_slack(distance)


def approach_reached(gap: float, distance: float) -> bool:
    """Whether Approach has finished (it drives on until within APPROACH_HOLD, then holds its
    speed, unless a later maneuver takes the speed first)."""
    return abs(gap - distance) < APPROACH_REACHED


# --- conditions ---------------------------------------------------------------------------------

#: TimeToCollision is measured between the bounding boxes (OpenSCENARIO freespace="true") unless
#: the node says otherwise: the default of its `freespace`, so files saved before that feature
#: keep their meaning.
TTC_FREESPACE = True


@dataclass(frozen=True)
class Separation:
    """Where a target is from an actor, in the actor's frame (x ahead, y to the left), and the
    sizes of both boxes: what a measuring condition's distance is taken from."""

    ahead: float
    left: float
    length: float
    width: float
    target_length: float
    target_width: float
    #: The least distance between the two boxes' outlines (0 while they overlap); None where
    #: the measure is not taken between the boxes (finding it is most of a preview step's cost).
    box_gap: float | None
    #: Where the target's box centre is from the actor's (ahead, left), where a box is not
    #: centred on its reference point (Actor.boxCenterX); None: the same as (ahead, left).
    centres: tuple[float, float] | None = None


def measured_distance(at: Separation, freespace: bool, kind: str) -> float:
    """The distance a condition measures (esmini 3.6, `Object::Distance` in the entity
    coordinate system): euclidean is the straight line, longitudinal and lateral its parts
    along and across the actor's heading; with freespace between the boxes' outlines (the
    boxes taken as aligned for the parts), else between the reference points."""
    ahead, left = at.centres if freespace and at.centres is not None else (at.ahead, at.left)
    if kind == "longitudinal":
        reach = (at.length + at.target_length) / 2 if freespace else 0.0
        return max(0.0, abs(ahead) - reach)
    if kind == "lateral":
        reach = (at.width + at.target_width) / 2 if freespace else 0.0
        return max(0.0, abs(left) - reach)
    if not freespace:
        return math.hypot(at.ahead, at.left)
    if at.box_gap is None:
        raise ValueError("a distance between the boxes needs the separation's box_gap")
    return at.box_gap


#: TraveledDistance counts the actor's odometer from the start of the simulation, every metre
#: moved whichever way (esmini 3.6: `odometer_`, compared with `>=`), not from the node's start.
TRAVELED_FROM = "simulation start"


def traveled_reached(odometer: float, distance: float) -> bool:
    """Whether a TraveledDistance holds."""
    return odometer >= distance


def time_headway(at: Separation, freespace: bool, kind: str, speed: float) -> float | None:
    """The time headway a player measures (esmini 3.6, `TrigByTimeHeadway`): the measured
    distance to the target over the actor's own speed. None when undefined: the target
    behind, or the actor standing or reversing."""
    if at.ahead < 0 or speed < 1e-10:
        return None
    return measured_distance(at, freespace, kind) / speed


def time_to_collision(
    free_distance: float,
    velocity: tuple[float, float],
    speed: float,
    target_velocity: tuple[float, float],
    target_speed: float,
) -> float | None:
    """The time to collision a player measures (esmini 3.6, `Object::TimeToCollision`): the
    distance between the boxes over the closing speed along the target's direction of travel
    (the actor's own speed when the target stands). None when undefined: touching, or not
    closing in."""
    tx, ty = target_velocity
    target_moving = math.hypot(tx, ty)
    if target_moving < 1e-10:
        closing = speed
    else:
        along = (velocity[0] * tx + velocity[1] * ty) / target_moving
        closing = _sign(speed) * _sign(along) * (along - abs(target_speed))
    if abs(free_distance) < 1e-10 or abs(closing) < 1e-10:
        return None
    ttc = free_distance / closing
    return ttc if ttc >= 0 else None


def _sign(value: float) -> float:
    return -1.0 if value < 0 else 1.0


# --- arrival and lane changes ---------------------------------------------------------------------

#: Routed and trajectory maneuvers (TurnLeft, TurnRight, Cross, FollowTrajectory) finish when the
#: actor's reference point is within the maneuver's `tolerance` of its destination or last
#: waypoint; Overtake changes back once `overtake_back_tolerance(gap)` of the point `gap` metres
#: ahead of the target.


def overtake_back_tolerance(gap: float) -> float:
    """How near the point `gap` m ahead of the target counts as there (a fast pass skips it)."""
    return max(1.0, gap / 2.0)


# --- parameters and variables (the global kinds) -------------------------------------------------

#: A SetParameter or SetVariable finishes in the step it starts: players complete a
#: ParameterAction or VariableAction at once (esmini 3.6 logs the set and the action's
#: completeState in the same step). esmini 3.6 does not run a ParameterAction's ModifyAction
#: ("not supported yet"); a VariableAction's it does.
GLOBAL_ACTION_STEPS = 0


def _as_number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def value_holds(current: str, rule: str, value: str) -> bool:
    """Whether a ParameterCondition or VariableCondition holds: numbers compare as numbers
    (esmini compares a double parameter numerically), other values as text, equalTo only."""
    held, wanted = _as_number(current), _as_number(value)
    if held is None or wanted is None:
        return rule == "equalTo" and current.strip().lower() == value.strip().lower()
    return compares(rule, held, wanted)


def compares(rule: str, value: float, threshold: float) -> bool:
    """Whether `value` stands to `threshold` as a ComparisonRule says (equalTo within 1e-9)."""
    if rule == "lessThan":
        return value < threshold
    if rule == "greaterThan":
        return value > threshold
    if rule == "lessOrEqual":
        return value <= threshold
    if rule == "greaterOrEqual":
        return value >= threshold
    return abs(value - threshold) < 1e-9


def value_after(current: str, modify: str, value: str) -> str:
    """The parameter's or variable's text after a SetParameter or SetVariable; ValueError when
    adding to or multiplying something that is no number."""
    if modify == "set":
        return value
    held, by = _as_number(current), _as_number(value)
    if held is None or by is None:
        raise ValueError(f"cannot {modify} {value!r} to {current!r}: both must be numbers")
    result = held + by if modify == "add" else held * by
    return repr(result) if result != int(result) else str(int(result))


# --- lane offset ---------------------------------------------------------------------------------


def lane_offset_duration(change: float, max_lateral_acc: float, shape: str) -> float:
    """How long a LaneOffset takes to move `change` m sideways, its lateral acceleration peaking
    at `max_lateral_acc` (esmini 3.6's TransitionDynamics): a half sine over π√(|Δ|/2a); cubic,
    and linear read as cubic, √(6|Δ|/a); a step at once. It finishes then, continuous or not
    (esmini ends the action when the offset is reached)."""
    if shape == "step" or change == 0:
        return 0.0
    if shape == "sinusoidal":
        return math.pi * math.sqrt(abs(change) / (2 * max_lateral_acc))
    return math.sqrt(6 * abs(change) / max_lateral_acc)

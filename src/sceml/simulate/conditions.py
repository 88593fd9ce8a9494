"""When each condition kind holds (SPEC §3): a test of the actors' state, registered by name.

A condition is evaluated only after its activation, at the activation instant and after every
step, until it first holds (an `edge` other than none: until its test changes so; `on_edge`). A position's radius is between reference points (centres); an
InVehicleRadius, a time headway and a time to collision measure the distance their node names
(`xosc.meaning.measured_distance`: by default between the centres for InVehicleRadius, as the
export's `freespace="false"`, and between the boxes for the time conditions).
"""

from __future__ import annotations

import math
from collections.abc import Callable

from pyecore.ecore import EObject

from ..maps.resolve import is_relative
from ..model.params import concrete
from ..xosc import meaning
from .actors import Actor
from .geometry import free_distance_now
from .world import World

Test = Callable[[World], bool]

_KINDS: dict[str, Callable[[EObject, World], Test]] = {}


def kind(
    name: str,
) -> Callable[[Callable[[EObject, World], Test]], Callable[[EObject, World], Test]]:
    def register(make: Callable[[EObject, World], Test]) -> Callable[[EObject, World], Test]:
        _KINDS[name] = make
        return make

    return register


def condition_for(node: EObject, world: World) -> Test | None:
    """The test of a condition node, set up at its activation; None for an unknown kind."""
    make = _KINDS.get(node.eClass.name)
    if make is None:
        return None
    test = make(node, world)
    edge = getattr(getattr(node, "edge", None), "name", "none")
    return test if edge == "none" else on_edge(test, edge)


def on_edge(test: Test, edge: str) -> Test:
    """A test that holds when `test` changes as `edge` says between two evaluations: rising,
    false at the previous and true now; falling, the reverse; risingOrFalling, either. The
    first evaluation has no previous one and never holds, as in esmini."""
    previous: list[bool] = []

    def holds(w: World) -> bool:
        now = test(w)
        before = previous[-1] if previous else None
        previous[:] = [now]
        if before is None or before == now:
            return False
        return edge == "risingOrFalling" or (edge == "rising") == now

    return holds


def _compare(rule: EObject | None, value: float, threshold: float, previous: float | None) -> bool:
    name = getattr(rule, "name", "greaterThan")
    if name == "equalTo":
        crossed = previous is not None and (previous - threshold) * (value - threshold) <= 0
        return abs(value - threshold) < 1e-6 or crossed
    return meaning.compares(name, value, threshold)


@kind("InLocationRadius")
def in_location_radius(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    what = f"{node.name}'s position"
    radius = concrete(node, "radius")
    if is_relative(node.position):  # where its entity is at each step, as players evaluate it
        return lambda w: actor.distance_to(*w.point(node.position, what)) <= radius + 1e-9
    x, y = world.point(node.position, what)
    return lambda w: actor.distance_to(x, y) <= radius + 1e-9


@kind("InVehicleRadius")
def in_vehicle_radius(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    other = world.actor(node.targetActor, str(node.name))
    radius = concrete(node, "radius")
    freespace, measure = bool(node.freespace), node.relativeDistanceType.name
    rule = node.rule.name
    _frame_note(node, world)
    previous: list[float | None] = [None]

    def holds(w: World) -> bool:
        distance = meaning.measured_distance(
            separation(actor, other, freespace), freespace, measure
        )
        if rule in ("lessThan", "lessOrEqual"):
            # Within the radius counts its edge, as InVehicleRadius always has.
            result = distance <= radius + 1e-9
        else:
            result = _compare(node.rule, distance, radius, previous[0])
        previous[0] = distance
        return result

    return holds


@kind("TimeElapsed")
def time_elapsed(node: EObject, world: World) -> Test:
    until = world.t + concrete(node, "duration")
    return lambda w: w.t >= until - 1e-9


@kind("SpeedCondition")
def speed_condition(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    threshold = concrete(node, "speed")
    previous: list[float | None] = [None]

    def holds(w: World) -> bool:
        result = _compare(node.rule, actor.speed, threshold, previous[0])
        previous[0] = actor.speed
        return result

    return holds


@kind("TraveledDistance")
def traveled_distance(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    distance = concrete(node, "distance")
    return lambda w: meaning.traveled_reached(actor.odometer, distance)


#: Coordinate systems the preview measures in: the actor's own frame. Lane, road and
#: trajectory coordinates follow the road's curve, which the preview does not take apart.
_MEASURED_FRAMES = ("entity",)


def separation(actor: Actor, other: Actor, freespace: bool) -> meaning.Separation:
    """Where `other` is from `actor`, in the actor's frame; the gap between their boxes only
    where the measure is taken between them (`freespace`): it costs far more than the rest."""
    dx, dy = other.x - actor.x, other.y - actor.y
    cos, sin = math.cos(actor.heading), math.sin(actor.heading)
    centres = None
    if actor.box_ahead or other.box_ahead:
        # The boxes' centres lie ahead of the reference points (boxCenterX): freespace is
        # measured between the boxes where they are.
        cx = dx + other.box_ahead * math.cos(other.heading) - actor.box_ahead * cos
        cy = dy + other.box_ahead * math.sin(other.heading) - actor.box_ahead * sin
        centres = (cx * cos + cy * sin, -cx * sin + cy * cos)
    return meaning.Separation(
        ahead=dx * cos + dy * sin,
        left=-dx * sin + dy * cos,
        length=actor.length,
        width=actor.width,
        target_length=other.length,
        target_width=other.width,
        box_gap=free_distance_now(actor, other) if freespace else None,
        centres=centres,
    )


def _frame_note(node: EObject, world: World) -> None:
    system = node.coordinateSystem.name
    if system not in _MEASURED_FRAMES:
        world.note(
            f"{node.name}: measured in the actor's own frame; the preview has no {system} "
            "coordinates (a player measures along the road, so on a curve it differs)"
        )


@kind("TimeHeadway")
def time_headway(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    other = world.actor(node.targetActor, str(node.name))
    threshold = concrete(node, "time")
    freespace, measure = bool(node.freespace), node.relativeDistanceType.name
    _frame_note(node, world)

    def holds(w: World) -> bool:
        headway = meaning.time_headway(
            separation(actor, other, freespace), freespace, measure, actor.speed
        )
        # Undefined (target behind, standing): players hold no rule then.
        return headway is not None and _compare(node.rule, headway, threshold, None)

    return holds


@kind("TimeToCollision")
def time_to_collision(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    other = world.actor(node.targetActor, str(node.name))
    threshold = concrete(node, "time")
    freespace, measure = bool(node.freespace), node.relativeDistanceType.name
    _frame_note(node, world)

    def holds(w: World) -> bool:
        ttc = meaning.time_to_collision(
            meaning.measured_distance(separation(actor, other, freespace), freespace, measure),
            actor.velocity(),
            actor.speed,
            other.velocity(),
            other.speed,
        )
        # Undefined (touching, not closing in): players hold no rule then.
        return ttc is not None and _compare(node.rule, ttc, threshold, None)

    return holds


@kind("StandStill")
def stand_still(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    duration = concrete(node, "duration")
    # Counted from when the actor stopped, before the activation too (esmini's timestamp).
    return lambda w: actor.standing_for is not None and actor.standing_for > duration + 1e-9


@kind("AccelerationCondition")
def acceleration_condition(node: EObject, world: World) -> Test:
    actor = world.actor(node.referenceActor, str(node.name))
    threshold = concrete(node, "acceleration")
    direction = node.direction.name
    if direction in ("lateral", "vertical"):
        world.note(f"{node.name}: the preview has no {direction} acceleration, taken as 0")
    previous: list[float | None] = [None]

    def holds(w: World) -> bool:
        now = meaning.measured_acceleration(direction, actor.acceleration)
        result = _compare(node.rule, now, threshold, previous[0])
        previous[0] = now
        return result

    return holds

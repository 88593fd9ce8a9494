"""Kinematic actors: a point moving along a path at a speed, with a lateral offset and a box.

Nothing here knows vehicle dynamics: speed changes at the rate a maneuver asks for, the heading
is the path's (turned by the slope of a lane change), and the box turns with it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

from ..model import speed_shapes
from ..xosc.meaning import (
    GapLimits,
    free_gap,
    gap_acceleration,
    jerk_limited,
    requested_gap,
    standing_after,
)
from .paths import Path


@dataclass(frozen=True)
class Shift:
    """A lateral move of `amount` m (left positive) over `length` m of path from `start`,
    along half a cosine: no lateral speed at either end."""

    start: float
    length: float
    amount: float

    def progress(self, d: float) -> float:
        return min(max((d - self.start) / self.length, 0.0), 1.0) if self.length > 0 else 1.0

    def offset(self, d: float) -> float:
        return self.amount * (1.0 - math.cos(math.pi * self.progress(d))) / 2.0

    def slope(self, d: float) -> float:
        u = self.progress(d)
        if self.length <= 0 or u <= 0.0 or u >= 1.0:
            return 0.0
        return self.amount * math.pi / (2.0 * self.length) * math.sin(math.pi * u)


class SpeedControl(Protocol):
    """What decides an actor's speed at the end of the next step."""

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float: ...


class Hold:
    """Keep the speed: no longitudinal maneuver is running."""

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float:
        return actor.speed


@dataclass(frozen=True)
class OwnLimits:
    """An actor's own Performance (release 1.4's Actor.maxSpeed, maxAcceleration,
    maxDeceleration; m/s, m/s2, m/s2); None where it states none (the preview then caps nothing,
    as before)."""

    max_speed: float | None = None
    max_acceleration: float | None = None
    max_deceleration: float | None = None

    def target(self, speed: float) -> float:
        """A target speed held to the top speed either way, as esmini holds a SpeedAction's."""
        if self.max_speed is None:
            return speed
        return max(-self.max_speed, min(speed, self.max_speed))

    def rate(self, rate: float, speeding_up: bool) -> float:
        """A finite rate held to the largest acceleration (speeding up) or deceleration; a step
        (an infinite rate) stays a step, as in esmini."""
        most = self.max_acceleration if speeding_up else self.max_deceleration
        return rate if most is None or math.isinf(rate) else min(rate, most)


@dataclass(frozen=True)
class Ramp:
    """Change the speed towards `target` at `rate` (m/s2); a step when `rate` is infinite.
    Both are held to the actor's own limits (`OwnLimits`)."""

    target: float
    rate: float = math.inf

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float:
        target = actor.own_limits.target(self.target)
        change = target - actor.speed
        limit = actor.own_limits.rate(self.rate, abs(target) > abs(actor.speed)) * dt
        return target if abs(change) <= limit else actor.speed + math.copysign(limit, change)


@dataclass(frozen=True)
class SpeedMatching:
    """Bring the speed to the `target` actor's times `factor` plus `delta`, following it as it
    changes, at `rate` (m/s2; a step when infinite): MatchSpeed."""

    target: str
    factor: float
    delta: float
    rate: float = math.inf

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float:
        wanted = others[self.target].speed * self.factor + self.delta
        return Ramp(wanted, self.rate).next_speed(actor, others, dt)


class ShapedRamp:
    """Change the speed from `start` to `target` over `duration` s along a cubic or sinusoidal
    curve (`model.speed_shapes`), as players do; it counts its own time step by step."""

    def __init__(self, shape: str, start: float, target: float, duration: float) -> None:
        self.shape, self.start, self.target, self.duration = shape, start, target, duration
        self.elapsed = 0.0

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float:
        self.elapsed += dt
        if self.elapsed >= self.duration - 1e-9:
            return self.target
        share = speed_shapes.fraction(self.shape, self.elapsed / self.duration)
        return self.start + (self.target - self.start) * share


@dataclass(frozen=True)
class GapSpec:
    """What gap a distance keeping drives to: `value` m (or s at the target's speed, with
    `time_gap`), between the boxes with `freespace`, ahead of the target with `leading`."""

    value: float
    time_gap: bool = False
    freespace: bool = False
    leading: bool = False

    def wanted(self, lead: Actor) -> float:
        """The signed gap wanted now (positive: the target ahead)."""
        return requested_gap(self.value, self.time_gap, lead.speed, self.leading)

    def measured(self, actor: Actor, lead: Actor) -> float:
        """The signed gap now, measured as the action measures it."""
        if not self.freespace:
            return actor.gap_to(lead)
        return free_gap(actor.box_gap_ahead(lead), actor.length, lead.length)


class GapKeeping:
    """Drive towards the gap `spec` says to the `target` actor, by the players' law
    (`xosc.meaning.gap_acceleration`), within `limits` and their jerks."""

    def __init__(
        self, target: str, spec: GapSpec, limits: GapLimits, hold_within: float | None = None
    ) -> None:
        self.target, self.spec, self.limits = target, spec, limits
        #: Stop driving (hold the speed) once the gap is within this much; None: keep it.
        self.hold_within = hold_within
        #: The acceleration of the last step, which the jerk limits change from.
        self.acceleration = 0.0

    def next_speed(self, actor: Actor, others: Mapping[str, Actor], dt: float) -> float:
        lead = others[self.target]
        gap, wanted = self.spec.measured(actor, lead), self.spec.wanted(lead)
        if self.hold_within is not None and abs(gap - wanted) < self.hold_within:
            actor.control = Hold()
            return actor.speed
        asked = gap_acceleration(gap, wanted, actor.speed - lead.speed, self.limits)
        self.acceleration = jerk_limited(asked, self.acceleration, self.limits, dt)
        speed = actor.speed + self.acceleration * dt
        return max(-self.limits.max_speed, min(speed, self.limits.max_speed))


class Actor:
    """One actor's state: path, distance along it, lateral offset, speed and pose."""

    def __init__(
        self,
        name: str,
        kind: str,
        ego: bool,
        size: tuple[float, float],
        path: Path,
        speed: float,
        lateral: float = 0.0,
    ) -> None:
        self.name, self.kind, self.ego = name, kind, ego
        self.length, self.width = size
        #: How far the box's centre lies ahead of the reference point (Actor.boxCenterX).
        self.box_ahead = 0.0
        self.path = path
        self.d = 0.0
        self.lateral = lateral
        self.shift: Shift | None = None
        self.speed = speed
        self.control: SpeedControl = Hold()
        self.x = self.y = self.heading = 0.0
        #: Metres moved since the run started, whichever way (TraveledDistance's odometer).
        self.odometer = 0.0
        #: Dragged by another actor (`trailers.py`): it neither drives nor follows its path.
        self.towed = False
        #: Seconds stood still since the step it stopped in (StandStill); None while moving
        #: and before the first step (`xosc.meaning.standing_after`).
        self.standing_for: float | None = None
        #: The change of speed over the last step (AccelerationCondition), m/s².
        self.acceleration = 0.0
        #: The actor's own Performance, where the model states one (`setup.make_actor`).
        self.own_limits = OwnLimits()
        self.place()

    def place(self) -> None:
        """Compute the pose from the path, the distance along it and the lateral offset."""
        px, py, heading = self.path.pose(self.d)
        offset, slope = self.lateral, 0.0
        if self.shift is not None:
            offset += self.shift.offset(self.d)
            slope = self.shift.slope(self.d)
        self.x = px - offset * math.sin(heading)
        self.y = py + offset * math.cos(heading)
        self.heading = heading + math.atan(slope)

    def advance_to(self, speed: float, dt: float) -> bool:
        """Move one step ending at `speed`: the mean speed of the step gives the distance.

        A negative speed drives backwards along the path (the heading stays). At the end of a
        road without a link the actor stops, as players stop it; True when it stops there in
        this step."""
        step = (self.speed + speed) / 2.0 * dt
        self.acceleration = (speed - self.speed) / dt
        self.standing_for = standing_after(self.standing_for, speed, dt)
        self.speed = speed
        end = self.path.end_of_road
        if end is not None and self.d >= end - 1e-9 and step >= 0.0:
            self.speed = 0.0
            return False
        if step != 0.0:  # standing actors (waiting for their trigger) cost nothing
            # The speed is along the heading: during a lane change part of it goes sideways.
            slope = self.shift.slope(self.d) if self.shift is not None else 0.0
            self.d += step / math.sqrt(1.0 + slope * slope)
            x, y = self.x, self.y
            stopped = False
            if end is not None and self.d >= end:
                self.d, self.speed, stopped = end, 0.0, True
            self.place()
            self.odometer += math.hypot(self.x - x, self.y - y)
            return stopped
        return False

    def follow(self, path: Path, lateral: float = 0.0) -> None:
        """Go on along a new path that starts where the actor is."""
        self.path, self.d, self.lateral, self.shift = path, 0.0, lateral, None
        self.place()

    def settle_shift(self) -> None:
        """A finished lateral move becomes part of the constant offset."""
        if self.shift is not None:
            self.lateral += self.shift.offset(self.d)
            self.shift = None

    def velocity(self) -> tuple[float, float]:
        """The velocity (m/s) along the heading."""
        return self.speed * math.cos(self.heading), self.speed * math.sin(self.heading)

    def distance_to(self, x: float, y: float) -> float:
        return math.hypot(self.x - x, self.y - y)

    def gap_to(self, other: Actor) -> float:
        """How far `other` is ahead, centre to centre, along this actor's heading."""
        return (other.x - self.x) * math.cos(self.heading) + (other.y - self.y) * math.sin(
            self.heading
        )

    def box_gap_ahead(self, other: Actor) -> float:
        """How far `other`'s box centre is ahead of this actor's, along this actor's heading
        (the boxes' centres lie `box_ahead` ahead of the reference points)."""
        ahead = self.gap_to(other) - self.box_ahead
        turn = other.heading - self.heading
        return ahead + other.box_ahead * math.cos(turn)

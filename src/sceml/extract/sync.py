"""Why an actor started when it did: the condition that held first at that moment.

When a maneuver starts some time after the node before it finished, something made it wait.
Each explanation SceML can state is tried on the recording: another actor came within a radius
(InVehicleRadius), another actor reached a place (InLocationRadius), another actor's speed
passed a value (SpeedCondition). One counts only if, evaluated from the node's activation as
the preview and the export evaluate it, it first holds at the start (within a tolerance) and
not already at the activation. The simplest that counts is taken in that order; when none
does, the wait is a time (TimeElapsed, or KeepVelocity while driving on).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..simulate import DEFAULT_STEP
from .events import Event
from .motion import Array, Motion
from .thresholds import Thresholds


@dataclass(frozen=True)
class Explanation:
    """A condition node to put before a maneuver: kind, reference and target actor, parameters.

    `fires` is when it first holds on the recording after its activation; `alternatives`
    names the other explanations that also fitted; `confidence` is high, medium or low.
    """

    kind: str
    actor: str
    target: str | None
    parameters: dict[str, object]
    fires: float
    confidence: str
    reason: str
    alternatives: tuple[str, ...] = field(default=())

    def describe(self) -> str:
        """The condition as one line: kind, actors and parameters."""
        about = f"{self.actor}" + (f" and {self.target}" if self.target else "")
        values = ", ".join(f"{k}={_show(v)}" for k, v in self.parameters.items())
        return f"{self.kind}({about}; {values})"


def _show(value: object) -> str:
    if isinstance(value, tuple):
        return "(" + ", ".join(f"{v:.2f}" for v in value) + ")"
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)


def explain(
    actor: str,
    start: float,
    activation: float,
    motions: dict[str, Motion],
    ego: str | None,
    thresholds: Thresholds,
    *,
    driving: bool,
    speed_changes: dict[str, list[Event]] | None = None,
) -> Explanation:
    """The best explanation of `actor` starting at `start` after waiting since `activation`.

    `speed_changes` are the speed changes extracted for each actor: a speed condition on
    another actor is stated only at a speed its extracted change passes through.
    """
    others = [m for name, m in motions.items() if name != actor]
    # The ego first: scenarios are written around it, so it is the likelier trigger.
    others.sort(key=lambda m: (m.name != ego, m.name))
    found = [
        *_vehicle_radius(actor, motions[actor], others, start, activation, thresholds),
        *_speed(others, start, activation, thresholds, speed_changes or {}),
        *_location(motions[actor], others, start, activation, thresholds),
    ]
    if not found:
        return _waited(actor, start, activation, driving)
    best, rest = found[0], found[1:]
    error = abs(best.fires - start)
    step = motions[actor].step
    confidence = "high" if error <= 1.5 * step and not rest else "medium"
    return Explanation(
        best.kind,
        best.actor,
        best.target,
        best.parameters,
        best.fires,
        confidence,
        best.reason,
        tuple(r.describe() for r in rest),
    )


def _waited(actor: str, start: float, activation: float, driving: bool) -> Explanation:
    # A player ends the wait at the first step at least `duration` after its start. Aimed at
    # the step itself, a start known to a few milliseconds fell on either side of it (a car's
    # step fitted 5 ms late set off a whole step late, half a metre at 10 m/s); half a step
    # less ends it at the nearest step.
    duration = round(max(start - activation - DEFAULT_STEP / 2, 0.0), 2)
    kind = "KeepVelocity" if driving else "TimeElapsed"
    return Explanation(
        kind,
        actor,
        None,
        {"duration": duration},
        start,
        "low",
        "no other actor explains the start; it is kept as a time",
    )


def _first(held: NDArray[np.bool_], times: Array, activation: float) -> float | None:
    """The first time from `activation` at which `held` is true; None if never or at once."""
    k0 = int(np.searchsorted(times, activation - 1e-9))
    hits = np.nonzero(held[k0:])[0]
    if not len(hits) or hits[0] == 0:
        return None  # never, or already at the activation: it would not wait for the start
    return float(times[k0 + int(hits[0])])


def _round_between(low: float, high: float, near: float) -> float:
    """The roundest number in [low, high]: an integer, else a half, else `near` to 0.1."""
    for unit in (5.0, 1.0, 0.5):
        options = np.arange(math.ceil(low / unit) * unit, high + 1e-9, unit)
        if len(options):
            return float(options[np.argmin(np.abs(options - near))])
    return round(near, 1)


def _vehicle_radius(
    actor: str,
    own: Motion,
    others: list[Motion],
    start: float,
    activation: float,
    thresholds: Thresholds,
) -> list[Explanation]:
    found: list[tuple[float, Explanation]] = []
    for other in others:
        distance = np.hypot(
            own.x - np.interp(own.times, other.times, other.x),
            own.y - np.interp(own.times, other.times, other.y),
        )
        at = own.at(distance, start)
        if at > thresholds.vehicle_radius:
            continue
        tolerance = thresholds.sync_tolerance
        low, high = own.at(distance, start + tolerance / 2), own.at(distance, start - tolerance / 2)
        if not high > at > low:
            continue  # not closing in at the start
        radius = _round_between(low, high, at)
        closing = (high - low) / tolerance
        fires = _first(distance <= radius, own.times, activation)
        if fires is None or abs(fires - start) > tolerance:
            continue
        found.append(
            (
                closing,
                Explanation(
                    "InVehicleRadius",
                    actor,
                    other.name,
                    {"radius": radius},
                    fires,
                    "",
                    f"{other.name} came within {radius:g} m",
                ),
            )
        )
    # The fastest approach first: it pins the moment best, and is the likelier cause.
    return [e for _, e in sorted(found, key=lambda pair: -pair[0])]


def _speed(
    others: list[Motion],
    start: float,
    activation: float,
    thresholds: Thresholds,
    speed_changes: dict[str, list[Event]],
) -> list[Explanation]:
    found = []
    for other in others:
        acceleration = np.gradient(other.speed, other.step)
        if abs(other.at(acceleration, start)) <= thresholds.accel_threshold:
            continue
        speed = round(other.at(other.speed, start), 1)
        rising = other.at(acceleration, start) > 0
        if not _passes(speed_changes.get(other.name, []), start, speed, rising, thresholds):
            continue
        held = other.speed >= speed if rising else other.speed <= speed
        fires = _first(held, other.times, activation)
        if fires is None or abs(fires - start) > thresholds.sync_tolerance:
            continue
        rule = "greaterThan" if rising else "lessThan"
        found.append(
            Explanation(
                "SpeedCondition",
                other.name,
                None,
                {"rule": rule, "speed": speed},
                fires,
                "",
                f"{other.name}'s speed passed {speed:g} m/s",
            )
        )
    return found


def _passes(
    changes: list[Event], start: float, speed: float, rising: bool, thresholds: Thresholds
) -> bool:
    """Whether one of the extracted speed changes runs at `start` (within the tolerance) and
    passes through `speed` the same way, with a margin of the smallest speed change each side.

    The smoothed speed of a noisy recording wanders by tenths of a m/s; a condition on a
    value the extracted change never reaches (or passes long before) would never fire in the
    scenario, and its actor would wait for ever.
    """
    margin = thresholds.min_speed_change / 2
    tolerance = thresholds.sync_tolerance
    for change in changes:
        if change.from_speed is None or not change.start - tolerance <= start <= change.end:
            continue
        target = float(str(change.parameters.get("targetSpeed", change.parameters.get("speed", 0))))
        low, high = sorted((change.from_speed, target))
        if (target > change.from_speed) == rising and low + margin <= speed <= high - margin:
            return True
    return False


def _location(
    own: Motion, others: list[Motion], start: float, activation: float, thresholds: Thresholds
) -> list[Explanation]:
    found = []
    radius = thresholds.location_radius
    here = own.position(start)
    for other in others:
        if other.at(other.speed, start) <= thresholds.standing_speed:
            continue
        # The place is `radius` further on along the other's path, less half a replay step's
        # travel, so that it enters the circle about that place at the start, half a step
        # clear of the boundary either side (a place right on it fires a step late or early
        # in a replay, by the rounding of its coordinates).
        margin = other.at(other.speed, start) * DEFAULT_STEP / 2
        ahead = other.at(other.arc, start) + radius - margin
        when = float(np.interp(ahead, other.arc, other.times))
        x, y = other.position(when)
        heading = other.at(other.heading, when)
        if math.hypot(x - here[0], y - here[1]) > thresholds.location_reach:
            continue  # too far away to be why this actor started
        held = np.hypot(other.x - x, other.y - y) <= radius
        fires = _first(held, other.times, activation)
        if fires is None or abs(fires - start) > thresholds.sync_tolerance:
            continue
        found.append(
            Explanation(
                "InLocationRadius",
                other.name,
                None,
                {"position": (x, y, heading), "radius": radius},
                fires,
                "",
                f"{other.name} reached ({x:.1f}, {y:.1f})",
            )
        )
    return found

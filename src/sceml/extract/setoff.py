"""A walker's or rider's set-off before a crossing, fitted in the plane (noisy recordings).

SceML's crossing (the library's CrossingManeuver, and what the preview plays) is a speed
change from standing along the way the actor faces, then, when it has finished, a Cross
straight to the destination: a ramp along one line and a sharp bend onto another at the
ramp's end. Fitted against the distance along the smoothed path, that ramp came out longer
and gentler than walked: the smoothing cuts the bend's corner (about 0.1 m of distance lost
over the second around it, just where the ramp ends) and, at a walker's low speed, adds its
own sideways jitter to the length (about 0.05 m while the ramp runs). The replay starts the
Cross when the change has finished, so the walker turned late, a metre off.

Here the raw positions are fitted directly: standing at P until t1, then along a line at a
speed ramping linearly to its end at t2, where the path bends onto another line, walked at
a steady speed. For fixed (t1, t2) each coordinate is linear in its three unknowns (where it
stood, and its two velocities), so each candidate pair is one small least-squares problem,
as for the ramps of `longitudinal`; the bend, which the raw positions show sharply, pins the
ramp's end, and the standing before it its start.
"""

from __future__ import annotations

import numpy as np

from .events import Event
from .longitudinal import ramp_integral
from .motion import Array, Motion
from .thresholds import Thresholds

#: How far (s) before the fitted start and after the bend the raw positions are fitted.
_BEFORE = 2.0
_AFTER = 2.5
#: How far (s) about the first fit's start and end the candidates are searched.
_REACH = 0.6
#: As in `longitudinal`: a start whose squared error is within this many times the noise's
#: variance of the best fits as well (95 % bound of a likelihood-ratio test, one parameter).
_AS_WELL = 3.84


def fit_set_offs(
    events: list[Event], motion: Motion, thresholds: Thresholds, acceleration: float | None
) -> None:
    """Refit, in place, each speed change from standing that a Cross follows (on a noisy
    recording: one whose start is known only within a range), with the Cross starting at
    its end. `acceleration` is the actor kind's limit (m/s²; None: none).

    Only a bend of at least `thresholds.sharp_bend` between the set-off's line and the
    crossing's, as this fit finds them, is taken: the smoothing cuts such a corner by a
    decimetre, and the bend pins the ramp's end. A bike veering 0.24 rad across the road
    loses next to nothing to the smoothing, and its long ramp was fitted better along the path
    (UIS1's bikes replayed up to 0.5 m further off with this fit).
    """
    ordered = sorted(events, key=lambda e: e.start)
    for change, cross in zip(ordered, ordered[1:], strict=False):
        if cross.kind != "Cross" or change.kind not in ("Accelerate", "DriveDistance"):
            continue
        # A step (DriveDistance) from standing is tried too: a walker's short ramp (0 to
        # 1.1 m/s in 0.55 s) was fitted steeper than a walker can, a step, which replays the
        # set-off as a jump and was timed at the bend, half a second late, so that the
        # pedestrian seemed to wait for the ego rather than for the car.
        if (change.start_range if change.kind == "Accelerate" else motion.noisy) in (None, False):
            continue
        if change.from_speed is None or change.from_speed > thresholds.standing_speed:
            continue
        fitted = _fit(motion, change, cross, acceleration, thresholds.sharp_bend)
        if fitted is None:
            continue
        t1, t2, speed, starts = fitted
        if change.kind == "DriveDistance":
            change.kind, change.parameters = "Accelerate", {}
        change.start, change.end, change.finish = t1, t2, t2
        change.parameters["targetSpeed"] = round(speed, 2)
        change.parameters["rate"] = round(speed / (t2 - t1), 2)
        change.start_range = starts
        cross.start = cross.end = t2


def _fit(
    motion: Motion, change: Event, cross: Event, acceleration: float | None, sharp: float
) -> tuple[float, float, float, tuple[float, float]] | None:
    """The start, end (the bend) and speed of the set-off that fits the raw positions best,
    and the range of starts that fit as well; None where too few samples show it."""
    times = motion.times
    step = motion.step
    low = min(change.start_range[0] if change.start_range else change.start, change.start)
    keep = (times >= low - _BEFORE) & (times <= max(cross.start, change.end) + _AFTER)
    window, x, y = times[keep], motion.raw_x[keep], motion.raw_y[keep]
    if len(window) < 10:
        return None
    starts = np.arange(low - _REACH, change.start + _REACH + 1e-9, step / 4)
    ends = np.arange(
        min(change.end, cross.start) - _REACH, max(change.end, cross.start) + _REACH, step / 4
    )
    t1, t2 = (grid.ravel() for grid in np.meshgrid(starts, ends, indexing="ij"))
    usable = (t1 >= window[0]) & (t2 > t1 + step) & (t2 < window[-1] - 1.0)
    t1, t2 = t1[usable], t2[usable]
    if not len(t1):
        return None
    errors, speeds, lines = _errors(window, x, y, t1, t2)
    if acceleration is not None:
        errors = np.where(speeds / (t2 - t1) <= acceleration * (1 + 1e-6), errors, np.inf)
    best = int(np.argmin(errors))
    if not np.isfinite(errors[best]):
        return None
    (ax, ay), (bx, by) = lines[best]
    if abs(np.arctan2(ax * by - ay * bx, ax * bx + ay * by)) < sharp:
        return None
    variance = errors[best] / max(2 * len(window) - 8, 1)
    # The starts with the best end that fit as well: how well the noise lets the start be told.
    same_end = np.isclose(t2, t2[best]) & (errors <= errors[best] + _AS_WELL * variance)
    starts_kept = t1[same_end]
    return (
        float(t1[best]),
        float(t2[best]),
        float(speeds[best]),
        (float(starts_kept.min()), float(starts_kept.max())),
    )


def _errors(window: Array, x: Array, y: Array, t1: Array, t2: Array) -> tuple[Array, Array, Array]:
    """For each pair (t1, t2): the squared error of the best fit of both coordinates, the
    speed walked after the bend (m/s), and the velocities along the two lines ((x, y) before
    and after the bend).

    The design's columns are 1, the distance's ramp up to the bend (A), and the time walked
    after it (B); the same for x and y, each with its own coefficients (where it stood, its
    velocity along the first line and along the second).
    """
    ramp = ramp_integral(window[None, :], t1[:, None], t2[:, None])
    reached = (t2 - t1)[:, None] / 2  # the ramp's integral at its end (t1 is in the window)
    first = np.minimum(ramp, reached)
    second = ramp - first
    n = float(len(window))
    normal = np.empty((len(t1), 3, 3))
    normal[:, 0, 0] = n
    normal[:, 0, 1] = normal[:, 1, 0] = first.sum(axis=1)
    normal[:, 0, 2] = normal[:, 2, 0] = second.sum(axis=1)
    normal[:, 1, 1] = np.einsum("pn,pn->p", first, first)
    normal[:, 1, 2] = normal[:, 2, 1] = np.einsum("pn,pn->p", first, second)
    normal[:, 2, 2] = np.einsum("pn,pn->p", second, second)
    right = np.stack(
        [
            np.stack([np.full(len(t1), values.sum()), first @ values, second @ values], axis=1)
            for values in (x, y)
        ],
        axis=2,
    )
    solution = np.linalg.solve(normal + 1e-9 * np.eye(3), right)
    errors = np.zeros(len(t1))
    for k, values in enumerate((x, y)):
        coefficients = solution[:, :, k]
        fitted = coefficients[:, 0:1] + coefficients[:, 1:2] * first + coefficients[:, 2:3] * second
        errors += ((fitted - values) ** 2).sum(axis=1)
    speeds = np.hypot(solution[:, 2, 0], solution[:, 2, 1])
    return errors, speeds, solution[:, 1:3, :]

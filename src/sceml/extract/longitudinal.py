"""Speed changes: where a smoothed speed profile ramps, fitted as linear ramps between plateaus.

Accelerate, Decelerate and Stop each change the speed linearly at a rate to a target, so the
profile is piecewise linear. The ramps are found where the acceleration exceeds a threshold,
then each one's start and end are refined by least squares against the profile around it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.signal import savgol_filter

from .events import Event
from .motion import Array, Motion
from .thresholds import Thresholds


@dataclass(frozen=True)
class RateLimits:
    """The most an actor kind can accelerate and brake (m/s²; None: no limit), and the speed
    (m/s) below which it stands."""

    acceleration: float | None
    deceleration: float | None
    standing: float


def speed_events(
    motion: Motion, thresholds: Thresholds, limits: RateLimits | None = None
) -> list[Event]:
    """The actor's speed changes as Accelerate, Decelerate and Stop events, in time order.

    With `limits`, a change of an actor already moving is fitted among the ramps its kind can
    drive (a constrained least-squares fit); one from standing may still fit as a jump, which
    `within_limits` makes a step.
    """
    window = max(5, int(round(thresholds.smoothing_window / motion.step)) | 1)
    acceleration = savgol_filter(
        motion.speed, min(window, len(motion.speed) // 2 * 2 - 1), 2, deriv=1, delta=motion.step
    )
    changing = np.abs(acceleration) > thresholds.accel_threshold
    spans = _runs(changing, gap=max(1, int(0.5 / motion.step)))
    # On a noisy recording the smoothed speed crosses the threshold here and there by chance,
    # and each such run cut the plateaus of its neighbours short: a real change near the start
    # was fitted over a second or two and missed. So the runs are fitted again, bounded only
    # by those that came out as changes, until that set no longer changes (a clean recording
    # has no such runs and is fitted once).
    kept = list(range(len(spans)))
    fits: dict[tuple[int, ...], _Fit | None] = {}  # a run's fit depends only on its bounds
    for _ in range(_REFITS):
        found = _fit_spans(motion, thresholds, limits, spans, kept, fits)
        now = sorted(found)
        if now == kept:
            break
        kept = now
    return [found[i] for i in sorted(found)]


#: How many times at most the runs are fitted again with the bounds of those that held.
_REFITS = 4


def _fit_spans(
    motion: Motion,
    thresholds: Thresholds,
    limits: RateLimits | None,
    spans: list[tuple[int, int]],
    bounding: list[int],
    fits: dict[tuple[int, ...], _Fit | None],
) -> dict[int, Event]:
    """Each run of `spans` fitted as a speed change, between its neighbours among `bounding`
    (indices into spans); the runs that are changes, by index. `fits` keeps each fit by
    what it depends on (the run and the bounds of its plateaus), so a refit whose bounds did
    not change costs nothing."""
    step = motion.step
    last = len(motion.times) - 1
    events: dict[int, Event] = {}
    # The plateaus either side weigh in up to this many samples: enough to pin v0 and v1.
    margin = int(6.0 / step)
    edge = len(motion.times) - max(1, int(thresholds.smoothing_window / step))
    half = max(5, int(round(thresholds.smoothing_window / step)) | 1) // 2
    for i, (a, b) in enumerate(spans):
        if a >= edge:
            continue  # a change that shows only in the smoothing's last window: its edge
        b = min(b, edge)
        previous = max((spans[j][1] for j in bounding if j < i), default=0)
        following = min((spans[j][0] for j in bounding if j > i), default=last)
        before, after = max(previous, a - margin), min(following, b + margin)
        # An actor that stood before the change (no motion shows in the plateau before it,
        # short of the half window by which the chord shows a start early) starts from 0:
        # not a parameter (noise made a slow creep of it, and the ramp late).
        standing = not motion.moving[before : max(before + 1, a - half)].any()
        key = (a, b, before, after, int(standing))
        if key not in fits:
            fits[key] = _fit_ramp(
                motion.times,
                motion.along,
                before,
                a,
                b,
                after,
                step,
                # Only a ramp of an actor already moving is taken back to the start: a
                # standing actor's start is an event of its own, whose time a condition may
                # explain.
                thresholds.smoothing_window if motion.moving[0] else 0.0,
                limits,
                standing=standing,
            )
        fitted = fits[key]
        at_start = motion.noisy and bool(motion.moving[0]) and a <= half and before == 0
        if at_start and (
            fitted is None or abs(fitted[3] - fitted[2]) < thresholds.min_speed_change
        ):
            # A change under way at the start that the free fit cannot tell from noise, or
            # whose length it leaves open: tried at the start rate (`_start_change`).
            fitted = _start_change(motion.times, motion.along, after, thresholds)
        if fitted is None:
            continue
        t1, t2, v0, v1, starts = fitted
        if t1 < thresholds.min_wait:
            t1 = float(motion.times[0])  # a change from the first moments: from the start
            starts = None
        if abs(v1 - v0) < thresholds.min_speed_change:
            continue
        if v1 < v0 and t1 <= motion.times[0] and not motion.moving[0]:
            continue  # slowing down from the start of an actor that stands: the filter's edge
        event = _event(motion.name, t1, t2, v0, v1, thresholds)
        event.start_range = starts
        events[i] = event
    return events


def _event(actor: str, t1: float, t2: float, v0: float, v1: float, thresholds: Thresholds) -> Event:
    rate = round(abs(v1 - v0) / max(t2 - t1, 1e-3), 2)
    if v1 < thresholds.standing_speed:
        return Event("Stop", actor, t1, t2, {"rate": rate}, finish=t2, from_speed=v0)
    kind = "Accelerate" if v1 > v0 else "Decelerate"
    parameters: dict[str, object] = {"targetSpeed": round(v1, 2), "rate": rate}
    return Event(kind, actor, t1, t2, parameters, finish=t2, from_speed=v0)


def _runs(mask: NDArray[np.bool_], gap: int) -> list[tuple[int, int]]:
    """Index spans [a, b] where mask holds, joining runs apart by at most `gap` samples.

    Runs are joined whatever their sign: a short dip between two changes (a corner cut by the
    smoothing) is one change, which the fit then measures.
    """
    spans: list[tuple[int, int]] = []
    k, n = 0, len(mask)
    while k < n:
        if not mask[k]:
            k += 1
            continue
        a = k
        while k < n and mask[k]:
            k += 1
        b = k - 1
        if spans and a - spans[-1][1] <= gap:
            spans[-1] = (spans[-1][0], b)
        else:
            spans.append((a, b))
    return spans


#: The spacing (s) of the first, coarse search for a ramp's start and end.
_COARSE_GRID = 0.1
#: A fitted speed change: start, end, speed before and after, and the range of its start.
_Fit = tuple[float, float, float, float, tuple[float, float] | None]


def _fit_ramp(
    times: Array,
    along: Array,
    before: int,
    a: int,
    b: int,
    after: int,
    step: float,
    anchor: float,
    limits: RateLimits | None = None,
    *,
    standing: bool = False,
) -> _Fit | None:
    """Least-squares fit of the distance driven over [before, after]: speed v0 until t1, a
    linear change to v1 at t2, then v1; and on a noisy recording the range of starts that
    fit as well (`_start_range`), else None.

    For fixed t1 and t2 the distance is linear in (s0, v0, v1), so each candidate pair is one
    small linear least-squares problem (solved together, by their normal equations); the pairs
    are searched at a quarter of the sample step around the run [a, b] where the smoothed speed
    was seen to change. Fitting the distance rather than the smoothed speed keeps the smoothing
    from stretching short ramps.
    """
    window = times[before : after + 1]
    values = along[before : after + 1]
    if len(window) < 4:
        return None
    reach = (max(b - a, 4) + 6) * step
    # A fast recording is searched on a grid of about a tenth of a second first, then at its
    # own step about the best pair: the pairs, and the cost, grow with the square of the rate.
    grid = step * max(1, round(_COARSE_GRID / step))
    starts = np.arange(max(times[before], times[a] - reach), min(times[a] + reach, times[b]), grid)
    ends = np.arange(max(times[a], times[b] - reach), min(times[b] + reach, times[after]), grid)
    coarse = _best_ramp(window, values, starts, ends, limits, standing=standing)
    if coarse is None:
        return None
    if grid > step:
        near = np.arange(-grid, grid + 1e-9, step)
        coarse = (
            _best_ramp(
                window, values, coarse[0] + near, coarse[1] + near, limits, standing=standing
            )
            or coarse
        )
    fine = np.arange(-step, step + 1e-9, step / 4)
    refined = _best_ramp(
        window, values, coarse[0] + fine, coarse[1] + fine, limits, standing=standing
    )
    t1, t2, v0, v1, error = refined or coarse
    variance = error / max(len(window) - 5, 1)
    if _steady_error(window, values) - error <= _SIGNIFICANT * variance:
        return None  # a steady speed explains the distance as well, within the noise
    if before == 0 and t1 - times[0] <= anchor:
        # At the start of a noisy recording a ramp that began with it is easily fitted late,
        # with a short plateau that follows the noise. It is taken from the start when that
        # fits as well as noise allows: within `_ANCHORED` times the noise's variance, which
        # the free fit's residual estimates (a likelihood-ratio test for one parameter more).
        # Its end is searched over the whole run, not about the free fit's end: anchored,
        # the ramp is longer (UIS2's ego, 3 to 6.8 m/s from the start, was fitted from
        # 0.65 s; its end, held within a step of that fit's 1.8 s, never reached 1.95 s,
        # and the start came out late, a wait the scenario did not have).
        anchored = _best_ramp(
            window,
            values,
            np.array([times[0]]),
            np.arange(times[0] + grid, min(times[b] + reach, times[after]), grid),
            limits,
        )
        if anchored is not None:
            anchored = (
                _best_ramp(window, values, np.array([times[0]]), anchored[1] + fine, limits)
                or anchored
            )
        if anchored is not None and anchored[4] - error <= _ANCHORED * variance:
            t1, t2, v0, v1, error = anchored
            if limits is not None and v0 <= limits.standing and not standing:
                # It set off with the recording: from standing, which the replay starts
                # from (a free v0 of 0.3 m/s, replayed from 0 at the rate fitted with it,
                # left UIS1's bike 1.1 m behind).
                still = _best_ramp(
                    window, values, np.array([times[0]]), t2 + fine, limits, standing=True
                )
                if still is not None:
                    t1, t2, v0, v1, error = still
            return t1, t2, max(v0, 0.0), max(v1, 0.0), None
    starts_range = _start_range(window, values, t1, t2, step, error, variance, standing)
    return t1, t2, max(v0, 0.0), max(v1, 0.0), starts_range


#: How many times the noise's variance a change under way at the start must explain beyond a
#: steady speed to count, by default (`Thresholds.start_significance`): a likelihood-ratio
#: test for its one parameter more (the change; its length follows from the start rate).


def _start_change(times: Array, along: Array, after: int, thresholds: Thresholds) -> _Fit | None:
    """A speed change under way when a noisy recording starts, fitted at the `rate` given.

    Five samples at 10 Hz and the filter's edge leave a short change at the start (1.3 m/s
    in 0.65 s) within the noise of a steady speed for the free fit, which needs 20 times the
    noise's variance; and its length is open: a ramp from the start by dv over T seconds
    leaves the actor dv T / 2 behind a steady speed, and only that product shows above the
    noise (a gentle 0.4 m/s over 1.5 s and 1.3 m/s over 0.65 s fitted alike). With the rate
    given, dv is the one parameter more than a steady speed: for each dv on a grid the
    distance is s0 + v1 t + dv (r(t) - t), linear in (s0, v1), r the ramp's integral.
    Returns (t1, t2, v0, v1, None), or None when the change explains less than
    `start_significance` times the noise's variance, or is smaller than `min_speed_change`.
    """
    rate = thresholds.start_rate
    window, values = times[: after + 1], along[: after + 1]
    if len(window) < 8:
        return None
    base = window - window[0]
    lasting = float(base[-1]) / 2  # the steady speed after it must show too
    changes = np.arange(-rate * lasting, rate * lasting + 1e-9, 0.05)
    changes = changes[np.abs(changes) >= 0.05]
    if not len(changes):
        return None
    lengths = np.abs(changes) / rate
    ramp = ramp_integral(window[None, :], window[0], window[0] + lengths[:, None])
    shifted = values[None, :] - changes[:, None] * (ramp - base[None, :])
    design = np.column_stack([np.ones_like(base), base])
    solution = shifted @ np.linalg.pinv(design).T
    errors = ((solution @ design.T - shifted) ** 2).sum(axis=1)
    best = int(np.argmin(errors))
    variance = float(errors[best]) / (len(window) - 3)
    gain = _steady_error(window, values) - float(errors[best])
    if gain <= thresholds.start_significance * variance:
        return None
    change, v1 = float(changes[best]), float(solution[best, 1])
    if abs(change) < thresholds.min_speed_change:
        return None
    t0 = float(window[0])
    return t0, t0 + float(lengths[best]), max(v1 - change, 0.0), max(v1, 0.0), None


#: A ramp from the recording's start is preferred to a later start whose squared error is
#: smaller by less than this many times the noise's variance (for noise alone about 1 in 400,
#: the chi-squared tail for one parameter):
#: a change fitted late needs a wait that nothing explains, a timed one, which a change under
#: way from the start does not (at 6, UIS2's ego was fitted 0.65 s late in 1 of 100 samples).
_ANCHORED = 9.0


#: A ramp whose squared error exceeds the best one's by less than this many times the noise's
#: variance fits as well (the 95 % bound of a likelihood-ratio test for one parameter: the
#: start, with the midpoint held).
_AS_WELL = 3.84
#: Below this spread (m²) of the residuals per sample a recording is clean: its starts are exact.
_CLEAN_VARIANCE = 1e-4


def _start_range(
    window: Array,
    values: Array,
    t1: float,
    t2: float,
    step: float,
    error: float,
    variance: float,
    standing: bool = False,
) -> tuple[float, float] | None:
    """The earliest and latest start of ramps with the midpoint of (t1, t2) that fit as well
    as the best (squared `error`) within the noise's `variance`: how well the noise lets the
    start be told. None on a clean recording, whose start is as fitted."""
    if variance < _CLEAN_VARIANCE:
        return None
    bound = error + _AS_WELL * variance
    middle = (t1 + t2) / 2
    starts = np.arange(max(window[0], middle - 4.0), middle - step / 4, step / 4)
    ends = 2 * middle - starts
    inside = ends <= window[-1]
    starts, ends = starts[inside], ends[inside]
    if not len(starts):
        return None
    _, errors = _ramp_fits(window, values, starts, ends, standing=standing)
    kept = starts[errors <= bound]
    if not len(kept):
        return None
    return min(float(kept[0]), t1), max(float(kept[-1]), t1)


#: How many times the noise's variance a ramp must explain beyond a steady speed to count
#: (a likelihood-ratio test for its three parameters more, at a small chance of noise passing).
_SIGNIFICANT = 20.0


def _steady_error(window: Array, values: Array) -> float:
    """The squared error of the best steady speed (a straight line) through the distances."""
    design = np.column_stack([np.ones_like(window), window - window[0]])
    solution, *_ = np.linalg.lstsq(design, values, rcond=None)
    return float(((design @ solution - values) ** 2).sum())


def _best_ramp(
    window: Array,
    values: Array,
    starts: Array,
    ends: Array,
    limits: RateLimits | None = None,
    *,
    standing: bool = False,
) -> tuple[float, float, float, float, float] | None:
    """The (t1, t2, v0, v1, squared error) of the candidate pairs that fits `values` best;
    with `limits`, of those a moving actor can drive (when there are any); `standing`: with
    v0 = 0 (its column is zero, so the regularised solution gives it 0)."""
    t1, t2 = (grid.ravel() for grid in np.meshgrid(starts, ends, indexing="ij"))
    keep = (t2 > t1 + 1e-9) & (t1 >= window[0]) & (t2 <= window[-1])
    t1, t2 = t1[keep], t2[keep]
    if not len(t1):
        return None
    solution, errors = _ramp_fits(window, values, t1, t2, standing=standing)
    if limits is not None:
        v0, v1 = solution[:, 1], solution[:, 2]
        rate = np.abs(v1 - v0) / (t2 - t1)
        allowed = np.where(v1 > v0, limits.acceleration or np.inf, limits.deceleration or np.inf)
        possible = (v0 <= limits.standing) | (rate <= allowed * (1 + 1e-6))
        if possible.any():
            errors = np.where(possible, errors, np.inf)
    best = int(np.argmin(errors))
    return (
        float(t1[best]),
        float(t2[best]),
        float(solution[best, 1]),
        float(solution[best, 2]),
        float(errors[best]),
    )


def _ramp_fits(
    window: Array, values: Array, t1: Array, t2: Array, *, standing: bool = False
) -> tuple[Array, Array]:
    """For each candidate pair (t1[p], t2[p]): the least-squares (s0, v0, v1) of the distance
    driven, and its squared error.

    The design has the columns 1, the time driven before the ramp (zero when `standing`) and
    the ramp's integral r; its normal equations need only the sums of r, r², r·t and r·s per
    pair (matrix-vector products), not the pairs' whole design matrices, which cost far more
    to build and multiply (most of an extraction's time before).
    """
    ramp = ramp_integral(window[None, :], t1[:, None], t2[:, None])
    base = window - window[0]
    n = float(len(window))
    sum_r = ramp.sum(axis=1)
    sum_rr = np.einsum("pn,pn->p", ramp, ramp)
    sum_rb = ramp @ base
    sum_rv = ramp @ values
    sum_b, sum_bb = float(base.sum()), float(base @ base)
    sum_v, sum_bv = float(values.sum()), float(base @ values)
    normal = np.zeros((len(t1), 3, 3))
    right = np.zeros((len(t1), 3))
    normal[:, 0, 0] = n
    normal[:, 0, 2] = normal[:, 2, 0] = sum_r
    normal[:, 2, 2] = sum_rr
    right[:, 0] = sum_v
    right[:, 2] = sum_rv
    if not standing:
        # The column before the ramp is base - r.
        normal[:, 0, 1] = normal[:, 1, 0] = sum_b - sum_r
        normal[:, 1, 1] = sum_bb - 2 * sum_rb + sum_rr
        normal[:, 1, 2] = normal[:, 2, 1] = sum_rb - sum_rr
        right[:, 1] = sum_bv - sum_rv
    solution = np.asarray(
        np.linalg.solve(normal + 1e-9 * np.eye(3), right[..., None])[..., 0], dtype=np.float64
    )
    s0, v0, v1 = solution[:, 0:1], solution[:, 1:2], solution[:, 2:3]
    fitted = s0 + v1 * ramp if standing else s0 + v0 * base + (v1 - v0) * ramp
    errors: Array = ((fitted - values) ** 2).sum(axis=1)
    return solution, errors


def ramp_integral(t: Array, t1: Array, t2: Array) -> Array:
    """The integral from t[..., 0] to each t of w(u) = clip((u - t1) / (t2 - t1), 0, 1)."""

    def primitive(u: Array) -> Array:
        inside = np.clip(u, t1, t2) - t1
        return inside**2 / (2 * (t2 - t1)) + np.maximum(u - t2, 0.0)

    return primitive(t) - primitive(t[..., :1])


def within_limits(
    events: list[Event],
    kind: str,
    acceleration: float | None,
    deceleration: float | None,
    standing: float,
) -> list[str]:
    """Make speed changes steeper than the actor kind's plausibility limits (SCEML-L002) into
    what they were; returns a note for each.

    A speed that jumps (a player's step change: the preview's DriveDistance, an esmini step
    SpeedAction) is no motion at a rate. A jump from standing to a speed is extracted as a
    step, a DriveDistance at the jump's midpoint (its distance is set by `drive_distances`),
    which replays it as recorded. Other jumps become a ramp at the limit with the same
    midpoint, so the actor covers the same distance by the ramp's end; in between it is off by
    up to (speed change)² / (8 × limit). A DriveDistance to standing never finishes; one of an
    actor that moved before is warned about for the carla profile (scenario_runner counts its
    distance from the act's start, SCEML-Y003); and under
    noise a steep ramp of a moving actor is often fitted as a near-jump, which a step would
    then make worse.
    """
    notes = []
    for event in events:
        if not event.longitudinal or event.from_speed is None or "rate" not in event.parameters:
            continue
        rate = float(str(event.parameters["rate"]))
        speeding_up = event.kind == "Accelerate"
        limit = acceleration if speeding_up else deceleration
        middle = (event.start + event.end) / 2
        target = _target(event)
        if limit is None or rate <= limit:
            if limit is not None and event.start_range is not None:
                # Only starts that keep the rate within the limit.
                latest = middle - abs(target - event.from_speed) / (2 * limit)
                low, high = event.start_range
                event.start_range = (low, min(high, max(latest, event.start)))
            continue
        event.start_range = None
        if target > standing and event.from_speed <= standing:
            event.kind = "DriveDistance"
            event.start = event.end = event.finish = middle
            event.parameters = {"speed": round(target, 2)}
            notes.append(
                f"{event.actor}: the speed jumped from standing to {target:g} m/s at "
                f"{middle:.2f} s ({rate:g} m/s², above the {kind} limit of {limit:g} m/s²); "
                "it is extracted as a step of the speed, a DriveDistance"
            )
            continue
        half = abs(target - event.from_speed) / limit / 2
        event.start, event.end = max(middle - half, 0.0), middle + half
        event.finish = event.end
        event.parameters["rate"] = float(limit)
        event.limited = True
        notes.append(
            f"{event.actor}: the {event.kind} at {middle:.2f} s ran at {rate:g} m/s², above the "
            f"{kind} limit of {limit:g} m/s²; it is extracted at the limit"
        )
    return notes


def drive_distances(events: list[Event], motion: Motion) -> None:
    """Fit each step of the speed (DriveDistance) over all it shows, and give it its distance:
    what the actor drove at that speed until its next maneuver started, or the recording
    ended. The node then finishes when the actor next did something, as on the recording
    (which shows no other end of a step), and that maneuver follows it."""
    ordered = sorted(events, key=lambda e: e.start)
    end = float(motion.times[-1])
    for i, event in enumerate(ordered):
        if event.kind != "DriveDistance":
            continue
        later = [e for e in ordered[i + 1 :] if e.start > event.start]
        until = later[0].start if later else end
        # The speed holds until the next speed change (a turn or crossing keeps it).
        changes = [e.start for e in later if e.longitudinal]
        _fit_step(event, motion, changes[0] if changes else end)
        speed = float(str(event.parameters["speed"]))
        distance = round(max(speed * (until - event.start), 0.1), 1)
        event.parameters["distance"] = distance
        event.finish = event.end = event.start + distance / speed


def _fit_step(event: Event, motion: Motion, until: float) -> None:
    """Refit a step from standing by least squares on the distance driven: s0 until the jump
    at tj, then s0 + v (t - tj), over the standing before it and all the driving up to
    `until`. The ramp fit looked at a few seconds either side; a step's speed is pinned far
    better by everything after it, and a timing error of a tenth of a second would put the
    actor a metre off for good (at 10 m/s)."""
    step = motion.step
    keep = (motion.times >= event.start - 3.0) & (motion.times <= until)
    times, values = motion.times[keep], motion.along[keep]
    if len(times) < 4:
        return
    jumps = event.start + np.arange(-2 * step, 2 * step + 1e-9, step / 10)
    best: tuple[float, float, float] | None = None
    for jump in jumps:
        design = np.column_stack([np.ones_like(times), np.maximum(times - jump, 0.0)])
        solution, *_ = np.linalg.lstsq(design, values, rcond=None)
        error = float(((design @ solution - values) ** 2).sum())
        if best is None or error < best[0]:
            best = (error, float(jump), float(solution[1]))
    assert best is not None
    _, jump, speed = best
    if speed > 0:
        if motion.noisy:
            jump = _jump_in_plane(motion, jump)
        event.start = event.end = event.finish = jump
        event.parameters["speed"] = round(speed, 2)


#: Over this long (s) after a step from standing its time is fitted in the plane.
_JUMP_AFTER = 2.0


def _jump_in_plane(motion: Motion, jump: float) -> float:
    """The time of a step from standing, fitted to the raw positions: standing at P until tj,
    then a steady velocity, over a few seconds either side of the first estimate `jump`.

    The distance driven of a noisy recording is worked out along the smoothed path, which
    the filter moves before a sudden start and which loses what it moved while the actor
    counted as standing: a car's step came out 0.04 s early (0.4 m at 10 m/s), and the car,
    replayed, a metre off once what it waits for ran a step early too. The raw positions
    have no such bias; the speed is still the one fitted over all the driving after.
    """
    step = motion.step
    keep = (motion.times >= jump - 3.0) & (motion.times <= jump + _JUMP_AFTER)
    times, x, y = motion.times[keep], motion.raw_x[keep], motion.raw_y[keep]
    if len(times) < 8:
        return jump
    jumps = jump + np.arange(-2 * step, 2 * step + 1e-9, step / 10)
    best_error, best_jump = np.inf, jump
    for candidate in jumps:
        design = np.column_stack([np.ones_like(times), np.maximum(times - candidate, 0.0)])
        _, residual, *_ = np.linalg.lstsq(design, np.column_stack([x, y]), rcond=None)
        error = float(residual.sum()) if len(residual) else np.inf
        if error < best_error:
            best_error, best_jump = error, float(candidate)
    return best_jump


def _target(event: Event) -> float:
    return float(str(event.parameters.get("targetSpeed", 0.0)))


def end_by_crossings(events: list[Event]) -> None:
    """On a noisy recording, let a speed change that a crossing follows end by its bend.

    A short change of a slow actor (a pedestrian setting off: 1.5 m/s in under a second)
    pins its midpoint, but the noise leaves its length open (`Event.start_range`), and the
    fit leans to a longer, gentler ramp than was walked (over 40 noisy UIS2 samples its
    start came out 0.15 s early and its end 0.18 s late on average). The replay starts the crossing only once the change has finished, so the walker turned
    late, a metre off. The walker did turn where the bend was seen, so the change had
    finished by then: only starts whose ramp (same midpoint and target) ends by the bend
    are kept, and a fitted start before them is moved to the first.
    """
    ordered = sorted(events, key=lambda e: e.start)
    for event, following in zip(ordered, ordered[1:], strict=False):
        if following.kind != "Cross" or event.start_range is None:
            continue
        if not event.longitudinal or event.kind == "DriveDistance":
            continue
        middle = (event.start + event.end) / 2
        earliest = 2 * middle - following.start
        low, high = event.start_range
        if following.start <= middle or earliest > high or earliest <= low:
            continue
        event.start_range = (earliest, high)
        if event.start < earliest:
            event.retime(earliest)


def crossings_after_set_offs(events: list[Event], standing: float, window: float) -> None:
    """Put a Cross that was seen while its actor was still setting off from standing (or up
    to a smoothing `window` before) at the end of that set-off; sorts `events` by start.

    SceML's crossing is a set-off, then a Cross when it has finished (the library's
    CrossingManeuver; the preview and the export play it so). The Cross's start is where
    the heading bent, judged from the chord across the smoothing window, and a slow set-off's
    noisy heading bends early: a bike's Cross came out at 1.0 s, in the middle of its set-off
    (0.6 to 2.9 s), and a walker's 0.17 s before its step of the speed. A Cross that starts
    while another of the actor's maneuvers still runs gets a branch of its own, so the replay
    crossed first and set off after, the other way round. An actor that stands has no heading
    to bend: its crossing began once it was under way.
    """
    for cross in events:
        if cross.kind != "Cross":
            continue
        for change in events:
            if not change.longitudinal or change.from_speed is None:
                continue
            if change.from_speed > standing or not change.start - window < cross.start:
                continue
            if change.kind == "DriveDistance" and cross.start < change.start:
                # A step: under way at once. It drives the least distance a node says
                # (0.1 m, as `drive_distances`), then the Cross follows.
                speed = float(str(change.parameters["speed"]))
                change.parameters["distance"] = 0.1
                change.end = change.finish = change.start + 0.1 / speed
                cross.start = cross.end = change.end
            elif change.kind != "DriveDistance" and cross.start < change.end:
                cross.start = cross.end = change.end
    events.sort(key=lambda e: e.start)


#: Over at most this long (s) from the recording's start the start position is fitted.
_START_SPAN = 6.0


def start_shift(motion: Motion, events: list[Event], initial_speed: float) -> float:
    """How far (m) along its heading a moving actor was at the recording's start from the
    smoothed first point, on a noisy recording (else 0).

    The filter extrapolates a cubic there, off by more than the noise itself; a start 0.25 m
    ahead put UIS2's ego as far ahead all the way, and the car that waits for it set off a
    step early (a metre at 10 m/s). The speed profile up to the actor's next maneuver is known
    by then (its initial speed, and a speed change that starts with the recording), so the
    distance driven is fitted with one unknown, its offset at the start: the mean of what is
    left, which noise moves by its own deviation over the square root of seconds of samples.
    """
    if not motion.noisy or not motion.moving[0]:
        return 0.0
    t0 = float(motion.times[0])
    first = next(
        (e for e in events if e.longitudinal and e.start <= t0 + 1e-9 and e.from_speed is not None),
        None,
    )
    if first is not None and first.kind == "DriveDistance":
        return 0.0
    until = min([t0 + _START_SPAN] + [e.start for e in events if e is not first and e.start > t0])
    keep = motion.times <= until + 1e-9
    if keep.sum() < 5:
        return 0.0
    times = motion.times[keep]
    if first is None:
        driven = initial_speed * (times - t0)
    else:
        v0, v1 = float(first.from_speed or 0.0), _target(first)
        ramp = ramp_integral(
            times, np.array(first.start), np.array(max(first.end, first.start + 1e-3))
        )
        driven = v0 * (times - t0) + (v1 - v0) * ramp
    return float(np.mean(motion.along[keep] - driven))

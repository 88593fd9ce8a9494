"""A track made smooth: uniform samples, smoothed positions, speed, heading and arc length."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.signal import savgol_coeffs, savgol_filter

from ..errors import LoadError
from .recording import Track
from .thresholds import Thresholds

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Motion:
    """One actor's motion on a uniform clock: smoothed x, y (m), speed (m/s), heading (rad,
    unwrapped; held while standing) and arc length driven (m); `heading_error` is the standard
    deviation (rad) that the recording's noise gives the heading (0 on a clean recording);
    `raw_x` and `raw_y` are the recorded positions on the same clock, unsmoothed; `noise` the
    standard deviation (m) of their noise, estimated from the filter's residuals."""

    name: str
    times: Array
    x: Array
    y: Array
    speed: Array
    moving: NDArray[np.bool_]
    heading: Array
    turn_rate: Array
    arc: Array
    along: Array
    heading_error: Array
    raw_x: Array
    raw_y: Array
    noise: float

    @property
    def noisy(self) -> bool:
        """Whether the recording has position noise (a player's log has none)."""
        return self.noise >= _CLEAN

    @property
    def step(self) -> float:
        """The time between samples (s)."""
        return float(self.times[1] - self.times[0])

    def index(self, t: float) -> int:
        """The sample at or just after time t (clamped to the track)."""
        return int(np.clip(np.searchsorted(self.times, t - 1e-9), 0, len(self.times) - 1))

    def at(self, values: Array, t: float) -> float:
        """A series interpolated at time t."""
        return float(np.interp(t, self.times, values))

    def position(self, t: float) -> tuple[float, float]:
        """The smoothed (x, y) at time t."""
        return self.at(self.x, t), self.at(self.y, t)


def sample_step(track: Track) -> float:
    """The recording's own step: the median time between samples."""
    return float(np.median(np.diff(track.times)))


def smooth(track: Track, thresholds: Thresholds, step: float | None = None) -> Motion:
    """Resample a track to a uniform clock and smooth it (Savitzky-Golay, quadratic).

    The speed is the smoothed derivative of the positions; a speed column in the recording is
    not used, so every format (and noisy positions) is treated alike.
    """
    if len(track.times) < 5:
        raise LoadError(f"{track.name!r} has {len(track.times)} samples; at least 5 are needed")
    step = step or sample_step(track)
    times = np.arange(track.times[0], track.times[-1] + step / 2, step)
    x = np.interp(times, track.times, track.x)
    y = np.interp(times, track.times, track.y)
    window = max(5, int(round(thresholds.smoothing_window / step)) | 1)
    window = min(window, len(times) - (1 - len(times) % 2))
    # Cubic rather than quadratic: a quadratic cuts the corners of tight turns, which shows as
    # a false dip of the speed in every turn.
    xs = savgol_filter(x, window, 3, mode="interp")
    ys = savgol_filter(y, window, 3, mode="interp")
    vx = savgol_filter(x, window, 3, deriv=1, delta=step, mode="interp")
    vy = savgol_filter(y, window, 3, deriv=1, delta=step, mode="interp")
    speed = np.hypot(vx, vy)
    moving = _moving(xs, ys, window // 2, step, thresholds.standing_speed)
    # The filter's first and last half windows are extrapolations of a cubic: on noisy data
    # their speed is several times noisier than inside (a standing bike "moves" at 3 m/s).
    # Where a straight line through the raw samples of the edge window shows no motion that
    # noise cannot explain, the actor stands there.
    half = window // 2
    for edge in (slice(0, window), slice(len(times) - window, len(times))):
        if _stands(times[edge], x[edge], y[edge], thresholds.standing_speed):
            ends = slice(0, half) if edge.start == 0 else slice(len(times) - half, len(times))
            speed[ends] = 0.0
            moving[ends] = False
    heading = _heading(track, times, xs, ys, moving, window // 2)
    turn_rate = savgol_filter(heading, window, 2, deriv=1, delta=step, mode="interp")
    lengths = np.hypot(np.diff(xs), np.diff(ys))
    # Standing still, the smoothed noise would add up to a distance never driven.
    lengths[~(moving[1:] | moving[:-1])] = 0.0
    arc = np.concatenate([[0.0], np.cumsum(lengths)])
    noise = _noise(x, y, xs, ys, window)
    along = _along(x, y, xs, ys, arc, heading, thresholds.standing_speed, speed, noise, window // 2)
    error = _heading_error(xs, ys, window, noise)
    xs, ys = _hold_standing_start(x, y, xs, ys, moving, speed, half)
    return Motion(
        track.name, times, xs, ys, speed, moving, heading, turn_rate, arc, along, error, x, y, noise
    )


def _hold_standing_start(
    x: Array, y: Array, xs: Array, ys: Array, moving: NDArray[np.bool_], speed: Array, half: int
) -> tuple[Array, Array]:
    """Where an actor stands from the start, put it at the mean of its raw samples there.

    The filter's value at the first sample is an extrapolated cubic, off by about the noise
    itself (0.15 m with 0.1 m of noise), and an actor's start position is taken from it; the
    mean of the samples it stood at is off by the noise over the square root of their
    number. Only samples a half window before the chord first shows motion are used: the
    chord spans the window, so the motion began at most that much earlier. (The noise, the
    heading and the distance driven are worked out from the filter's values before this.)
    """
    if moving[0] or speed[0] > 0.0:
        return xs, ys
    still = int(np.argmax(moving)) - half if moving.any() else len(x)
    if still < 3:
        return xs, ys
    xs, ys = xs.copy(), ys.copy()
    xs[:still] = float(np.mean(x[:still]))
    ys[:still] = float(np.mean(y[:still]))
    return xs, ys


def _noise(x: Array, y: Array, xs: Array, ys: Array, window: int) -> float:
    """The standard deviation (m) of the position noise, from the residuals of the filter.

    They keep 1 - h of the noise's variance, h being the filter's weight on a sample itself.
    The spread is taken robustly (1.4826 times the median absolute residual, which is the
    standard deviation for Gaussian noise): a clean recording of a sudden start has large
    residuals only about the start, where the cubic rings, and stays clean.
    """
    half = window // 2
    weight = float(savgol_coeffs(window, 3)[half])
    inside = slice(half, len(x) - half) if len(x) > 2 * half else slice(None)
    residual = np.concatenate([(x - xs)[inside], (y - ys)[inside]])
    return float(1.4826 * np.median(np.abs(residual)) / math.sqrt(1 - weight))


def _heading_error(xs: Array, ys: Array, window: int, noise: float) -> Array:
    """The standard deviation (rad) that position noise gives the heading, the direction of
    the chord across the window. The chord's two ends lie a window apart, each keeping h of
    the noise's variance (the filter's weight on a sample itself: for a least-squares filter
    the sum of its squared weights), so its error across is noise * sqrt(2 h), and the
    heading's that over the chord's length.
    """
    half = window // 2
    weight = float(savgol_coeffs(window, 3)[half])
    chord = np.hypot(
        _shifted(xs, half) - _shifted(xs, -half), _shifted(ys, half) - _shifted(ys, -half)
    )
    return noise * math.sqrt(2 * weight) / np.maximum(chord, 1e-9)


#: How many standard errors a fitted speed must exceed to show motion rather than noise.
_SIGNIFICANT_SPEED = 3.0


def _stands(times: Array, x: Array, y: Array, standing: float) -> bool:
    """Whether an actor stands over these raw samples: the slope of a straight line fitted to
    x and to y (least squares) is below the standing speed, or within what the noise about
    the line (estimated from the residuals) makes of a standing actor's slope."""
    if len(times) < 4:
        return False
    t = times - times.mean()
    spread = float((t**2).sum())
    speeds, errors = [], []
    for values in (x, y):
        slope = float((t * (values - values.mean())).sum() / spread)
        residual = values - values.mean() - slope * t
        errors.append(float(np.sqrt((residual**2).sum() / (len(t) - 2) / spread)))
        speeds.append(slope)
    return bool(math.hypot(*speeds) < max(standing, _SIGNIFICANT_SPEED * math.hypot(*errors)))


def _shifted(values: Array, by: int) -> Array:
    """values[k + by], held at the ends."""
    if by >= 0:
        return np.concatenate([values[by:], np.repeat(values[-1], by)])
    return np.concatenate([np.repeat(values[0], -by), values[:by]])


def _moving(x: Array, y: Array, half: int, step: float, standing: float) -> NDArray[np.bool_]:
    """Where the actor moves: the chord across the window is longer than standing would give.

    The smoothed derivative would do on clean data, but on noisy data a standing actor's
    derivative jitters past any small threshold; the chord averages over the whole window.
    """
    chord = np.hypot(_shifted(x, half) - _shifted(x, -half), _shifted(y, half) - _shifted(y, -half))
    return np.asarray(chord > standing * 2 * half * step)


def _heading(
    track: Track, times: Array, x: Array, y: Array, moving: NDArray[np.bool_], half: int
) -> Array:
    """The direction of motion where the actor moves; held over standing stretches.

    It is the direction of the chord across the smoothing window, not of the smoothed
    velocity: a cubic filter rings around a sudden start, and its velocity briefly points
    backwards. Before the first motion the recorded heading (if any) is used, else the first
    direction of motion.
    """
    raw = np.arctan2(_shifted(y, half) - _shifted(y, -half), _shifted(x, half) - _shifted(x, -half))
    if not moving.any():
        if track.heading is not None:
            return np.interp(times, track.times, track.heading)
        return np.zeros_like(times)
    first = int(np.argmax(moving))
    held = raw.copy()
    for k in range(len(times)):
        if not moving[k]:
            held[k] = held[k - 1] if k > first else raw[first]
    heading = np.unwrap(held)
    if track.heading is not None and first > 0:
        recorded = float(np.interp(times[0], track.times, track.heading))
        heading[:first] = recorded + np.round((heading[first] - recorded) / (2 * np.pi)) * 2 * np.pi
    return heading


#: Below this noise (m, `_noise`) a recording is clean.
_CLEAN = 0.02


def _along(
    x: Array,
    y: Array,
    xs: Array,
    ys: Array,
    arc: Array,
    heading: Array,
    standing: float,
    speed: Array,
    noise: float,
    half: int,
) -> Array:
    """Each raw sample's distance along the path.

    A clean recording (a player's log) gives it exactly as the summed lengths of its own steps,
    corners and all. A noisy one would add its noise to those lengths, so there each raw point
    is placed along the smoothed path instead: the smoothed arc plus its offset along the
    heading, which cuts tight corners by a few centimetres.
    """
    if noise < _CLEAN:
        lengths = np.hypot(np.diff(x), np.diff(y))
        lengths[(speed[1:] + speed[:-1]) / 2 <= standing / 10] = 0.0
        return np.concatenate([[0.0], np.cumsum(lengths)])
    along = arc + (x - xs) * np.cos(heading) + (y - ys) * np.sin(heading)
    # In the first half window the smoothed path is an extrapolated cubic, which wanders
    # sideways as well as along (a bike setting off "moved" at 2.9 m/s there), and its
    # length counted that: the distance of UIS1's bike at the start came out 0.5 m short, and
    # its set-off, fitted to it, from 1.2 m/s at 0.8 s rather than from standing at 0 s. Over
    # half a window from the start the path is as good as straight, so there each raw point
    # is placed along the heading from the first point inside instead. (Not at the end: an
    # actor may be turning there, as a bike onto its lane after crossing, and the straight
    # line lost length, a Decelerate that was not.)
    if 0 < half < len(x):
        along[:half] = (
            along[half]
            + (x[:half] - x[half]) * np.cos(heading[half])
            + (y[:half] - y[half]) * np.sin(heading[half])
        )
    return along

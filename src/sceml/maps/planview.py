"""A road's reference line: from s to a point and heading, and from a point back to s and t.

Lines, arcs and spirals are clothoids (curvature linear in s) and are evaluated by pyclothoids,
the Python binding of Bertolazzi's Clothoids library that scenariogeneration also uses to build
maps. The cubic shapes (poly3, paramPoly3) are given in their own parameter, not in s, so they are
tabulated once and looked up by arc length.

Roads of lines, arcs and spirals (every road of the bundled map) are sampled and projected onto
in plain Python floats, without numpy: reading such a map for `sceml validate` should not cost
numpy's import, which takes longer than the work. The arithmetic is numpy's, operation by
operation (`linspace`, `clip`, `unwrap`, the nearest segment), so the answers are the same to the
last bit as they were with arrays (tests/maps/test_planview_floats.py holds them to numpy's).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import accumulate, pairwise

import pyclothoids

from .model import Geometry

#: Sampling step of the polyline that projection starts from; Newton steps then refine s.
SAMPLE_STEP = 0.5  # m
_CUBIC_SAMPLES = 400
_NEWTON_STEPS = 8

Pose = tuple[float, float, float]  # x, y, heading


def _clothoid(piece: Geometry) -> Callable[[float], Pose]:
    if piece.kind == "line":
        k0 = dk = 0.0
    elif piece.kind == "arc":
        k0, dk = float(piece.params.get("curvature", 0.0)), 0.0
    else:
        k0 = float(piece.params.get("curvStart", 0.0))
        k1 = float(piece.params.get("curvEnd", 0.0))
        dk = (k1 - k0) / piece.length if piece.length > 0 else 0.0
    curve = pyclothoids.Clothoid.StandardParams(piece.x, piece.y, piece.hdg, k0, dk, piece.length)
    # The compiled curve's own methods, taken once: the wrapper finds them by __getattr__ at
    # every call, and a road is evaluated at every sample.
    x_at, y_at, heading_at = curve.X, curve.Y, curve.Theta

    def pose(ds: float) -> Pose:
        return float(x_at(ds)), float(y_at(ds)), float(heading_at(ds))

    return pose


def _cubic(piece: Geometry) -> Callable[[float], Pose]:
    """poly3 (v over u) and paramPoly3 (u and v over p), parametrised by arc length."""
    import numpy as np  # only maps with cubic roads pay for it

    p = piece.params

    def coefficients(prefix: str) -> tuple[float, float, float, float]:
        return tuple(float(p.get(f"{c}{prefix}", 0.0)) for c in "abcd")  # type: ignore[return-value]

    if piece.kind == "poly3":
        end = piece.length  # u never exceeds the arc length; the table is cut at it below
        params = np.linspace(0.0, end, _CUBIC_SAMPLES)
        au, bu, cu, du = 0.0, 1.0, 0.0, 0.0
        av, bv, cv, dv = coefficients("")
    else:
        end = piece.length if p.get("pRange") == "arcLength" else 1.0
        params = np.linspace(0.0, end, _CUBIC_SAMPLES)
        au, bu, cu, du = coefficients("U")
        av, bv, cv, dv = coefficients("V")
    u = au + params * (bu + params * (cu + params * du))
    v = av + params * (bv + params * (cv + params * dv))
    du_dp = bu + params * (2 * cu + params * 3 * du)
    dv_dp = bv + params * (2 * cv + params * 3 * dv)
    arc = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(u), np.diff(v)))))
    cos_h, sin_h = math.cos(piece.hdg), math.sin(piece.hdg)
    tangent = np.arctan2(dv_dp, du_dp)

    def pose(ds: float) -> Pose:
        uu = float(np.interp(ds, arc, u))
        vv = float(np.interp(ds, arc, v))
        heading = float(np.interp(ds, arc, np.unwrap(tangent)))
        return (
            piece.x + uu * cos_h - vv * sin_h,
            piece.y + uu * sin_h + vv * cos_h,
            piece.hdg + heading,
        )

    return pose


@dataclass(frozen=True)
class Projection:
    """A point in a road's (s, t) frame; `beyond` > 0 when it lies past either end of the road."""

    s: float
    t: float
    beyond: float


class ReferenceLine:
    """The plan view of one road: pose at s, sampled polyline and projection.

    `s`, `xy` and `heading` are the samples (lists of floats, xy as (x, y) pairs).
    """

    def __init__(self, geometries: tuple[Geometry, ...], length: float) -> None:
        self.length = length
        self._starts = [piece.s for piece in geometries]
        self._lengths = [piece.length for piece in geometries]
        self._pieces = [
            _clothoid(piece) if piece.kind in ("line", "arc", "spiral") else _cubic(piece)
            for piece in geometries
        ]
        samples: list[float] = []
        for start, piece_length in zip(self._starts, self._lengths, strict=True):
            count = max(2, math.ceil(piece_length / SAMPLE_STEP) + 1)
            samples.extend(linspace(start, start + piece_length, count)[:-1])
        samples.append(length)
        self.s = [clip(value, 0.0, length) for value in samples]
        poses = [self.pose(s) for s in self.s]
        self.xy = [(x, y) for x, y, _ in poses]
        self.heading = [heading for _, _, heading in poses]
        # Mean curvature of each polyline segment: the Newton step of `project` needs it.
        turns = unwrap(self.heading)
        self._curvature = [
            (h1 - h0) / max(s1 - s0, 1e-12)
            for (s0, s1), (h0, h1) in zip(pairwise(self.s), pairwise(turns), strict=True)
        ]
        # Each polyline segment as its start and its step, with the step's squared length
        # (1 for a segment of no length, as the projection divides by it).
        self._segments = [
            (ax, ay, bx - ax, by - ay, (bx - ax) * (bx - ax) + (by - ay) * (by - ay) or 1.0)
            for (ax, ay), (bx, by) in pairwise(self.xy)
        ]

    def pose(self, s: float) -> Pose:
        """Point and heading of the reference line at `s` (clamped to the road)."""
        s = min(max(s, 0.0), self.length)
        index = 0
        for i, start in enumerate(self._starts):
            if start <= s + 1e-12:
                index = i
        return self._pieces[index](min(s - self._starts[index], self._lengths[index]))

    def project(self, x: float, y: float) -> Projection:
        """The nearest point of the reference line to (x, y), as s and signed t (left positive)."""
        index, fraction = self._nearest_segment(x, y)
        s = self.s[index] + fraction * (self.s[index + 1] - self.s[index])
        # Newton on the along-track residual. Its derivative is -(1 - k*t): a point t off a line
        # of curvature k moves 1/(1 - k*t) metres of s per metre along, so a plain `s += along`
        # converges only by a factor k*t per step (up to 0.8 on the junction's tight lanes).
        curvature = self._curvature[index]
        for _ in range(_NEWTON_STEPS):
            px, py, h = self.pose(s)
            along = (x - px) * math.cos(h) + (y - py) * math.sin(h)
            t = -(x - px) * math.sin(h) + (y - py) * math.cos(h)
            scale = 1.0 - curvature * t
            step = along / scale if scale > 0.2 else along  # near the centre of curvature
            next_s = min(max(s + step, 0.0), self.length)
            if abs(next_s - s) < 1e-10:
                break
            s = next_s
        px, py, h = self.pose(s)
        along = (x - px) * math.cos(h) + (y - py) * math.sin(h)
        t = -(x - px) * math.sin(h) + (y - py) * math.cos(h)
        return Projection(s, t, abs(along))

    def _nearest_segment(self, x: float, y: float) -> tuple[int, float]:
        """The polyline segment nearest to (x, y), the first of equals, and where along it
        (0 to 1) the nearest point lies."""
        best, index, fraction = math.inf, 0, 0.0
        for i, (ax, ay, dx, dy, squared) in enumerate(self._segments):
            u = ((x - ax) * dx + (y - ay) * dy) / squared
            u = 0.0 if u < 0.0 else 1.0 if u > 1.0 else u  # clip(u, 0.0, 1.0), inline: the hot loop
            nx = ax + u * dx - x
            ny = ay + u * dy - y
            distance = nx * nx + ny * ny
            if distance < best:
                best, index, fraction = distance, i, u
        return index, fraction


def clip(value: float, low: float, high: float) -> float:
    """`value` held between `low` and `high` as numpy.clip does it: a value equal to a bound is
    kept (-0.0 stays -0.0 against a bound of 0.0)."""
    return low if value < low else high if value > high else value


def linspace(start: float, stop: float, count: int) -> list[float]:
    """`count` (>= 2) evenly spaced values from `start` to `stop`, as numpy.linspace gives them:
    i * step + start, the last one `stop` itself."""
    div = count - 1
    delta = stop - start
    step = delta / div
    if step == 0:  # numpy's order for a step too small to be a float (gh-5437)
        values = [i / div * delta + start for i in range(count)]
    else:
        values = [i * step + start for i in range(count)]
    values[-1] = stop
    return values


def unwrap(angles: Sequence[float]) -> list[float]:
    """The angles with every jump of more than pi between neighbours taken the short way round,
    as numpy.unwrap computes them (its remainder is Python's % for floats)."""
    if not angles:
        return []
    corrections = []
    for before, after in pairwise(angles):
        jump = after - before
        wrapped = (jump + math.pi) % (2 * math.pi) - math.pi
        if wrapped == -math.pi and jump > 0:
            wrapped = math.pi
        corrections.append(0.0 if abs(jump) < math.pi else wrapped - jump)
    return [angles[0]] + [a + c for a, c in zip(angles[1:], accumulate(corrections), strict=True)]

"""A road's reference line: from s to a point and heading, and from a point back to s and t.

Lines, arcs and spirals are clothoids (curvature linear in s) and are evaluated by pyclothoids,
the Python binding of Bertolazzi's Clothoids library that scenariogeneration also uses to build
maps. The cubic shapes (poly3, paramPoly3) are given in their own parameter, not in s, so they are
tabulated once and looked up by arc length.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
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

    def pose(ds: float) -> Pose:
        return float(curve.X(ds)), float(curve.Y(ds)), float(curve.Theta(ds))

    return pose


def _cubic(piece: Geometry) -> Callable[[float], Pose]:
    """poly3 (v over u) and paramPoly3 (u and v over p), parametrised by arc length."""
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
    """The plan view of one road: pose at s, sampled polyline and projection."""

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
            samples.extend(np.linspace(start, start + piece_length, count)[:-1].tolist())
        samples.append(length)
        self.s = np.clip(np.array(samples), 0.0, length)
        poses = np.array([self.pose(float(s)) for s in self.s])
        self.xy = poses[:, :2]
        self.heading = poses[:, 2]
        # Mean curvature of each polyline segment: the Newton step of `project` needs it.
        spans = np.maximum(np.diff(self.s), 1e-12)
        self._curvature = np.diff(np.unwrap(self.heading)) / spans

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
        point = np.array([x, y])
        a, b = self.xy[:-1], self.xy[1:]
        d = b - a
        squared = np.einsum("ij,ij->i", d, d)
        squared[squared == 0.0] = 1.0
        u = np.clip(np.einsum("ij,ij->i", point - a, d) / squared, 0.0, 1.0)
        nearest = a + u[:, None] * d
        index = int(np.argmin(np.einsum("ij,ij->i", nearest - point, nearest - point)))
        s = float(self.s[index] + u[index] * (self.s[index + 1] - self.s[index]))
        # Newton on the along-track residual. Its derivative is -(1 - k*t): a point t off a line
        # of curvature k moves 1/(1 - k*t) metres of s per metre along, so a plain `s += along`
        # converges only by a factor k*t per step (up to 0.8 on the junction's tight lanes).
        curvature = float(self._curvature[index])
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

"""Trailers in the preview: a towed actor's coupler is held at its tower's hitch, and it is
dragged behind as an articulated follower (release 1.4's Actor.trailer, hitchX, couplerX).

The follower is the kinematic trailer of a single axle at the reference point: each step the
trailer turns to face its coupler's new place, the hitch, and stands `coupler` metres behind it.
A towed actor neither drives nor follows a path of its own; it starts in line with its tower
(players place a trailer at the hitch whatever start it was given).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from ..model.towing import Coupling
from .actors import Actor

__all__ = ["Coupling", "couple", "drag"]


def couple(actors: Mapping[str, Actor], links: Iterable[Coupling]) -> None:
    """Place each trailer at the start: in line with its tower, its coupler at the hitch."""
    for link in links:
        tower, trailer = actors[link.tower], actors[link.trailer]
        trailer.towed = True
        hx, hy = _hitch(tower, link.hitch)
        _put(trailer, hx, hy, tower.heading, link.coupler, tower.speed)


def drag(actors: Mapping[str, Actor], links: Iterable[Coupling]) -> None:
    """One step of towing: each trailer turns towards where the hitch has moved and follows."""
    for link in links:
        tower, trailer = actors[link.tower], actors[link.trailer]
        hx, hy = _hitch(tower, link.hitch)
        x, y = trailer.x, trailer.y
        heading = math.atan2(hy - y, hx - x) if math.hypot(hx - x, hy - y) > 1e-9 else 0.0
        if math.cos(heading - trailer.heading) < 0:
            # Pushed back past its own axle the trailer would flip round: it keeps its
            # heading (a jack-knife the preview does not model).
            heading = trailer.heading
        _put(trailer, hx, hy, heading, link.coupler, tower.speed)


def _hitch(tower: Actor, hitch: float) -> tuple[float, float]:
    return tower.x + hitch * math.cos(tower.heading), tower.y + hitch * math.sin(tower.heading)


def _put(
    trailer: Actor, hx: float, hy: float, heading: float, coupler: float, speed: float
) -> None:
    x, y = trailer.x, trailer.y
    trailer.x = hx - coupler * math.cos(heading)
    trailer.y = hy - coupler * math.sin(heading)
    trailer.heading = heading
    trailer.speed = speed
    trailer.odometer += math.hypot(trailer.x - x, trailer.y - y)

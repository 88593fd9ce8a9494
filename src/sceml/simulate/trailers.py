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
from dataclasses import dataclass

import scemlmodel as scm

from ..model.params import concrete
from .actors import Actor


@dataclass(frozen=True)
class Coupling:
    """One tower and the actor it tows, with where its hitch and the trailer's coupler lie
    ahead of their reference points (m)."""

    tower: str
    trailer: str
    hitch: float
    coupler: float


def couplings(actors: Iterable[scm.Actor]) -> list[Coupling]:
    """The model's couplings, each tower's before its trailer's own (a chain front to back)."""
    actors = list(actors)
    towed = {actor.trailer for actor in actors if actor.trailer is not None}
    found: list[Coupling] = []
    for first in actors:
        if first in towed:
            continue  # reached from its tower
        current, seen = first, set()
        while current.trailer is not None and current not in seen:
            seen.add(current)
            after = current.trailer
            found.append(
                Coupling(
                    str(current.name),
                    str(after.name),
                    concrete(current, "hitchX"),
                    concrete(after, "couplerX"),
                )
            )
            current = after
    return found


def is_towed(actor: scm.Actor, actors: Iterable[scm.Actor]) -> bool:
    """Whether another of `actors` tows this one."""
    return any(other.trailer is actor for other in actors if other is not actor)


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

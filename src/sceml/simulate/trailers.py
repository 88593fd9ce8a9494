"""Trailers in the preview: a towed actor's coupler is held at its tower's hitch, and it is
dragged behind as an articulated follower (release 1.4's Actor.trailer, hitchX, couplerX).

The follower is the kinematic trailer of a single axle at the reference point: each step the
trailer turns to face its coupler's new place, the hitch, and stands `coupler` metres behind it.
A towed actor neither drives nor follows a path of its own; it starts in line with its tower
(players place a trailer at the hitch whatever start it was given).

Release 1.5's ConnectTrailer and DisconnectTrailer couple and uncouple during the run
(`connect`, `disconnect`): a trailer connected where it stands is drawn to the hitch in the
next drag, as esmini 3.6 moves it there in the step after the action.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from ..model.towing import Coupling
from .actors import Actor
from .paths import heading_path

__all__ = ["Coupling", "connect", "couple", "disconnect", "drag"]


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


def connect(
    actors: Mapping[str, Actor], links: list[Coupling], link: Coupling, rolls_on: bool
) -> None:
    """Couple `link.trailer` to its tower where it stands; a trailer the tower already tows is
    uncoupled first (as `disconnect`), as esmini 3.6's ConnectTrailerAction does."""
    if any(old == link for old in links):
        return
    disconnect(actors, links, link.tower, rolls_on)
    links[:] = [each for each in links if each.trailer != link.trailer]  # one tower at a time
    links.append(link)
    # A tower that is itself towed is dragged first: keep every tower before its trailer.
    links.sort(key=lambda each: _depth(links, each.tower))
    actors[link.trailer].towed = True


def disconnect(
    actors: Mapping[str, Actor], links: list[Coupling], tower: str, rolls_on: bool
) -> str | None:
    """Uncouple what `tower` tows; the trailer's name, None when it towed nothing. The trailer
    goes straight on from where it stands at its speed when `rolls_on` (esmini 3.6 moves it
    along its road), else it stops (esmini cannot move it where there is no road)."""
    link = next((each for each in links if each.tower == tower), None)
    if link is None:
        return None
    links.remove(link)
    trailer = actors[link.trailer]
    trailer.towed = False
    trailer.follow(heading_path(trailer.x, trailer.y, trailer.heading))
    if not rolls_on:
        trailer.speed = 0.0
    return link.trailer


def _depth(links: list[Coupling], name: str) -> int:
    """How many towers pull `name` (0 for a tower nobody tows); a towing loop is cut."""
    towers = {each.trailer: each.tower for each in links}
    depth, seen = 0, {name}
    while name in towers and towers[name] not in seen:
        name = towers[name]
        seen.add(name)
        depth += 1
    return depth


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

"""Who tows whom (release 1.4's Actor.trailer, hitchX, couplerX): one reading of the model that
the validation, the export, the preview and the map view share."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import scemlmodel as scm

from .params import concrete


@dataclass(frozen=True)
class Coupling:
    """One tower and the actor it tows, with where its hitch and the trailer's coupler lie
    ahead of their reference points (m)."""

    tower: str
    trailer: str
    hitch: float
    coupler: float


def couplings(actors: Iterable[scm.Actor]) -> list[Coupling]:
    """The model's couplings, each tower's before its trailer's own (a chain front to back).

    A towing loop (SCEML-A009) is followed once round and no further."""
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


def is_towed(actor: scm.Actor) -> bool:
    """Whether another actor of the same root node tows this one."""
    others = getattr(actor.eContainer(), "actors", ())
    return any(other.trailer is actor for other in others if other is not actor)

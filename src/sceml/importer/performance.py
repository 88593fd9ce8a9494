"""A vehicle's own Performance (release 1.4's Actor.maxSpeed, maxAcceleration, maxDeceleration).

esmini caps every vehicle's motion by its Performance, so a catalog bus good for 70 m/s keeps up
with a car at 40 m/s where SceML's bus table (27.8 m/s) would leave it behind. One function reads
it, for the entities and for any conversion that needs the actor's own limits.
"""

from __future__ import annotations

from typing import NamedTuple

from lxml import etree

import scemlmodel as scm

from ..export.entities import performance_of
from . import traced
from .context import Build
from .positions import number

#: Performance attribute -> Actor feature; the same names on both sides.
FEATURES = ("maxSpeed", "maxAcceleration", "maxDeceleration")
#: 1.2's jerk limits: no SceML feature holds them, and esmini's default motion does not read them.
UNKEPT = ("maxAccelerationRate", "maxDecelerationRate")


class Performance(NamedTuple):
    """A Vehicle's stated limits (m/s, m/s2, m/s2); None where the file states none."""

    max_speed: float | None
    max_acceleration: float | None
    max_deceleration: float | None


def read_performance(vehicle: etree._Element) -> Performance:
    """The Performance of a Vehicle element (a catalog entry already resolved into it), its
    parameters resolved; all None when it has none (a Pedestrian, a MiscObject)."""
    element = vehicle.find("Performance")
    if element is None:
        return Performance(None, None, None)
    values = [number(element, name) if element.get(name) is not None else None for name in FEATURES]
    return Performance(*values)


def keep_performance(build: Build, actor: scm.Actor, vehicle: etree._Element) -> None:
    """Set the actor's limits where the Vehicle's Performance differs from its kind's default
    (the table the export writes when unset), so a file with the usual limits stays unchanged."""
    stated = read_performance(vehicle)
    defaults = performance_of(actor.eClass.name)
    for feature, value, default in zip(FEATURES, stated, defaults, strict=True):
        if value is not None and abs(value - default) > 1e-9:
            actor.eSet(feature, traced.value(value))
    element = vehicle.find("Performance")
    dropped = [] if element is None else [a for a in UNKEPT if element.get(a) is not None]
    if dropped:
        build.report.add(
            "not represented",
            f"entity {actor.name!r}: Performance {', '.join(dropped)} (SceML keeps no jerk limit)",
            build.where(element),
        )

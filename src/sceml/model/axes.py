"""Which of an actor's motions a maneuver drives: its speed (longitudinal), its path (lateral)
or both. Simultaneity (validation) and the import's ordering of overlapping maneuvers read it.

A maneuver drives the axes of its category, a composite one both, except a FollowTrajectory:
SceML follows it at the actor's speed, so it drives the path only and a speed change may run
beside it, as an OpenSCENARIO event with a SpeedAction and a FollowTrajectoryAction without a
time reference does (esmini's pedestrian and traffic_lights walkers).
"""

from __future__ import annotations

from pyecore.ecore import EObject

from . import catalog

_BY_CATEGORY = {
    "longitudinal": frozenset({"longitudinal"}),
    "lateral": frozenset({"lateral"}),
    "composite": frozenset({"longitudinal", "lateral"}),
}

#: Composite kinds that leave the speed to the actor's other maneuvers.
_PATH_ONLY = frozenset({"FollowTrajectory"})


def maneuver_axes(node: EObject) -> frozenset[str]:
    """`longitudinal` and/or `lateral`: what `node` drives (none for a kind that is no maneuver)."""
    kind = str(node.eClass.name)
    if kind in _PATH_ONLY:
        return _BY_CATEGORY["lateral"]
    return _BY_CATEGORY.get(catalog.category(kind) or "", frozenset())

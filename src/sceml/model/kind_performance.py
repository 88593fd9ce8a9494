"""What the export writes for each actor kind when the actor states no value of its own: the
OpenSCENARIO vehicleCategory and the Performance (maxSpeed, maxAcceleration, maxDeceleration).

Below export, simulate, validation and the import, which all read an actor's limits the way the
export writes them (`own_performance`).
"""

from __future__ import annotations

import scemlmodel as scm

from . import params

#: OpenSCENARIO vehicleCategory of each SceML vehicle kind.
VEHICLE_CATEGORIES = {
    "Car": "car",
    "Van": "van",
    "Truck": "truck",
    "Bus": "bus",
    "Motorcycle": "motorbike",
    "Bicycle": "bicycle",
}
#: Performance (maxSpeed m/s, maxAcceleration m/s2, maxDeceleration m/s2) per category.
PERFORMANCE = {
    "car": (69.444, 10.0, 10.0),
    "van": (50.0, 6.0, 9.0),
    "truck": (33.333, 3.0, 8.0),
    "bus": (27.778, 3.0, 8.0),
    "motorbike": (55.556, 8.0, 10.0),
    "bicycle": (11.111, 2.0, 5.0),
}
#: A Pedestrian has no Performance element; its limits for actions that need some (walking pace).
PEDESTRIAN_PERFORMANCE = (3.0, 1.5, 3.0)
#: The Actor features (release 1.4) that hold an actor's own Performance, in table order.
PERFORMANCE_FEATURES = ("maxSpeed", "maxAcceleration", "maxDeceleration")


def performance_of(kind: str) -> tuple[float, float, float]:
    """(maxSpeed, maxAcceleration, maxDeceleration) of an actor kind (a metaclass name)."""
    limits = PERFORMANCE[VEHICLE_CATEGORIES[kind]] if kind in VEHICLE_CATEGORIES else None
    return limits or PEDESTRIAN_PERFORMANCE


def own_performance(actor: scm.Participant) -> tuple[float, float, float]:
    """(maxSpeed, maxAcceleration, maxDeceleration) of an actor: its own limits where it states
    them (release 1.4, from an imported Vehicle's Performance), its kind's otherwise."""
    defaults = performance_of(actor.eClass.name)
    if not isinstance(actor, scm.Actor):
        return defaults
    own = (
        params.concrete(actor, feature) if actor.eGet(feature) is not None else default
        for feature, default in zip(PERFORMANCE_FEATURES, defaults, strict=True)
    )
    max_speed, max_acceleration, max_deceleration = own
    return max_speed, max_acceleration, max_deceleration

"""How long a lane change given by its lateral rate takes (`dynamicsDimension="rate"`).

OpenSCENARIO's rate of a lane change is its peak lateral speed (m/s). Players turn it into a
duration over the lateral distance to cover: esmini's TransitionDynamics takes the time at
which the shape's steepest slope equals the rate, `peak factor × distance / rate`. Reading the
rate as a duration (metres = speed × rate) drove ALKS 4.4.x and 4.5.x's cut-ins and cut-outs
over 33 m instead of 45 m (0.97 m off).
"""

from __future__ import annotations

import math

import scemlmodel as scm

from ..maps.resolve import resolve, start_poses
from .context import Build

#: The steepest slope of each shape over a change of 1 m in 1 s: a linear change is as steep
#: throughout, a sinusoidal one π/2 times that at its middle, a cubic one 3/2 times.
PEAK_FACTOR = {"linear": 1.0, "sinusoidal": math.pi / 2, "cubic": 1.5}


def rate_seconds(build: Build, actor: scm.Actor, shape: str, rate: float) -> float | None:
    """The duration of a one-lane change at lateral `rate`, over the width of the lane the
    actor starts in; None without a map or a start on it, for a rate of 0 or less, or a step
    (which takes no time whatever its rate)."""
    width = start_lane_width(build, actor)
    if width is None or rate <= 0 or shape not in PEAK_FACTOR:
        return None
    return PEAK_FACTOR[shape] * width / rate


def start_lane_width(build: Build, actor: scm.Actor) -> float | None:
    """The width of the lane the actor starts in, where it starts."""
    road_map = build.road_map
    if road_map is None:
        return None
    try:
        pose = resolve(actor.startPosition, road_map, start_poses(build.actors.values(), road_map))
        if pose is None:
            return None
        found = road_map.world_to_lane(pose.x, pose.y)
        if not found:
            return None
        band = road_map.band(found[0].road_id, found[0].lane_id, found[0].s)
    except ValueError:  # a PositionError: the start lies off the map
        return None
    return abs(band.outer - band.inner)

"""Who the actors are: kind and size from the recording, the user, or a guess from the motion."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

import scemlmodel as scm

from ..errors import ArgumentError
from ..maps import RoadMap
from ..model import catalog
from ..model.build import lane, world
from .motion import Motion
from .recording import Track

#: Box sizes (length, width, m) that tell a kind when the recording gives a size but no kind.
_SIZES = (("Pedestrian", 1.0, 1.0), ("Bicycle", 2.2, 1.0), ("Car", 5.5, 2.3), ("Van", 7.0, 2.6))
#: Below this top speed (m/s) an actor of no stated kind or size is taken for a pedestrian.
_WALKING = 3.0


@dataclass(frozen=True)
class ActorSpec:
    """What the user says of an actor: `NAME=KIND[:LENGTHxWIDTH]` on the command line."""

    name: str
    kind: str
    length: float | None = None
    width: float | None = None


def parse_actor(text: str) -> ActorSpec:
    """Read `NAME=KIND` or `NAME=KIND:LENGTHxWIDTH` (metres); ArgumentError if it is not."""
    name, _, rest = text.partition("=")
    kind, _, size = rest.partition(":")
    if not name or not kind:
        raise ArgumentError(f"expected NAME=KIND[:LENGTHxWIDTH], got {text!r}")
    if not _is_actor_kind(kind):
        options = ", ".join(c.__name__ for c in catalog.concrete_subclasses("Actor"))
        raise ArgumentError(f"unknown actor kind {kind!r}; choose one of: {options}")
    if not size:
        return ActorSpec(name, kind)
    try:
        length, width = (float(v) for v in size.lower().split("x"))
    except ValueError:
        raise ArgumentError(f"expected LENGTHxWIDTH in metres, got {size!r}") from None
    if not (length > 0 and width > 0):
        raise ArgumentError(f"an actor's size must be positive, got {size!r}")
    return ActorSpec(name, kind, length, width)


def _is_actor_kind(kind: str) -> bool:
    cls = getattr(scm, kind, None)
    return cls is not None and catalog.is_kind_of(kind, "Actor") and not cls.eClass.abstract


def actor_kind(track: Track, motion: Motion, given: ActorSpec | None, *, ego: bool) -> str:
    """The actor's kind: the user's, the recording's, one told by its size, else a Car (the
    ego always), or a Pedestrian when it never goes faster than walking.

    Speed alone cannot tell a bike from a slow car, so bikes need a size or `--actor`.
    """
    if given is not None:
        return given.kind
    if track.kind is not None:
        return track.kind
    if track.length is not None and track.width is not None:
        for kind, length, width in _SIZES:
            if track.length <= length and track.width <= width:
                return kind
        return "Truck"
    if not ego and float(np.percentile(motion.speed, 95)) <= _WALKING:
        return "Pedestrian"
    return "Car"


def start_position(
    motion: Motion, kind: str, road_map: RoadMap | None, shift: float = 0.0
) -> scm.LanePosition | scm.WorldPosition:
    """Where the actor starts: on its lane (road, lane, s, offset) when it stands on one and
    faces along its traffic; else the world point and heading (people facing across a kerb).
    `shift` (m) moves the smoothed first point along the heading (`longitudinal.start_shift`)."""
    x, y, heading = float(motion.x[0]), float(motion.y[0]), float(motion.heading[0])
    x, y = x + shift * math.cos(heading), y + shift * math.sin(heading)
    if road_map is not None and kind != "Pedestrian":
        for found in road_map.world_to_lane(x, y):
            along = road_map.traffic_heading(found.road_id, found.lane_id, found.s)
            if math.cos(heading - along) > math.cos(math.radians(20)):
                return lane(found.road_id, found.lane_id, round(found.s, 3), round(found.offset, 3))
    return world(round(x, 3), round(y, 3), h=round(math.remainder(heading, 2 * math.pi), 4))

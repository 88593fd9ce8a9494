"""OpenDRIVE road networks: read a map, convert between lane and world coordinates, find routes.

    >>> from sceml.maps import load_map
    >>> road_map = load_map("maps/intersection.xodr")
    >>> pose = road_map.lane_to_world("3", 1, 30.0)
    >>> [c.lane_id for c in road_map.world_to_lane(pose.x, pose.y)]
    [1]

Why SceML reads OpenDRIVE this way (and not with one of the PyPI readers): docs/map-reader.md.
`RoadMap` and `load_map` are imported when first used: they bring pyclothoids (and numpy for
maps with cubic roads, the road index and drawings), which validating a scenario without a map,
or starting the CLI, should not pay for.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from .model import (
    BICYCLE_LANE_TYPES,
    PEDESTRIAN_LANE_TYPES,
    VEHICLE_EDGE_LANE_TYPES,
    VEHICLE_LANE_TYPES,
    LaneBand,
    LaneCoordinate,
    PositionError,
    WorldPose,
    wrap_angle,
)
from .reader import MapError

if TYPE_CHECKING:
    from .roadmap import RoadMap, load_map

__all__ = [
    "BICYCLE_LANE_TYPES",
    "PEDESTRIAN_LANE_TYPES",
    "VEHICLE_EDGE_LANE_TYPES",
    "VEHICLE_LANE_TYPES",
    "LaneBand",
    "LaneCoordinate",
    "MapError",
    "PositionError",
    "RoadMap",
    "WorldPose",
    "load_map",
    "wrap_angle",
]


def __getattr__(name: str) -> Any:
    if name in ("RoadMap", "load_map"):
        from . import roadmap

        return getattr(roadmap, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

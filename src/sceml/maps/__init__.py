"""OpenDRIVE road networks: read a map, convert between lane and world coordinates, find routes.

    >>> from sceml.maps import load_map
    >>> road_map = load_map("maps/intersection.xodr")
    >>> pose = road_map.lane_to_world("3", 1, 30.0)
    >>> [c.lane_id for c in road_map.world_to_lane(pose.x, pose.y)]
    [1]

Why SceML reads OpenDRIVE this way (and not with one of the PyPI readers): docs/map-reader.md.
"""

from .model import BICYCLE_LANE_TYPES, PEDESTRIAN_LANE_TYPES, VEHICLE_LANE_TYPES
from .reader import MapError
from .roadmap import (
    LaneBand,
    LaneCoordinate,
    PositionError,
    RoadMap,
    WorldPose,
    load_map,
    wrap_angle,
)

__all__ = [
    "BICYCLE_LANE_TYPES",
    "PEDESTRIAN_LANE_TYPES",
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

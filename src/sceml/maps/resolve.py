"""Any model Position as one world pose on a map: the single meaning every stage shares.

Validation's map rules, the preview, the map view and the importer all ask "where is this
position?"; they ask here, so a road coordinate means the same point to each of them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from pyecore.ecore import EObject

import scemlmodel as scm

from .model import LaneCoordinate, PositionError, WorldPose, wrap_angle
from .positions import nominal

if TYPE_CHECKING:
    from .roadmap import RoadMap


def road_to_lane(road_map: RoadMap, road_id: str, s: float, t: float) -> LaneCoordinate:
    """The lane holding road coordinate (s, t), with the offset from that lane's centre.

    PositionError names the road, or the s or t that lies off it.
    """
    road = road_map.road(road_id)
    if not -1e-6 <= s <= road.length + 1e-6:
        raise PositionError(
            f"s={s:g} m is outside road {road.id!r}, which is {road.length:g} m long"
        )
    bands = road_map.bands(road, s)
    for band in bands:
        low, high = sorted((band.inner, band.outer))
        if band.lane.id != 0 and band.width > 0 and low - 1e-9 <= t <= high + 1e-9:
            return LaneCoordinate(road.id, band.lane.id, s, t - band.centre, band.lane.type)
    edges = [edge for band in bands for edge in (band.inner, band.outer)]
    span = f"{min(edges):g} to {max(edges):g} m" if edges else "no lanes"
    raise PositionError(f"t={t:g} m is off road {road.id!r} at s={s:g} (its lanes span {span})")


def road_pose(
    road_map: RoadMap, road_id: str, s: float, t: float, h: float | None = None
) -> WorldPose:
    """The world pose of a road coordinate.

    Without `h` the heading is the direction of traffic of the lane the point lies in (as a
    lane position there); with `h` it is the road's direction at s turned by h, as
    OpenSCENARIO's relative Orientation of a RoadPosition says.
    """
    lane = road_to_lane(road_map, road_id, s, t)
    pose = road_map.lane_to_world(lane.road_id, lane.lane_id, s, lane.offset)
    if h is None:
        return pose
    _, _, road_heading = road_map.reference_line(lane.road_id).pose(s)
    return WorldPose(pose.x, pose.y, wrap_angle(road_heading + h))


def resolve(position: EObject | None, road_map: RoadMap | None) -> WorldPose | None:
    """The world pose a position stands for (its nominal value); None when it has no number
    or needs a map that is not given. PositionError when it lies off the map."""
    if isinstance(position, scm.WorldPosition):
        x, y, h = nominal(position.x), nominal(position.y), nominal(position.h, 0.0)
        if x is None or y is None or h is None:
            return None
        return WorldPose(x, y, wrap_angle(h))
    if road_map is None:
        return None
    if isinstance(position, scm.LanePosition):
        s, offset = nominal(position.s), nominal(position.offset, 0.0)
        if s is None or offset is None or not position.roadId or position.laneId is None:
            return None
        return road_map.lane_to_world(str(position.roadId), int(position.laneId), s, offset)
    if isinstance(position, scm.RoadPosition):
        s, t = nominal(position.s), nominal(position.t, 0.0)
        if s is None or t is None or not position.roadId:
            return None
        return road_pose(road_map, str(position.roadId), s, t, nominal(position.h))
    return None

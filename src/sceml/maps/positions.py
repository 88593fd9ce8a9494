"""A model's Position on a map: the world points it stands for, at every abstraction level.

A concrete position is one point. A logical one may give ranges or distributions; it is judged at
the ends of what each coordinate allows (a range or uniform distribution by min and max, a normal
one by its bounds, or mean +- 3 sd when unbounded, a discrete one by each option), and at the
middle. Parameter references (inside module definitions) have no number: such a position is
skipped until a use gives it one (rules run on the flattened scenario for that).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from pyecore.ecore import EObject

import scemlmodel as scm

from .model import PositionError, WorldPose, wrap_angle

if TYPE_CHECKING:
    from .roadmap import RoadMap


#: How a coordinate is read: every number it is judged at, or only its nominal one.
Spread = Callable[[EObject | None, float | None], list[float] | None]


def spread(parameter: EObject | None, default: float | None = None) -> list[float] | None:
    """The numbers a parameter value is judged at; `[default]` when unset; None when unknown."""
    if parameter is None:
        return None if default is None else [default]
    if isinstance(parameter, scm.Value):
        return None if parameter.value is None else [float(parameter.value)]
    if isinstance(parameter, scm.Range | scm.UniformDistribution):
        if parameter.min is None or parameter.max is None:
            return None
        low, high = float(parameter.min), float(parameter.max)
        return [low, (low + high) / 2, high]
    if isinstance(parameter, scm.NormalDistribution):
        if parameter.mean is None:
            return None
        mean = float(parameter.mean)
        deviation = float(parameter.standardDeviation or 0.0)
        low, high = parameter.lowerBound, parameter.upperBound
        low_value = float(low) if low is not None else mean - 3 * deviation
        high_value = float(high) if high is not None else mean + 3 * deviation
        return [low_value, mean, high_value]
    if isinstance(parameter, scm.DiscreteDistribution):
        options = [float(o.value) for o in parameter.options if o.value is not None]
        return options or None
    return None  # a parameter reference: no number before a use gives one


def nominal(parameter: EObject | None, default: float | None = None) -> float | None:
    """One representative number: the value, a range's middle, a distribution's mean.

    A discrete distribution gives its middle option in order of size (the mean of two).
    """
    numbers = spread(parameter, default)
    if not numbers:
        return None
    if isinstance(parameter, scm.NormalDistribution):
        return float(parameter.mean)
    numbers = sorted(numbers)  # a discrete distribution lists its options in any order
    return numbers[len(numbers) // 2] if len(numbers) != 2 else sum(numbers) / 2


@dataclass(frozen=True)
class Located:
    """A world point a position stands for, and the lane coordinate it was given in (if any).

    `heading` is None when a world position leaves h unset.
    """

    x: float
    y: float
    heading: float | None
    lane: tuple[str, int, float, float] | None = None


def is_concrete(position: EObject) -> bool:
    """Whether every coordinate of a position is a single value (or unset with a default)."""
    return all(
        held is None or isinstance(held, scm.Value)
        for held in (
            position.eGet(feature)
            for feature in position.eClass.eAllStructuralFeatures()
            if getattr(feature, "containment", False)
        )
    )


def locate(position: EObject | None, road_map: RoadMap | None) -> list[Located]:
    """The world points a position stands for (one when concrete); [] when it has no numbers.

    A lane position needs the map; its coordinates are checked by `RoadMap.band`, which raises
    PositionError naming the road, lane or s that does not exist.
    """
    if isinstance(position, scm.WorldPosition):
        xs, ys = spread(position.x), spread(position.y)
        given = spread(position.h)
        headings: list[float | None] = list(given) if given else [None]
        if not xs or not ys:
            return []
        return [
            Located(x, y, wrap_angle(h) if h is not None else None)
            for x, y, h in itertools.product(xs, ys, headings)
        ]
    if isinstance(position, scm.LanePosition) and road_map is not None:
        ss, offsets = spread(position.s), spread(position.offset, 0.0)
        if not ss or not offsets or position.roadId is None or position.laneId is None:
            return []
        points = []
        for s, offset in itertools.product(ss, offsets):
            pose: WorldPose = road_map.lane_to_world(
                str(position.roadId), int(position.laneId), s, offset
            )
            points.append(
                Located(
                    pose.x, pose.y, pose.heading, (str(position.roadId), position.laneId, s, offset)
                )
            )
        return points
    if isinstance(position, scm.RoadPosition) and road_map is not None:
        return _on_road(position, road_map, spread)
    if isinstance(position, scm.RoutePosition) and road_map is not None:
        return _on_route(position, road_map)
    return []


def _on_route(position: scm.RoutePosition, road_map: RoadMap) -> list[Located]:
    """The point of a route position (its nominal place: a route is not spread over values)."""
    from .resolve import route_pose  # resolve reads this module's numbers

    pose = route_pose(position, road_map)
    return [] if pose is None else [Located(pose.x, pose.y, pose.heading)]


def _on_road(position: scm.RoadPosition, road_map: RoadMap, numbers: Spread) -> list[Located]:
    """The points of a road position, each with the lane coordinate it lies in."""
    from .resolve import road_pose, road_to_lane  # resolve reads this module's numbers

    ss, ts, hs = numbers(position.s, None), numbers(position.t, 0.0), numbers(position.h, None)
    if not ss or not ts or not position.roadId:
        return []
    road = str(position.roadId)
    points = []
    headings: list[float | None] = list(hs) if hs else [None]
    for s, t, h in itertools.product(ss, ts, headings):
        lane = road_to_lane(road_map, road, s, t)
        pose = road_pose(road_map, road, s, t, h)
        points.append(Located(pose.x, pose.y, pose.heading, (road, lane.lane_id, s, lane.offset)))
    return points


def _nominal_only(parameter: EObject | None, default: float | None = None) -> list[float] | None:
    value = nominal(parameter, default)
    return None if value is None else [value]


def centre(position: EObject | None, road_map: RoadMap | None) -> Located | None:
    """The representative point of a position (its value, or the middle of what it allows)."""
    try:
        if isinstance(position, scm.WorldPosition):
            x, y = nominal(position.x), nominal(position.y)
            h = nominal(position.h)
            if x is None or y is None:
                return None
            return Located(x, y, wrap_angle(h) if h is not None else None)
        if isinstance(position, scm.LanePosition) and road_map is not None:
            s, offset = nominal(position.s), nominal(position.offset, 0.0)
            if s is None or offset is None or position.roadId is None or position.laneId is None:
                return None
            pose = road_map.lane_to_world(str(position.roadId), int(position.laneId), s, offset)
            return Located(
                pose.x, pose.y, pose.heading, (str(position.roadId), position.laneId, s, offset)
            )
        if isinstance(position, scm.RoadPosition) and road_map is not None:
            points = _on_road(position, road_map, _nominal_only)
            return points[0] if points else None
        if isinstance(position, scm.RoutePosition) and road_map is not None:
            points = _on_route(position, road_map)
            return points[0] if points else None
    except PositionError:
        return None
    return None

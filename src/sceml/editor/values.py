"""ParamValue and Position as the protocol's JSON, to and from pyecore objects, and the text the
page shows for them.

The display text is the server's, in SceML's one value notation (`params.describe`, with units
and km/h as the canvas's boxes write them, render/labels.py): the page shows it as it comes and
keeps only what editing needs (web/src/lib/values.ts).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import scemlmodel as scm

from ..model import params
from ..render.labels import Scope, describe_position, describe_value, unit_text
from .errors import OperationError

#: Every ParamValue type of the protocol, in the order the panels offer them.
VALUE_TYPES = ("value", "range", "uniform", "normal", "discrete", "ref")

#: Finds a module parameter by name (None outside a module, where `ref` is refused).
ParameterLookup = Callable[[str], "scm.ModuleParameter | None"]


def value_to_json(value: scm.ParameterValue | None) -> dict[str, Any] | None:
    """The protocol's ParamValue for a model value (None when unset)."""
    if value is None:
        return None
    if isinstance(value, scm.Value):
        return {"type": "value", "value": value.value}
    if isinstance(value, scm.Range):
        return {"type": "range", "min": value.min, "max": value.max, "step": value.step}
    if isinstance(value, scm.UniformDistribution):
        return {"type": "uniform", "min": value.min, "max": value.max}
    if isinstance(value, scm.NormalDistribution):
        return {
            "type": "normal",
            "mean": value.mean,
            "sd": value.standardDeviation,
            "min": value.lowerBound,
            "max": value.upperBound,
        }
    if isinstance(value, scm.DiscreteDistribution):
        weights = [option.weight for option in value.options]
        return {
            "type": "discrete",
            "values": [option.value for option in value.options],
            "weights": None if all(w is None for w in weights) else weights,
        }
    if isinstance(value, scm.ParameterRef):
        name = value.parameter.name if value.parameter is not None else None
        return {"type": "ref", "parameter": name}
    return {"type": value.eClass.name}


def value_text(value: scm.ParameterValue | None, unit: str = "") -> str | None:
    """What the panel shows for a value, as a box on the canvas writes it (`[6, 10] step 1 m/s`,
    `8 m/s = 28.8 km/h`, `$speed, default 8 m/s`); None when unset."""
    return None if value is None else describe_value(value, unit, Scope())


def default_text(default: scm.ParameterValue | float | None, unit: str = "") -> str | None:
    """A default as the panel names it beside an unset value (`8 m/s`, `N(8, 1) m/s`)."""
    if default is None:
        return None
    if isinstance(default, int | float):
        return params.describe_number(default, unit_text(unit))
    return params.describe(default, unit_text(unit))


def position_text(position: scm.Position | None) -> str | None:
    """What the panel shows for a position (`road 3 lane 1 s 30 m`); None when unset."""
    return None if position is None else describe_position(position, Scope())


def _number(data: Mapping[str, Any], key: str, *, optional: bool = False) -> float | None:
    given = data.get(key)
    if given is None and optional:
        return None
    if isinstance(given, bool) or not isinstance(given, int | float) or not math.isfinite(given):
        raise OperationError(f"{key!r} must be a finite number, not {given!r}")
    return float(given)


def _numbers(data: Mapping[str, Any], key: str) -> list[float]:
    given = data.get(key)
    if not isinstance(given, list) or not given:
        raise OperationError(f"{key!r} must be a non-empty list of numbers")
    return [_number({key: item}, key) for item in given]  # type: ignore[misc]


def value_from_json(
    data: object, find_parameter: ParameterLookup | None = None
) -> scm.ParameterValue | None:
    """A new model value from the protocol's ParamValue; None stays None (unset)."""
    if data is None:
        return None
    if not isinstance(data, Mapping):
        raise OperationError(f"a parameter value must be an object with a 'type', not {data!r}")
    kind = data.get("type")
    try:
        return _MAKERS[kind](data, find_parameter)
    except KeyError:
        raise OperationError(
            f"unknown parameter value type {kind!r}; use one of {', '.join(VALUE_TYPES)}"
        ) from None
    except ValueError as error:  # params' own checks (one weight per value)
        raise OperationError(str(error)) from None


def _ordered(low: float | None, high: float | None) -> None:
    if low is not None and high is not None and low > high:
        raise OperationError(f"min ({low:g}) must not be above max ({high:g})")


def _range(data: Mapping[str, Any], _: ParameterLookup | None) -> scm.ParameterValue:
    low, high = _number(data, "min"), _number(data, "max")
    _ordered(low, high)
    return params.span(low, high, _number(data, "step", optional=True))  # type: ignore[arg-type]


def _uniform(data: Mapping[str, Any], _: ParameterLookup | None) -> scm.ParameterValue:
    low, high = _number(data, "min"), _number(data, "max")
    _ordered(low, high)
    return params.uniform(low, high)  # type: ignore[arg-type]


def _normal(data: Mapping[str, Any], _: ParameterLookup | None) -> scm.ParameterValue:
    low, high = _number(data, "min", optional=True), _number(data, "max", optional=True)
    _ordered(low, high)
    return params.normal(_number(data, "mean"), _number(data, "sd"), low, high)  # type: ignore[arg-type]


def _discrete(data: Mapping[str, Any], _: ParameterLookup | None) -> scm.ParameterValue:
    weights = None if data.get("weights") is None else _numbers(data, "weights")
    return params.discrete(_numbers(data, "values"), weights)


def _ref(data: Mapping[str, Any], find: ParameterLookup | None) -> scm.ParameterValue:
    name = data.get("parameter")
    if find is None:
        raise OperationError("parameter references ('ref') exist only inside a module")
    target = find(str(name)) if isinstance(name, str) else None
    if target is None:
        raise OperationError(f"the module has no parameter {name!r}")
    return scm.ParameterRef(parameter=target)


_MAKERS: dict[object, Callable[[Mapping[str, Any], ParameterLookup | None], scm.ParameterValue]] = {
    "value": lambda data, _: params.value(_number(data, "value")),  # type: ignore[arg-type]
    "range": _range,
    "uniform": _uniform,
    "normal": _normal,
    "discrete": _discrete,
    "ref": _ref,
}


def position_to_json(position: scm.Position | None) -> dict[str, Any] | None:
    """The protocol's Position for a model position (None when unset)."""
    if isinstance(position, scm.WorldPosition):
        return {
            "type": "world",
            **{key: value_to_json(position.eGet(key)) for key in ("x", "y", "z", "h")},
        }
    if isinstance(position, scm.LanePosition):
        return {
            "type": "lane",
            "roadId": position.roadId,
            "laneId": position.laneId,
            "s": value_to_json(position.s),
            "offset": value_to_json(position.offset),
            "h": value_to_json(position.h),
        }
    if isinstance(position, scm.RoadPosition):
        return {
            "type": "road",
            "roadId": position.roadId,
            **{key: value_to_json(position.eGet(key)) for key in ("s", "t", "h")},
        }
    if isinstance(position, scm.RoutePosition):
        return {
            "type": "route",
            "routeName": position.routeName,
            "closed": bool(position.closed),
            "waypoints": [
                {"routeStrategy": w.routeStrategy.name, "position": position_to_json(w.position)}
                for w in position.waypoints
            ],
            "laneId": position.laneId,
            **{key: value_to_json(position.eGet(key)) for key in ("pathS", "laneOffset", "t")},
        }
    kind = None if position is None else RELATIVE_TYPES.get(position.eClass.name)
    if kind is not None:
        assert position is not None
        lane = {"dLane": int(position.dLane or 0)} if kind == "relativeLane" else {}
        return {
            "type": kind,
            "entity": getattr(position.entity, "name", None),
            **lane,
            **{key: value_to_json(position.eGet(key)) for key in _OFFSETS[kind]},
        }
    return None


#: The protocol's type of each relative position, and the offsets it carries (none required).
RELATIVE_TYPES = {
    "RelativeLanePosition": "relativeLane",
    "RelativeRoadPosition": "relativeRoad",
    "RelativeObjectPosition": "relativeObject",
    "RelativeWorldPosition": "relativeWorld",
}
_OFFSETS = {
    "relativeLane": ("ds", "offset"),
    "relativeRoad": ("ds", "dt"),
    "relativeObject": ("dx", "dy", "dz", "h"),
    "relativeWorld": ("dx", "dy", "dz"),
}


def position_from_json(
    data: object,
    find_parameter: ParameterLookup | None = None,
    participants: Mapping[str, scm.Participant] | None = None,
) -> scm.Position | None:
    """A new model position from the protocol's Position; None stays None (unset).

    `participants` by name: what a relative position may name as its entity (the scenario's
    actors, or the module's roles).
    """
    if data is None:
        return None
    if not isinstance(data, Mapping):
        raise OperationError(f"a position must be an object with a 'type', not {data!r}")
    kind = data.get("type")

    def coordinate(key: str, *, required: bool) -> scm.ParameterValue | None:
        made = value_from_json(data.get(key), find_parameter)
        if made is None and required:
            raise OperationError(f"a {kind} position needs {key!r}")
        return made

    if kind == "world":
        position: scm.Position = scm.WorldPosition()
        for key in ("x", "y", "z", "h"):
            position.eSet(key, coordinate(key, required=key in ("x", "y")))
        return position
    if kind in ("lane", "road"):
        road, lane_id = data.get("roadId"), data.get("laneId")
        if not isinstance(road, str | int) or isinstance(road, bool) or str(road) == "":
            raise OperationError(f"'roadId' must be a road id, not {road!r}")
        if kind == "road":
            return scm.RoadPosition(
                roadId=str(road),
                s=coordinate("s", required=True),
                t=coordinate("t", required=False),
                h=coordinate("h", required=False),
            )
        if isinstance(lane_id, bool) or not isinstance(lane_id, int):
            raise OperationError(f"'laneId' must be a whole number, not {lane_id!r}")
        return scm.LanePosition(
            roadId=str(road),
            laneId=lane_id,
            s=coordinate("s", required=True),
            offset=coordinate("offset", required=False),
            h=coordinate("h", required=False),
        )
    if kind in _OFFSETS:
        return _relative_from_json(data, str(kind), coordinate, participants or {})
    if kind == "route":
        return _route_from_json(data, coordinate, find_parameter)
    known = ", ".join(repr(k) for k in ("world", "lane", "road", "route", *_OFFSETS))
    raise OperationError(f"unknown position type {kind!r}; use one of {known}")


def _relative_from_json(
    data: Mapping[str, Any],
    kind: str,
    coordinate: Callable[..., scm.ParameterValue | None],
    participants: Mapping[str, scm.Participant],
) -> scm.Position:
    entity = participants.get(str(data.get("entity")))
    if entity is None:
        names = ", ".join(sorted(participants)) or "none"
        raise OperationError(
            f"a {kind} position names its entity: {data.get('entity')!r} is none of {names}"
        )
    cls = next(getattr(scm, name) for name, type_ in RELATIVE_TYPES.items() if type_ == kind)
    position: scm.Position = cls(entity=entity)
    if kind == "relativeLane":
        lanes = data.get("dLane", 0)
        if isinstance(lanes, bool) or not isinstance(lanes, int):
            raise OperationError(f"'dLane' must be a whole number, not {lanes!r}")
        position.dLane = lanes
    for key in _OFFSETS[kind]:
        position.eSet(key, coordinate(key, required=False))
    return position


def _route_from_json(
    data: Mapping[str, Any],
    coordinate: Callable[..., scm.ParameterValue | None],
    find_parameter: ParameterLookup | None,
) -> scm.RoutePosition:
    """A route position: two or more waypoints, each a world, lane or road position (a route
    is fixed: none relative to an entity, none on another route)."""
    waypoints = data.get("waypoints")
    if not isinstance(waypoints, list) or len(waypoints) < 2:
        raise OperationError("a route position needs 'waypoints': a list of two or more")
    lane_id = data.get("laneId")
    if lane_id is not None and (isinstance(lane_id, bool) or not isinstance(lane_id, int)):
        raise OperationError(f"'laneId' must be a whole number or null, not {lane_id!r}")
    position = scm.RoutePosition(
        routeName=str(data.get("routeName") or "Route"),
        closed=bool(data.get("closed", False)),
        laneId=lane_id,
        pathS=coordinate("pathS", required=False),
        laneOffset=coordinate("laneOffset", required=False),
        t=coordinate("t", required=False),
    )
    for waypoint in waypoints:
        if not isinstance(waypoint, Mapping):
            raise OperationError(f"a waypoint must be an object, not {waypoint!r}")
        at = position_from_json(waypoint.get("position"), find_parameter)
        if at is None or at.eClass.name in RELATIVE_TYPES or isinstance(at, scm.RoutePosition):
            raise OperationError("a waypoint's position is a world, lane or road position")
        strategy = scm.RouteStrategy.getEEnumLiteral(str(waypoint.get("routeStrategy", "shortest")))
        if strategy is None:
            names = ", ".join(str(e.name) for e in scm.RouteStrategy.eLiterals)
            raise OperationError(f"'routeStrategy' is one of {names}")
        position.waypoints.append(scm.RouteWaypoint(position=at, routeStrategy=strategy))
    return position

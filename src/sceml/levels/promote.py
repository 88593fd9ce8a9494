"""Promote a functional scenario to logical with ranges and distributions read from YAML or JSON.

The ranges file maps parameter paths (see `paths`) to what they hold:

    Root.maxDuration: 60                                  a single value
    ego.initialSpeed: {min: 3, max: 7, step: 1}           a range (step optional)
    Accelerate_2.targetSpeed: {uniform: [3, 6]}           a uniform distribution
    Accelerate_1.targetSpeed: {normal: [8, 1], bounds: [6, 10]}   mean, sd, optional bounds
    DriveDistance_1.speed: {values: [8, 10, 12], weights: [1, 2, 1]}   a discrete set
    ego.startPosition: {road: "3", lane: 1, s: 30}        a lane position (offset optional)
    TurnRight_1.destination: {x: 34, y: -1.75, h: 0}      a world position (z, h optional)

Coordinates of a position take the same forms as any parameter.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import scemlmodel as scm

from ..errors import LoadError
from ..files.config import load_config
from ..model import build, catalog, params
from .apply import copy_scenario, set_level
from .paths import LevelError, find_feature, place, resolve, slots, unresolved

#: A ranges file is a few hundred lines at most; anything larger is refused unread.
MAX_RANGES_BYTES = 256 * 1024

_FORMS = (
    "a number, {min, max, step?}, {uniform: [a, b]}, {normal: [mean, sd], bounds?: [lo, hi]}, "
    "{values: [...], weights?: [...]}, or for a position {x, y, z?, h?} / {road, lane, s, offset?}"
)


def load_ranges(path: Path, max_bytes: int = MAX_RANGES_BYTES) -> dict[str, Any]:
    """Read a ranges file (YAML; JSON or TOML by suffix) safely into {path: spec}."""
    data = load_config(path, "ranges file", max_bytes)
    if not isinstance(data, dict) or not all(isinstance(k, str) for k in data):
        raise LoadError("a ranges file maps parameter paths to values or ranges", file=path)
    return data


def promote(
    scenario: scm.Scenario, ranges: Mapping[str, Any], *, source: Path | None = None
) -> scm.Scenario:
    """A logical copy of `scenario` with every path in `ranges` set as given.

    LevelError when a required parameter or a position is still missing afterwards.
    """
    logical = copy_scenario(scenario)
    for path, spec in ranges.items():
        if _is_position(spec):
            owner, feature = find_feature(logical, path)
            owner.eSet(feature, position(path, spec, source))
    known = slots(logical)
    for path, spec in ranges.items():
        if not _is_position(spec):
            place(resolve(logical, path, known), parameter(path, spec, source))
    missing = [p for p in unresolved(logical, known) if known[p].held() is None]
    missing += missing_positions(logical)
    if missing:
        raise LevelError(
            "not yet logical; the ranges file must also give: " + ", ".join(missing),
            file=source,
        )
    set_level(logical, "logical")
    return logical


def missing_positions(scenario: scm.Scenario) -> list[str]:
    """Paths of start positions, destinations and locations that are not set."""
    owners: list[tuple[str, Any]] = []
    for node in scenario.nodes:
        owners.append((str(node.name), node))
        owners.extend((str(a.name), a) for a in getattr(node, "actors", ()))
    missing = []
    for name, owner in owners:
        for reference in owner.eClass.eAllReferences():
            kind = catalog.class_name(reference.eType)
            if reference.many or not catalog.is_kind_of(kind, "Position"):
                continue
            if owner.eGet(reference) is None:
                missing.append(f"{name}.{reference.name}")
    return missing


def _is_position(spec: Any) -> bool:
    return isinstance(spec, dict) and ("x" in spec or "road" in spec)


def position(path: str, spec: Mapping[str, Any], source: Path | None) -> scm.Position:
    """A WorldPosition or LanePosition from its spec."""

    def coordinate(key: str, default: float | None = None) -> scm.ParameterValue:
        if key not in spec:
            if default is None:
                raise LevelError(f"{path}: position needs {key!r}", file=source)
            return params.value(default)
        return parameter(f"{path}.{key}", spec[key], source)

    if "road" in spec:
        lane = spec.get("lane")
        if not isinstance(lane, int) or isinstance(lane, bool):
            raise LevelError(f"{path}: lane position needs an integer 'lane'", file=source)
        return build.lane(str(spec["road"]), lane, coordinate("s"), coordinate("offset", 0.0))
    return build.world(coordinate("x"), coordinate("y"), coordinate("z", 0.0), coordinate("h", 0.0))


def parameter(path: str, spec: Any, source: Path | None) -> scm.ParameterValue:
    """The parameter value a spec describes; LevelError naming the path when it is not one."""
    try:
        made = _parameter(spec)
    except (TypeError, ValueError, KeyError):
        made = None
    if made is None:
        raise LevelError(f"{path}: cannot read {spec!r}; expected {_FORMS}", file=source)
    return made


def _parameter(spec: Any) -> scm.ParameterValue | None:
    if _is_number(spec):
        return params.value(spec)
    if not isinstance(spec, dict):
        return None
    if set(spec) <= {"value"} and _is_number(spec.get("value")):
        return params.value(spec["value"])
    if {"min", "max"} <= set(spec) <= {"min", "max", "step"}:
        return params.span(*_numbers([spec["min"], spec["max"]]), *_numbers([spec.get("step")]))
    if set(spec) == {"uniform"}:
        low, high = _numbers(spec["uniform"], 2)
        return params.uniform(low, high)
    if {"normal"} <= set(spec) <= {"normal", "bounds"}:
        mean, sd = _numbers(spec["normal"], 2)
        bounds = _numbers(spec.get("bounds", [None, None]), 2)
        return params.normal(mean, sd, *bounds)
    if {"values"} <= set(spec) <= {"values", "weights"}:
        weights = spec.get("weights")
        return params.discrete(
            _numbers(spec["values"]), None if weights is None else _numbers(weights)
        )
    return None


def _is_number(spec: Any) -> bool:
    return isinstance(spec, int | float) and not isinstance(spec, bool)


def _numbers(items: Any, count: int | None = None) -> list[Any]:
    if not isinstance(items, list) or (count is not None and len(items) != count):
        raise ValueError("wrong list")
    if not all(item is None or _is_number(item) for item in items):
        raise TypeError("not numbers")
    return items

"""Plausibility limits per actor kind (paper rule 5): a built-in table a project file may override.

A limits file is YAML (`.yaml`, `.yml`) or TOML (`.toml`) mapping actor kinds to limits in SI units:

    Pedestrian:
      max_speed: 3.0          # m/s
      max_acceleration: 2.0   # m/s2
      max_deceleration: 4.0   # m/s2

Entries are merged key by key over the built-in table. A limit is looked up on the actor's own kind
first and then along its superclasses (Bicycle, TwoWheeler, Actor), so a project may set limits on
abstract kinds for kinds the table does not name.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

import scemlmodel as scm

from .. import catalog
from ..errors import LoadError, SceMLError

#: The limit names a table may use, with what each bounds.
LIMIT_KEYS = {
    "max_speed": "speed (m/s)",
    "max_acceleration": "acceleration rate (m/s2)",
    "max_deceleration": "deceleration rate (m/s2)",
}

#: Built-in limits (SI). Speeds are what the kind reaches on public roads with margin, rates what
#: its tyres or legs give; a pedestrian may run but not at 50 km/h.
DEFAULT_LIMITS: dict[str, dict[str, float]] = {
    "Pedestrian": {"max_speed": 5.0, "max_acceleration": 3.0, "max_deceleration": 5.0},
    "Bicycle": {"max_speed": 15.0, "max_acceleration": 3.0, "max_deceleration": 6.0},
    "Motorcycle": {"max_speed": 80.0, "max_acceleration": 9.0, "max_deceleration": 10.0},
    "Car": {"max_speed": 70.0, "max_acceleration": 8.0, "max_deceleration": 11.0},
    "Van": {"max_speed": 50.0, "max_acceleration": 5.0, "max_deceleration": 10.0},
    "Truck": {"max_speed": 35.0, "max_acceleration": 3.0, "max_deceleration": 8.0},
    "Bus": {"max_speed": 35.0, "max_acceleration": 3.0, "max_deceleration": 8.0},
}


class LimitsError(SceMLError):
    """A limits file cannot be read or says something that is not a limit."""

    exit_code = 2


@dataclass(frozen=True)
class Limits:
    """Limits per actor kind name; `limit` looks along the kind's superclasses."""

    table: Mapping[str, Mapping[str, float]] = field(default_factory=lambda: DEFAULT_LIMITS)

    def limit(self, kind: str, key: str) -> float | None:
        """The limit `key` for an actor kind, or None when no kind on its chain sets it."""
        for name in _kind_chain(kind):
            value = self.table.get(name, {}).get(key)
            if value is not None:
                return value
        return None

    def merged(self, overrides: Mapping[str, Mapping[str, float]]) -> Limits:
        """These limits with `overrides` laid over them key by key."""
        table = {kind: dict(values) for kind, values in self.table.items()}
        for kind, values in overrides.items():
            table.setdefault(kind, {}).update(values)
        return Limits(table)


@cache
def _kind_chain(kind: str) -> tuple[str, ...]:
    generated = getattr(scm, kind, None)
    if generated is None or not hasattr(generated, "eClass"):
        return (kind,)
    return (kind, *(s.name for s in generated.eClass.eAllSuperTypes()))


def load_limits(path: str | Path, base: Limits | None = None) -> Limits:
    """Read a YAML or TOML limits file and lay it over `base` (the built-in table by default)."""
    # Here rather than at the top: the reader imports PyYAML, which `sceml validate` without
    # --limits never needs (start-up, issue 31).
    from ..config import load_config

    path = Path(path)
    try:
        data = load_config(path, "limits file")
    except LoadError as error:
        raise LimitsError(error.message, file=path, line=error.line) from None
    return (base or Limits()).merged(_checked(data or {}, path))


def _checked(data: object, path: Path) -> dict[str, dict[str, float]]:
    if not isinstance(data, dict):
        raise LimitsError("a limits file maps actor kinds to limits", file=path)
    kinds = {c.__name__ for c in catalog.concrete_subclasses("Actor")} | {
        "Actor",
        "TwoWheeler",
        "FourWheeler",
    }
    table: dict[str, dict[str, float]] = {}
    for kind, values in data.items():
        if kind not in kinds:
            raise LimitsError(
                f"unknown actor kind {kind!r}; use one of {', '.join(sorted(kinds))}", file=path
            )
        if not isinstance(values, dict):
            raise LimitsError(f"{kind}: expected a table of limits", file=path)
        table[kind] = {}
        for key, value in values.items():
            if key not in LIMIT_KEYS:
                raise LimitsError(
                    f"{kind}: unknown limit {key!r}; use {', '.join(LIMIT_KEYS)}", file=path
                )
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise LimitsError(f"{kind}.{key}: expected a number", file=path)
            if not math.isfinite(value) or value <= 0:
                raise LimitsError(f"{kind}.{key}: a limit is a positive number", file=path)
            table[kind][key] = float(value)
    return table

"""OpenSCENARIO names: SceML names made safe, and kept unique across the whole storyboard."""

from __future__ import annotations

import re

_UNSAFE = re.compile(r"[^A-Za-z0-9_]+")
_RUNS = re.compile(r"_{2,}")

#: Separates a node's name from the suffix of its extra events (`TurnRight_1__arrived`); plain
#: names never contain it, so a reader can tell which node an element belongs to.
SEPARATOR = "__"


def sanitize(name: str | None, fallback: str = "unnamed") -> str:
    """Letters, digits and single underscores only: `CrossingManeuver_1.Accelerate_1` ->
    `CrossingManeuver_1_Accelerate_1`. Dots and `::` would read as namespaces in 1.2+ references."""
    cleaned = _RUNS.sub("_", _UNSAFE.sub("_", name or "")).strip("_")
    return cleaned or fallback


class NameTable:
    """Hands out names unique within one document; a taken name gets `_2`, `_3`, ..."""

    def __init__(self) -> None:
        self._taken: set[str] = set()

    def claim(self, wanted: str) -> str:
        """`wanted` if free, else the first free numbered variant."""
        name, count = wanted, 1
        while name in self._taken:
            count += 1
            name = f"{wanted}_{count}"
        self._taken.add(name)
        return name

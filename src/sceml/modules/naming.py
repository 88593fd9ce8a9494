"""Readable, unique names for expanded nodes, module uses and extracted module parts."""

from __future__ import annotations

from collections.abc import Collection

#: Joins a use's name and the name of a node inside its definition: `CrossingManeuver_1.Accelerate_1`.
SEPARATOR = "."


def scoped(use_name: str, node_name: str) -> str:
    """The name an expanded node gets: its use's name, then its own."""
    return f"{use_name}{SEPARATOR}{node_name}"


def unique(base: str, taken: Collection[str]) -> str:
    """`base` if it is free, else `base~2`, `base~3`, ... (the tilde never appears in built names)."""
    if base not in taken:
        return base
    counter = 2
    while f"{base}~{counter}" in taken:
        counter += 1
    return f"{base}~{counter}"


def numbered(stem: str, taken: Collection[str]) -> str:
    """The first free `stem_1`, `stem_2`, ...: how the builder names nodes and uses."""
    counter = 1
    while f"{stem}_{counter}" in taken:
        counter += 1
    return f"{stem}_{counter}"

"""Changes in words: one line per change, as a reviewer reads it (`TurnLeft_1.destination.x: -34 -> -30 m`)."""

from __future__ import annotations

from .changes import Change
from .snapshot import Leaf

#: The mark before a change in every format: it says what happened without colour.
MARKS = {"added": "+", "removed": "-", "changed": "~", "renamed": "~", "moved": "~"}


def number(value: object) -> str:
    """A number as a person writes it: `8`, `-1.75`, `?` for none."""
    if value is None:
        return "?"
    if isinstance(value, float | int) and not isinstance(value, bool):
        return f"{value:g}"
    return str(value)


def leaf_text(leaf: Leaf, unit: str = "") -> str:
    """A leaf's value in words; `unset` when it has none."""
    suffix = f" {unit}" if unit else ""
    if leaf is None:
        return "unset"
    if not isinstance(leaf, tuple):
        return number(leaf) if not isinstance(leaf, str) else leaf
    word, *rest = leaf
    if word == "value":
        return number(rest[0]) + suffix
    if word == "range":
        step = f" step {number(rest[2])}" if rest[2] is not None else ""
        return f"[{number(rest[0])}, {number(rest[1])}]{step}{suffix}"
    if word == "uniform":
        return f"U({number(rest[0])}, {number(rest[1])}){suffix}"
    if word == "normal":
        bounds = ""
        if rest[2] is not None or rest[3] is not None:
            bounds = f" in [{number(rest[2])}, {number(rest[3])}]"
        return f"N({number(rest[0])}, {number(rest[1])}){bounds}{suffix}"
    if word == "discrete":
        items = ", ".join(
            number(v) + (f"@{number(w)}" if w is not None else "") for v, w in rest[0]
        )
        return "{" + items + "}" + suffix
    if word == "ref":
        return f"${rest[0]}"
    if word == "actor":
        return str(rest[0])
    if word == "module":
        return f"{rest[0]}#{rest[1]}"
    if word == "object":
        return str(rest[0])
    return " ".join(number(part) for part in leaf)


def position_text(layout: Leaf) -> str:
    """A diagram position as `(x, y)`, or `auto` when the node is laid out automatically."""
    if layout is None:
        return "auto"
    return f"({number(layout[0])}, {number(layout[1])})"


def describe(change: Change) -> str:
    """One line for one change."""
    mark = MARKS[change.action]
    if change.action == "renamed":
        return f"{mark} {change.was} renamed to {change.element} ({change.kind})"
    if change.action == "moved":
        return (
            f"{mark} {change.path} moved {position_text(change.old)} -> {position_text(change.new)}"
        )
    if change.action == "changed":
        # The unit once, at the end: `-34 -> -30 m`.
        old, new = leaf_text(change.old), leaf_text(change.new, change.unit)
        return f"{mark} {change.path}: {old} -> {new}"
    noun = "flow" if change.part == "flows" else change.kind
    return f"{mark} {change.path} ({noun}) {change.action}"

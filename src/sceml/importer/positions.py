"""Position elements to SceML positions: WorldPosition and LanePosition; None for the others."""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from ..build import lane, world


def position(holder: etree._Element | None) -> scm.Position | None:
    """The SceML position of a `<Position>` element (or of the element holding one)."""
    if holder is None:
        return None
    if holder.tag != "Position":
        holder = holder.find("Position")
        if holder is None:
            return None
    kind = next((child for child in holder if isinstance(child.tag, str)), None)
    if kind is None:
        return None
    try:
        if kind.tag == "WorldPosition":
            found = world(_num(kind, "x"), _num(kind, "y"), _num(kind, "z", 0.0), 0.0)
            if kind.get("h") is None:
                found.h = None
            else:
                found.h = scm.Value(value=_num(kind, "h"))
            return found
        if kind.tag == "LanePosition":
            return lane(
                str(kind.get("roadId")),
                int(float(str(kind.get("laneId")))),
                _num(kind, "s"),
                _num(kind, "offset", 0.0),
            )
    except ValueError:
        return None
    return None


def _num(element: etree._Element, key: str, default: float | None = None) -> float:
    text = element.get(key)
    if text is None:
        if default is None:
            raise ValueError(key)
        return default
    return float(text)


def number(element: etree._Element, key: str, default: float | None = None) -> float:
    """A numeric attribute (already resolved); ValueError when missing without a default."""
    return _num(element, key, default)

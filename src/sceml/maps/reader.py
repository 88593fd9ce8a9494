"""Read an OpenDRIVE file into `sceml.maps.model` values, refusing what cannot be used.

lxml parses (through SceML's hardened parser and size limit); this module only maps elements to
values and says, with the file and line, what is missing or not a number. The geometry itself is
evaluated in `sceml.maps.planview` by pyclothoids.
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from pathlib import Path

from lxml import etree

from ..errors import LoadError
from ..files.safefiles import read_input
from ..files.safexml import doctype_line, hardened_parser, has_dtd
from .model import (
    Connection,
    Geometry,
    Junction,
    Lane,
    LaneLink,
    LaneSection,
    Poly3,
    Road,
    RoadLink,
)

_GEOMETRY_KINDS = ("line", "arc", "spiral", "poly3", "paramPoly3")


class MapError(LoadError):
    """The map cannot be used: missing, not OpenDRIVE, or an element SceML cannot read."""


def parse_opendrive(
    path: str | os.PathLike[str], roots: Iterable[str | os.PathLike[str]] | None = None
) -> tuple[str, list[Road], list[Junction]]:
    """The OpenDRIVE version ("1.7"), roads and junctions of the file at `path`.

    The file is read by the one reading rule (`sceml.files.safefiles.read_input`): a regular file,
    below one of `roots` when they are given, within the size limit.
    """
    root = _root(Path(path), roots)
    reader = _Reader(str(path))
    header = root.find("header")
    version = "1.?"
    if header is not None:
        version = f"{header.get('revMajor', '1')}.{header.get('revMinor', '?')}"
    roads = [reader.road(element) for element in root.iterfind("road")]
    junctions = [reader.junction(element) for element in root.iterfind("junction")]
    seen: set[str] = set()
    for road in roads:
        if road.id in seen:
            raise MapError(f"road id {road.id!r} is used twice", file=str(path), line=road.line)
        seen.add(road.id)
    return version, roads, junctions


def _root(path: Path, roots: Iterable[str | os.PathLike[str]] | None) -> etree._Element:
    try:
        data = read_input(path, roots=roots, what="map", error=MapError)
    except FileNotFoundError:
        raise MapError("the map file does not exist", file=path) from None
    except IsADirectoryError:
        raise MapError("the map is a folder, not an OpenDRIVE file", file=path) from None
    except OSError as error:
        raise MapError(f"cannot read the map: {error.strerror or error}", file=path) from None
    line = doctype_line(data)
    if line is not None:
        raise MapError("the map declares a DTD, which SceML refuses", file=path, line=line)
    try:
        tree = etree.ElementTree(etree.fromstring(data, hardened_parser(drop_comments=True)))
    except etree.XMLSyntaxError as error:
        line = error.position[0] if error.position else None
        raise MapError(
            f"the map is not well-formed XML: {error.msg}", file=path, line=line
        ) from None
    if has_dtd(tree):
        raise MapError("the map declares a DTD, which SceML refuses", file=path)
    root = tree.getroot()
    if etree.QName(root).localname != "OpenDRIVE":
        raise MapError(
            f"the map is not OpenDRIVE: its root element is <{etree.QName(root).localname}>",
            file=path,
            line=root.sourceline,
        )
    return root


class _Reader:
    """Element-to-value mapping with locations for every refusal."""

    def __init__(self, file: str) -> None:
        self.file = file

    def _fail(self, element: etree._Element, message: str) -> MapError:
        return MapError(message, file=self.file, line=element.sourceline)

    def number(self, element: etree._Element, name: str, default: float | None = None) -> float:
        text = element.get(name)
        if text is None:
            if default is not None:
                return default
            raise self._fail(element, f"<{element.tag}> has no {name}")
        try:
            value = float(text)
        except ValueError:
            raise self._fail(element, f"<{element.tag}> {name}={text!r} is not a number") from None
        if not math.isfinite(value):
            raise self._fail(element, f"<{element.tag}> {name}={text!r} is not a finite number")
        return value

    def text(self, element: etree._Element, name: str) -> str:
        value = element.get(name)
        if value is None:
            raise self._fail(element, f"<{element.tag}> has no {name}")
        return str(value)

    def poly3(self, element: etree._Element, start: str = "sOffset") -> Poly3:
        return Poly3(
            self.number(element, start, 0.0),
            self.number(element, "a", 0.0),
            self.number(element, "b", 0.0),
            self.number(element, "c", 0.0),
            self.number(element, "d", 0.0),
        )

    def road(self, element: etree._Element) -> Road:
        link = element.find("link")
        lanes = element.find("lanes")
        plan_view = element.find("planView")
        if plan_view is None or not len(plan_view.findall("geometry")):
            raise self._fail(element, f"road {element.get('id')!r} has no planView geometry")
        if lanes is None or lanes.find("laneSection") is None:
            raise self._fail(element, f"road {element.get('id')!r} has no lane section")
        return Road(
            id=self.text(element, "id"),
            name=element.get("name", ""),
            length=self.number(element, "length"),
            junction=element.get("junction", "-1"),
            rule=element.get("rule", "RHT"),
            geometries=tuple(self.geometry(g) for g in plan_view.iterfind("geometry")),
            lane_offset=tuple(self.poly3(o, "s") for o in lanes.iterfind("laneOffset")),
            # Some writers (scenariogeneration with uneven lane definitions) list sections out
            # of order; `Road.section_at` needs them by s.
            sections=tuple(
                sorted(
                    (self.section(s) for s in lanes.iterfind("laneSection")),
                    key=lambda section: section.s,
                )
            ),
            predecessor=self.road_link(link, "predecessor"),
            successor=self.road_link(link, "successor"),
            line=element.sourceline,
        )

    def geometry(self, element: etree._Element) -> Geometry:
        shape = next((child for child in element if child.tag in _GEOMETRY_KINDS), None)
        if shape is None:
            raise self._fail(element, "<geometry> has no line, arc, spiral, poly3 or paramPoly3")
        params: dict[str, float | str] = {}
        for name, text in shape.attrib.items():
            if name == "pRange":
                params[name] = text
            else:
                params[name] = self.number(shape, name)
        return Geometry(
            s=self.number(element, "s"),
            x=self.number(element, "x"),
            y=self.number(element, "y"),
            hdg=self.number(element, "hdg"),
            length=self.number(element, "length"),
            kind=str(shape.tag),
            params=params,
            line=element.sourceline,
        )

    def section(self, element: etree._Element) -> LaneSection:
        left = sorted(
            (self.lane(lane) for lane in element.iterfind("left/lane")), key=lambda lane: lane.id
        )
        right = sorted(
            (self.lane(lane) for lane in element.iterfind("right/lane")), key=lambda lane: -lane.id
        )
        return LaneSection(
            self.number(element, "s"), tuple(left), tuple(right), line=element.sourceline
        )

    def lane(self, element: etree._Element) -> Lane:
        lane_id = int(self.number(element, "id"))
        link = element.find("link")

        def linked(kind: str) -> int | None:
            target = link.find(kind) if link is not None else None
            return int(self.number(target, "id")) if target is not None else None

        widths = tuple(self.poly3(width) for width in element.iterfind("width"))
        return Lane(
            id=lane_id,
            type=element.get("type", "none"),
            widths=widths,
            predecessor=linked("predecessor"),
            successor=linked("successor"),
            line=element.sourceline,
        )

    def road_link(self, link: etree._Element | None, kind: str) -> RoadLink | None:
        target = link.find(kind) if link is not None else None
        if target is None:
            return None
        return RoadLink(
            element_type=target.get("elementType", "road"),
            element_id=self.text(target, "elementId"),
            contact_point=target.get("contactPoint"),
        )

    def junction(self, element: etree._Element) -> Junction:
        connections = tuple(
            Connection(
                id=connection.get("id", ""),
                incoming_road=self.text(connection, "incomingRoad"),
                connecting_road=self.text(
                    connection,
                    # A direct junction (OpenDRIVE 1.7) links the incoming road straight to
                    # `linkedRoad`: that road is where its traffic goes on.
                    "linkedRoad"
                    if element.get("type") == "direct" and connection.get("connectingRoad") is None
                    else "connectingRoad",
                ),
                contact_point=connection.get("contactPoint", "start"),
                lane_links=tuple(
                    LaneLink(int(self.number(link, "from")), int(self.number(link, "to")))
                    for link in connection.iterfind("laneLink")
                ),
                line=connection.sourceline,
            )
            for connection in element.iterfind("connection")
        )
        return Junction(
            self.text(element, "id"), element.get("name", ""), connections, element.sourceline
        )

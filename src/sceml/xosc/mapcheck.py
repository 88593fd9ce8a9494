"""The positions of an OpenSCENARIO file against the OpenDRIVE map its LogicFile names.

`check-xosc` runs this after the XSD: a file can pass every schema and still place an actor on a
road the map does not have, which a player then ignores (SPEC §7). Lane positions must name a
road and lane of the map with s on the road and the offset within the lane; world positions must
lie on some lane, within the tolerance the validation rules use. Which kind of lane fits which
entity is judged on the SceML model (SCEML-R004), not here.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Final

from lxml import etree

from ..diagnostics import Diagnostic, Severity
from ..files.safefiles import reading_roots
from ..maps import MapError
from ..maps.reference import is_town_name

if TYPE_CHECKING:
    from ..maps.roadmap import RoadMap

MAP_CODE: Final = "XOSC-MAP"
MAP_SKIPPED_CODE: Final = "XOSC-MAP-SKIPPED"
#: How far outside a lane's edges a world position may lie (the validation rules' tolerance).
TOLERANCE: Final = 0.5


def map_diagnostics(
    tree: etree._ElementTree, path: Path, allow: Iterable[Path] = ()
) -> list[Diagnostic]:
    """Every position of the file that is not on its map; an info when the map is not a file.

    The map is read by the reading rule of models: from the file's folder, its project root and
    `allow` only.
    """
    logic = tree.find("RoadNetwork/LogicFile")
    text = (logic.get("filepath") or "").strip() if logic is not None else ""
    file = str(path)
    if not text or is_town_name(text):
        what = f"LogicFile {text!r} is a simulator town" if text else "there is no LogicFile"
        return [
            Diagnostic(
                Severity.INFO,
                MAP_SKIPPED_CODE,
                f"positions are not checked against a map: {what}",
                file=file,
                line=logic.sourceline if logic is not None else None,
            )
        ]
    from ..maps.roadmap import load_map  # numpy and pyclothoids only when there is a map

    map_path = (path.resolve().parent / text).resolve()
    try:
        road_map = load_map(map_path, reading_roots(path, allow))
    except MapError as error:
        return [
            Diagnostic(
                Severity.ERROR,
                MAP_CODE,
                f"LogicFile {text!r}: {error}",
                path="RoadNetwork/LogicFile",
                file=file,
                line=logic.sourceline if logic is not None else None,
            )
        ]
    values = _parameter_values(tree)
    found = []
    for element in tree.iter("LanePosition", "WorldPosition"):
        problem = _problem(element, values, road_map)
        if problem is not None:
            found.append(
                Diagnostic(
                    Severity.ERROR,
                    MAP_CODE,
                    problem,
                    path=tree.getpath(element),
                    file=file,
                    line=element.sourceline,
                )
            )
    return found


def _parameter_values(tree: etree._ElementTree) -> dict[str, str]:
    """Top-level parameter declarations by name (`$name` in attributes refers to them)."""
    return {
        str(declaration.get("name")): str(declaration.get("value"))
        for declaration in tree.iterfind("ParameterDeclarations/ParameterDeclaration")
    }


def _number(element: etree._Element, name: str, values: dict[str, str]) -> float | None:
    text = element.get(name)
    if text is None:
        return None
    if text.startswith("$") and not text.startswith("${"):
        text = values.get(text[1:], "")
    try:
        number = float(text)
    except ValueError:
        return None  # an expression: its value is the player's business
    return number if math.isfinite(number) else None


def _problem(element: etree._Element, values: dict[str, str], road_map: RoadMap) -> str | None:
    if element.tag == "LanePosition":
        s = _number(element, "s", values)
        offset = _number(element, "offset", values) or 0.0
        road, lane = element.get("roadId"), element.get("laneId")
        if s is None or road is None or lane is None or not lane.lstrip("-").isdigit():
            return None
        problem = road_map.lane_problem(road, int(lane), s, offset)
        return None if problem is None else f"lane position: {problem}"
    x, y = _number(element, "x", values), _number(element, "y", values)
    if x is None or y is None or road_map.world_to_lane(x, y, TOLERANCE):
        return None
    return f"world position ({x:g}, {y:g}) is on no lane of the map"

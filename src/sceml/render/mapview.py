"""The map view: the start situation from above (the paper's Fig. 1a), drawn with matplotlib.

Lanes of the OpenDRIVE map, each actor's bounding box at its start with its heading, the
destinations and waypoints with a dashed line from the actor, and the radius of every location
and vehicle condition. Logical ranges are shaded. matplotlib is imported by this module only, so
the other commands do not pay for it; it draws with the Agg canvas, never a GUI. SVG output is
byte-stable: fixed id salt, no date, text kept as text.
"""

from __future__ import annotations

import io
import math
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import matplotlib
from lxml import etree
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import PolyCollection
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, FancyArrowPatch, Patch, Polygon, Wedge
from matplotlib.text import Annotation

import scemlmodel as scm

from . import style
from .flow import RenderError
from .mapscene import (
    ActorMark,
    CircleMark,
    MapScene,
    Place,
    TargetMark,
    actor_colours,
    build_scene,
    thin,
)

if TYPE_CHECKING:
    from matplotlib.typing import RcKeyType

Extent = Literal["scenario", "map"]
Point = tuple[float, float]
#: Where a label may go: the point it names, its offset in points, its alignment.
_Spot = tuple[
    Point,
    tuple[float, float],
    Literal["left", "center", "right"],
    Literal["bottom", "center", "top"],
]

#: Output formats, by file suffix (the same as the other views).
FORMATS = ("svg", "png", "pdf")

_METADATA: dict[str, dict[str, str | None]] = {
    "svg": {"Date": None},
    "pdf": {"CreationDate": None},
    "png": {},
}
_AXES_INCHES = 6.5
_PNG_DPI = 150


@dataclass
class MapFigure:
    """A drawn map view: the matplotlib figure, and its artists by id (`actor-ego`,
    `circle-InLocationRadius_1`, ...), which are also the SVG group ids."""

    figure: Figure
    axes: Axes
    scene: MapScene
    artists: dict[str, Artist]
    labels: list[tuple[int, Annotation, list[_Spot]]] = field(default_factory=list)


@dataclass(frozen=True)
class MapPicture:
    """The bytes of a map view and the notes about what it could not draw."""

    data: bytes
    notes: tuple[str, ...]


def map_view(
    scenario: scm.Scenario,
    scenario_file: str | Path | None,
    fmt: str = "svg",
    *,
    extent: Extent = "scenario",
) -> MapPicture:
    """The map view of a scenario as SVG, PNG or PDF bytes.

    MapViewError when the scenario's map is a simulator town or missing, MapError when the
    .xodr file cannot be read.
    """
    if fmt not in FORMATS:
        raise RenderError(f"unknown output format {fmt!r}; use one of {', '.join(FORMATS)}")
    scene = build_scene(scenario, scenario_file)
    drawn = draw(scene, extent=extent)
    return MapPicture(to_bytes(drawn, fmt), tuple(scene.notes))


def to_bytes(drawn: MapFigure, fmt: str) -> bytes:
    """The figure in one format; SVG and PDF carry no date."""
    buffer = io.BytesIO()
    with _style():
        drawn.figure.savefig(
            buffer,
            format=fmt,
            dpi=_PNG_DPI,
            metadata=_METADATA.get(fmt, {}),
            facecolor="white",
            bbox_inches="tight",  # the legend, titles and labels decide the picture's edges
            pad_inches=0.15,
        )
    return buffer.getvalue()


def draw(scene: MapScene, *, extent: Extent = "scenario") -> MapFigure:
    """Draw a scene: lanes, radii, targets, actors, legend and title."""
    with _style():
        xmin, ymin, xmax, ymax = scene.extent(extent)
        width, height = _size(xmax - xmin, ymax - ymin)
        figure = Figure(figsize=(width + 3.2, height + 1.0))
        FigureCanvasAgg(figure)
        axes = figure.add_axes(
            (
                0.8 / (width + 3.2),
                0.5 / (height + 1.0),
                width / (width + 3.2),
                height / (height + 1.0),
            )
        )
        drawn = MapFigure(figure, axes, scene, {})
        _frame(axes, (xmin, ymin, xmax, ymax))
        _lanes(drawn)
        colours = actor_colours(scene)
        for circle in scene.circles:
            _circle(drawn, circle, colours.get(circle.actor or "", style.MAP_NEUTRAL_COLOUR))
        for target in scene.targets:
            _target(drawn, target, colours.get(target.actor or "", style.MAP_NEUTRAL_COLOUR))
        for actor in scene.placed_actors():
            _actor(drawn, actor, colours[actor.name])
        _legend(drawn, colours)
        _titles(drawn)
        _declutter(drawn)
    return drawn


@contextmanager
def _style() -> Iterator[None]:
    settings: dict[RcKeyType, Any] = {
        "svg.hashsalt": "sceml-map-view",  # clip-path ids from a fixed salt: the same bytes every run
        "svg.fonttype": "none",  # names stay text: searchable, and readable by tests
        "text.parse_math": False,  # an actor called "$x$" is a name, not a formula
        "font.family": style.FONT,
        "font.size": 8,
    }
    with matplotlib.rc_context(settings):
        yield


def _size(width_m: float, height_m: float) -> tuple[float, float]:
    """Inches of the drawing area, keeping the map's proportions within sensible bounds."""
    ratio = height_m / width_m if width_m > 0 else 1.0
    width, height = _AXES_INCHES, _AXES_INCHES * ratio
    if height > 9.0:
        width, height = 9.0 / ratio, 9.0
    return max(width, 3.0), max(height, 3.0)


def _frame(axes: Axes, box: tuple[float, float, float, float]) -> None:
    axes.set_xlim(box[0], box[2])
    axes.set_ylim(box[1], box[3])  # y grows upwards: north is up
    axes.set_aspect("equal")
    axes.set_facecolor(style.MAP_BACKGROUND)
    axes.set_xlabel("x [m] (east)")
    axes.set_ylabel("y [m] (north)")
    axes.grid(True, color="#e0e0e0", linewidth=0.5, zorder=0)
    axes.set_axisbelow(True)


def _gid(*parts: str) -> str:
    """An SVG id from readable parts: characters an id cannot hold become `_`."""
    return re.sub(r"[^A-Za-z0-9_.-]", "_", "-".join(parts))


def _keep(drawn: MapFigure, artist: Artist, *parts: str) -> Artist:
    gid = _gid(*parts)
    artist.set_gid(gid)
    drawn.artists[gid] = artist
    return artist


def _lanes(drawn: MapFigure) -> None:
    """Lane areas by type (junction lanes first, without edges), then markings on the arms."""
    road_map = drawn.scene.road_map
    groups: dict[tuple[bool, str], list[object]] = {}
    markings = []
    for road in road_map.roads.values():
        in_junction = road.junction not in ("-1", "")
        for section in road.sections:
            outlines = road_map.section_outlines(road, section)
            for lane in section.lanes():
                outline = thin(outlines[lane.id])
                groups.setdefault((in_junction, _lane_group(lane.type)), []).append(outline)
            types = {lane.id: lane.type for lane in section.lanes()}
            if not in_junction and types.get(1) == types.get(-1) == "driving":
                inner = outlines[1]
                markings.append(thin(inner[: len(inner) // 2]))
    order = sorted(groups, key=lambda key: (not key[0], key[1] == "driving", key[1]))
    for in_junction, group in order:
        fill = style.MAP_LANE_FILLS.get(group, style.MAP_OTHER_LANE_FILL)
        collection = PolyCollection(
            groups[(in_junction, group)],  # type: ignore[arg-type]
            facecolors=fill,
            edgecolors=fill if in_junction else style.MAP_LANE_EDGE,
            linewidths=0.3 if in_junction else 0.5,
            zorder=1 if in_junction else 2,
        )
        drawn.axes.add_collection(collection)
        _keep(drawn, collection, "lanes", group, "junction" if in_junction else "roads")
    for index, line in enumerate(markings):
        (marking,) = drawn.axes.plot(
            line[:, 0],
            line[:, 1],
            color=style.MAP_LANE_MARKING,
            linewidth=0.8,
            dashes=(6, 6),
            zorder=3,
        )
        _keep(drawn, marking, "marking", str(index))


def _lane_group(lane_type: str) -> str:
    return lane_type if lane_type in style.MAP_LANE_FILLS else "other"


def _circle(drawn: MapFigure, circle: CircleMark, colour: str) -> None:
    """A radius as a circle; a logical radius as the ring between its ends, with each circle."""
    dash = (0, (4, 2)) if circle.kind == "location" else (0, (1, 1.5))
    low, high = circle.radii[0], circle.radii[-1]
    if high > low:
        ring = Wedge(circle.centre, high, 0, 360, width=high - low)
        ring.set(facecolor=colour, alpha=0.12, edgecolor="none", zorder=4)
        drawn.axes.add_patch(ring)
        _keep(drawn, ring, "ring", circle.node)
    for index, radius in enumerate(circle.radii):
        outline = Circle(circle.centre, radius, fill=False, edgecolor=colour)
        outline.set(linestyle=dash, zorder=5, linewidth=1.2 if radius in (low, high) else 0.6)
        drawn.axes.add_patch(outline)
        _keep(drawn, outline, "circle", circle.node, *([str(index)] if index else []))
    if circle.place is not None:
        _region(drawn, circle.place, colour, circle.node)
    x, y = circle.centre
    label = circle.node + (f" (r {low:g}–{high:g} m)" if high > low else f" (r {high:g} m)")
    top, bottom = (x, y + high), (x, y - high)
    _label(
        drawn,
        label,
        colour,
        ("label", circle.node),
        [
            (top, (0, 2), "center", "bottom"),
            (bottom, (0, -2), "center", "top"),
            (top, (0, -2), "center", "top"),
            ((x + high, y), (3, 0), "left", "center"),
            ((x - high, y), (-3, 0), "right", "center"),
            (top, (0, 12), "center", "bottom"),
            (bottom, (0, -12), "center", "top"),
        ],
        priority=2,
    )


def _target(drawn: MapFigure, target: TargetMark, colour: str) -> None:
    """A destination or waypoint: marker, dashed line from where the actor comes from, label."""
    point = target.place.centre
    if target.origin is not None:
        (route,) = drawn.axes.plot(
            [target.origin[0], point.x],
            [target.origin[1], point.y],
            color=colour,
            linewidth=1.3,
            linestyle=(0, (5, 3)),
            zorder=6,
        )
        _keep(drawn, route, "route", target.node)
    _region(drawn, target.place, colour, target.node)
    marker = "*" if target.kind == "destination" else "o"
    size = 13 if target.kind == "destination" else 7
    (mark,) = drawn.axes.plot(
        [point.x], [point.y], marker=marker, markersize=size, color=colour, zorder=8
    )
    mark.set(markeredgecolor="black", markeredgewidth=0.6, linestyle="none")
    _keep(drawn, mark, "target", target.node)
    if point.heading is not None:
        _arrow(drawn, (point.x, point.y), point.heading, 2.5, colour, "target-heading", target.node)
    _label(drawn, target.node, colour, ("label", target.node), _around((point.x, point.y), 7), 1)


def _actor(drawn: MapFigure, actor: ActorMark, colour: str) -> None:
    """An actor's bounding box at its start, turned to its heading, with an arrow and its name."""
    assert actor.place is not None
    _region(drawn, actor.place, colour, actor.name)
    box = Polygon(actor.corners(), closed=True, facecolor=colour, alpha=0.9, zorder=10)
    box.set(edgecolor="black", linewidth=1.6 if actor.ego else 0.7)
    drawn.axes.add_patch(box)
    _keep(drawn, box, "actor", actor.name)
    point = actor.place.centre
    if point.heading is not None:
        length = max(0.8 * actor.length, 2.5)
        _arrow(drawn, (point.x, point.y), point.heading, length, "black", "heading", actor.name)
    name = actor.name + (" (ego)" if actor.ego and actor.name != "ego" else "")
    text = _label(drawn, name, colour, ("label", actor.name), _around((point.x, point.y), 9), 0)
    text.set(fontsize=8.5, fontweight="bold" if actor.ego else "normal", zorder=11)


def _arrow(
    drawn: MapFigure,
    start: tuple[float, float],
    heading: float,
    length: float,
    colour: str,
    *gid: str,
) -> None:
    tip = (start[0] + length * math.cos(heading), start[1] + length * math.sin(heading))
    arrow = FancyArrowPatch(
        start, tip, arrowstyle="-|>", mutation_scale=10, color=colour, shrinkA=0, shrinkB=0
    )
    arrow.set(linewidth=1.2, zorder=12)
    drawn.axes.add_patch(arrow)
    _keep(drawn, arrow, *gid)


def _region(drawn: MapFigure, place: Place, colour: str, name: str) -> None:
    """The area or segment a logical position spans, shaded and hatched in the owner's colour."""
    if place.region is None:
        return
    points = list(place.region)
    if len(points) <= 2:  # one coordinate varies: a segment, drawn as a broad translucent bar
        (bar,) = drawn.axes.plot(*zip(*points, strict=True), color=colour, linewidth=6, alpha=0.45)
        bar.set(solid_capstyle="butt", zorder=7)
        _keep(drawn, bar, "range", name)
    else:
        region = Polygon(points, closed=True, facecolor=colour, edgecolor=colour)
        region.set(alpha=0.3, hatch="///", linewidth=1.5, zorder=7)
        drawn.axes.add_patch(region)
        _keep(drawn, region, "range", name)
    xs, ys = [p.x for p in place.points], [p.y for p in place.points]
    (ends,) = drawn.axes.plot(xs, ys, marker="|", markersize=6, color=colour, zorder=7)
    ends.set(linestyle="none")
    _keep(drawn, ends, "range-points", name)


def _label(
    drawn: MapFigure,
    text: str,
    colour: str,
    gid: tuple[str, ...],
    candidates: list[_Spot],
    priority: int,
) -> Annotation:
    """A label at the first of its candidate spots; `_declutter` may move it to another."""
    xy, offset, ha, va = candidates[0]
    label = drawn.axes.annotate(text, xy, xytext=offset, textcoords="offset points", ha=ha, va=va)
    label.set(color=colour, fontsize=7, zorder=9, clip_on=True, bbox=_label_box(0.75))
    _keep(drawn, label, *gid)
    drawn.labels.append((priority, label, candidates))
    return label


def _around(point: Point, gap: float) -> list[_Spot]:
    """Spots beside a point: right below, right above, left above, left below, above, below."""
    return [
        (point, (gap, -gap / 2), "left", "top"),
        (point, (gap, gap / 2), "left", "bottom"),
        (point, (-gap, gap / 2), "right", "bottom"),
        (point, (-gap, -gap / 2), "right", "top"),
        (point, (0, gap * 1.2), "center", "bottom"),
        (point, (0, -gap * 1.2), "center", "top"),
    ]


def _declutter(drawn: MapFigure) -> None:
    """Move each label to its first spot that overlaps no actor and no label placed before it
    (actors' names first, then targets', then radii's), inside the frame; else its first spot."""
    renderer = drawn.figure.canvas.get_renderer()  # type: ignore[attr-defined]
    frame = drawn.axes.get_window_extent(renderer)
    taken = [
        artist.get_window_extent(renderer)
        for gid, artist in drawn.artists.items()
        if gid.startswith(("actor-", "target-"))
    ]
    for _priority, label, candidates in sorted(drawn.labels, key=lambda entry: entry[0]):
        for spot in [*candidates, candidates[0]]:
            _move(label, spot)
            box = label.get_window_extent(renderer)
            inside = frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0
            if inside and box.y1 <= frame.y1 and not any(box.overlaps(o) for o in taken):
                break
        taken.append(label.get_window_extent(renderer))


def _move(label: Annotation, spot: _Spot) -> None:
    xy, offset, ha, va = spot
    label.xy = xy
    label.xyann = offset
    label.set_horizontalalignment(ha)
    label.set_verticalalignment(va)


def _label_box(alpha: float) -> dict[str, object]:
    return {"boxstyle": "round,pad=0.15", "facecolor": "white", "edgecolor": "none", "alpha": alpha}


def _legend(drawn: MapFigure, colours: dict[str, str]) -> None:
    scene = drawn.scene
    handles: list[Artist] = [
        Patch(
            facecolor=colours[a.name],
            edgecolor="black",
            label=f"{a.name}: {a.kind}" + ("" if a.place is not None else " (no position)"),
        )
        for a in scene.actors
    ]
    groups = {gid.split("-")[1] for gid in drawn.artists if gid.startswith("lanes-")}
    for group, label in (("driving", "driving lane"), ("sidewalk", "sidewalk"), ("other", "")):
        if group in groups:
            fill = style.MAP_LANE_FILLS.get(group, style.MAP_OTHER_LANE_FILL)
            text = label or "other lane type"
            handles.append(Patch(facecolor=fill, edgecolor=style.MAP_LANE_EDGE, label=text))
    kinds = {target.kind for target in scene.targets}
    neutral = style.MAP_NEUTRAL_COLOUR
    if "destination" in kinds:
        handles.append(_marker("*", 11, "destination (line from the actor)"))
    if "waypoint" in kinds:
        handles.append(_marker("o", 6, "waypoint (line from the previous one)"))
    circle_kinds = {circle.kind for circle in scene.circles}
    if "location" in circle_kinds:
        handles.append(
            Line2D([], [], color=neutral, linestyle=(0, (4, 2)), label="InLocationRadius")
        )
    if "vehicle" in circle_kinds:
        handles.append(
            Line2D([], [], color=neutral, linestyle=(0, (1, 1.5)), label="InVehicleRadius")
        )
    if any(gid.startswith("range-") for gid in drawn.artists):
        handles.append(Patch(facecolor=neutral, alpha=0.3, hatch="///", label="position range"))
    if any(gid.startswith("ring-") for gid in drawn.artists):
        handles.append(Patch(facecolor=neutral, alpha=0.12, label="radius range"))
    legend = drawn.axes.legend(
        handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, fontsize=7.5
    )
    legend.set_title("Legend", prop=FontProperties(size=8, weight="bold"))
    _keep(drawn, legend, "legend")


def _marker(shape: str, size: float, label: str) -> Line2D:
    return Line2D(
        [],
        [],
        marker=shape,
        markersize=size,
        color=style.MAP_NEUTRAL_COLOUR,
        markerfacecolor="white",
        markeredgecolor="black",
        linestyle="none",
        label=label,
    )


def _titles(drawn: MapFigure) -> None:
    scene = drawn.scene
    title = drawn.axes.set_title(
        f"{scene.title} ({scene.level} scenario): start situation", fontsize=11, pad=16
    )
    _keep(drawn, title, "title")
    drawn.axes.text(
        0.5,
        1.008,
        f"map {scene.road_map.path.name}",
        transform=drawn.axes.transAxes,
        ha="center",
        va="bottom",
        fontsize=7.5,
        color="#5f6368",
    )
    if not scene.placed_actors():
        note = drawn.axes.text(
            0.5,
            0.97,
            "The actors have no positions: only the map is drawn.",
            transform=drawn.axes.transAxes,
            ha="center",
            va="top",
            fontsize=9,
            bbox=_label_box(0.9),
            zorder=20,
        )
        _keep(drawn, note, "note")


def inline_svg(svg: bytes) -> str:
    """The SVG element as text for an HTML page, without matplotlib's page-wide style sheet."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
    root = etree.fromstring(svg, parser=parser)
    for sheet in root.iter("{http://www.w3.org/2000/svg}style"):
        sheet.getparent().remove(sheet)
    text: str = etree.tostring(root, encoding="unicode")
    return text

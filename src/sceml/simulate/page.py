"""The preview page: one self-contained HTML file that plays a run over the map.

The map comes from the map view's scene (render.mapscene: lanes, destinations, condition radii,
actor colours), drawn here as plain SVG in map metres so the page's script can move the actors
by setting a transform. Everything is inline (SVG, data, script): the page needs no network.
"""

from __future__ import annotations

import json
from html import escape
from pathlib import Path
from typing import Any

import numpy as np

import scemlmodel as scm

from ..errors import SceMLError
from ..render import style
from ..render.mapscene import MapScene, actor_colours, build_scene, thin
from ..templating import template
from .run import Run
from .timeline import timeline_svg

TEMPLATE = "simulate.html.j2"
_MARGIN = 6.0  # m around what the run uses
Box = tuple[float, float, float, float]


def preview_page(run: Run, scenario: scm.Scenario, scenario_file: str | Path | None) -> str:
    """The HTML page that plays `run` (of `scenario`, read from `scenario_file`)."""
    notes = list(run.notes)
    scene: MapScene | None
    try:
        scene = build_scene(scenario, scenario_file)
        notes.extend(scene.notes)
    except SceMLError as error:
        scene = None
        notes.append(f"no map drawn: {error.message}")
    colours = _colours(run, scene)
    box = _extent(run, scene)
    return template(TEMPLATE).render(
        title=f"{run.scenario}: preview",
        file=Path(scenario_file).name if scenario_file is not None else "",
        run=run,
        map_svg=_map_svg(run, scene, colours, box),
        timeline_svg=timeline_svg(run, cursor=True),
        data=_data_json(run, colours),
        metrics=[_metric_row(m) for m in run.metrics],
        notes=notes,
    )


def _colours(run: Run, scene: MapScene | None) -> dict[str, str]:
    known = actor_colours(scene) if scene is not None else {}
    others = iter(style.MAP_ACTOR_COLOURS * (len(run.actors) + 1))
    return {
        a.name: known.get(a.name) or (style.MAP_EGO_COLOUR if a.ego else next(others))
        for a in run.actors
    }


def _extent(run: Run, scene: MapScene | None) -> Box:
    xs, ys = run.states[:, :, 0], run.states[:, :, 1]
    boxes = [(float(xs.min()), float(ys.min()), float(xs.max()), float(ys.max()))]
    if scene is not None:
        boxes.append(scene.extent("scenario"))
    return (
        min(b[0] for b in boxes) - _MARGIN,
        min(b[1] for b in boxes) - _MARGIN,
        max(b[2] for b in boxes) + _MARGIN,
        max(b[3] for b in boxes) + _MARGIN,
    )


def _points(points: Any) -> str:
    return " ".join(f"{x:.2f},{y:.2f}" for x, y in points)


def _map_svg(run: Run, scene: MapScene | None, colours: dict[str, str], box: Box) -> str:
    """The map in metres: y is flipped by the group transform, so north is up."""
    xmin, ymin, xmax, ymax = box
    width, height = xmax - xmin, ymax - ymin
    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" id="map" role="img" '
        f'aria-label="Map of {escape(run.scenario)}" viewBox="{xmin:.2f} {-ymax:.2f} '
        f'{width:.2f} {height:.2f}" preserveAspectRatio="xMidYMid meet">',
        f'<rect x="{xmin:.2f}" y="{-ymax:.2f}" width="{width:.2f}" height="{height:.2f}" '
        f'fill="{style.MAP_BACKGROUND}"/>',
        '<g transform="scale(1,-1)">',
    ]
    if scene is not None:
        parts.extend(_lanes(scene))
        parts.extend(_targets(scene, colours))
    for index, actor in enumerate(run.actors):
        path = run.states[index, :, :2]
        parts.append(
            f'<polyline class="trail" points="{_points(path[:: max(1, len(path) // 400)])}" '
            f'fill="none" stroke="{colours[actor.name]}" stroke-width="0.25" '
            'stroke-opacity="0.45" stroke-dasharray="0.8 0.6"/>'
        )
    for metrics in run.metrics:
        if metrics.collision_time is not None:
            k = int(np.searchsorted(run.times, metrics.collision_time))
            a, b = run.actor_index(metrics.a), run.actor_index(metrics.b)
            x = (run.states[a, k, 0] + run.states[b, k, 0]) / 2
            y = (run.states[a, k, 1] + run.states[b, k, 1]) / 2
            parts.append(
                f'<circle class="collision" cx="{x:.2f}" cy="{y:.2f}" r="1.6" fill="none" '
                'stroke="#d93025" stroke-width="0.5"/>'
            )
    for actor in run.actors:
        colour = colours[actor.name]
        # The states are the reference point; the box's centre lies box_ahead metres ahead.
        front = actor.box_ahead + actor.length / 2
        back = front - min(0.8, actor.length / 2)
        parts.append(
            f'<g class="actor" id="actor-{escape(actor.name)}" data-actor="{escape(actor.name)}">'
            f'<rect x="{front - actor.length:.3f}" y="{-actor.width / 2:.3f}" '
            f'width="{actor.length:.3f}" height="{actor.width:.3f}" fill="{colour}" '
            'fill-opacity="0.85" stroke="#202124" stroke-width="0.15"/>'
            f'<polygon points="{front:.3f},0 {back:.3f},'
            f"{actor.width / 3:.3f} {back:.3f},"
            f'{-actor.width / 3:.3f}" fill="#ffffff"/></g>'
        )
    parts.append("</g>")
    for actor in run.actors:
        parts.append(
            f'<text class="actor-label" id="label-{escape(actor.name)}" font-size="2.2" '
            f'font-family="DejaVu Sans, sans-serif" fill="#202124" stroke="#ffffff" '
            f'stroke-width="0.5" paint-order="stroke">{escape(actor.name)}</text>'
        )
    parts.append("</svg>")
    return "".join(parts)


def _lanes(scene: MapScene) -> list[str]:
    road_map = scene.road_map
    parts = []
    for in_junction in (True, False):
        for road in road_map.roads.values():
            if (road.junction not in ("-1", "")) != in_junction:
                continue
            for section in road.sections:
                outlines = road_map.section_outlines(road, section)
                for lane in section.lanes():
                    fill = style.MAP_LANE_FILLS.get(lane.type, style.MAP_OTHER_LANE_FILL)
                    edge = fill if in_junction else style.MAP_LANE_EDGE
                    outline = thin(outlines[lane.id])
                    parts.append(
                        f'<polygon points="{_points(outline)}" fill="{fill}" stroke="{edge}" '
                        f'stroke-width="{0.05 if in_junction else 0.1}"/>'
                    )
    return parts


def _targets(scene: MapScene, colours: dict[str, str]) -> list[str]:
    parts = []
    for circle in scene.circles:
        colour = colours.get(circle.actor or "", style.MAP_NEUTRAL_COLOUR)
        x, y = circle.centre
        parts.append(
            f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{max(circle.radii):.2f}" fill="{colour}" '
            f'fill-opacity="0.08" stroke="{colour}" stroke-width="0.15" stroke-dasharray="0.6 0.4"/>'
        )
    for target in scene.targets:
        colour = colours.get(target.actor or "", style.MAP_NEUTRAL_COLOUR)
        point = target.place.centre
        parts.append(
            f'<path d="M{point.x - 0.8:.2f},{point.y - 0.8:.2f} l1.6,1.6 m0,-1.6 l-1.6,1.6" '
            f'stroke="{colour}" stroke-width="0.35"/>'
        )
    return parts


def _data_json(run: Run, colours: dict[str, str]) -> str:
    """The run as the page's script reads it; `<` escaped so the data cannot end the script."""
    data = {
        "times": np.round(run.times, 3).tolist(),
        "end": run.end_time,
        "actors": [
            {
                "name": a.name,
                "colour": colours[a.name],
                "x": np.round(run.states[i, :, 0], 3).tolist(),
                "y": np.round(run.states[i, :, 1], 3).tolist(),
                "heading": np.round(np.degrees(run.states[i, :, 2]), 2).tolist(),
                "speed": np.round(run.states[i, :, 3], 2).tolist(),
            }
            for i, a in enumerate(run.actors)
        ],
    }
    return json.dumps(data, separators=(",", ":")).replace("<", "\\u003c")


def _metric_row(metrics: Any) -> dict[str, str]:
    def seconds(value: float | None) -> str:
        return "—" if value is None else f"{value:.2f} s"

    ttc = (
        "—"
        if metrics.min_ttc is None
        else f"{metrics.min_ttc:.2f} s at {metrics.min_ttc_time:.2f} s"
    )
    return {
        "pair": f"{metrics.a} – {metrics.b}",
        "distance": f"{metrics.min_distance:.2f} m at {metrics.min_distance_time:.2f} s",
        "ttc": ttc,
        "pet": seconds(metrics.pet),
        "collision": f"yes, at {metrics.collision_time:.2f} s" if metrics.collision else "no",
    }

"""The review report's preview figure: the timeline of a run and its metrics (`sceml report`)."""

from __future__ import annotations

from html import escape

import scemlmodel as scm

from ..errors import SceMLError
from ..model.documents import Document
from ..model.graph import scenario_level
from ..simulate.preview import simulate
from ..simulate.run import Run
from ..simulate.timeline import LABEL, ROW, WIDTH, timeline_svg
from .figure import Figure

TITLE = "Preview run"
ANCHOR = "preview-run"


def report_figure(document: Document) -> Figure | None:
    """The run's timeline and metrics; None unless the scenario is concrete and its map (if it
    names one) can be read. A scenario the preview refuses gets a note saying why."""
    scenario = document.root
    if not isinstance(scenario, scm.Scenario):
        return None
    if scenario_level(scenario) != "concrete":
        return None
    try:
        run = simulate(scenario, document.path)
    except SceMLError as error:
        return Figure(TITLE, ANCHOR, "", f"No preview run: {error.message}.")
    note = (
        f"Kinematic preview (not a vehicle-dynamics simulation): ended at {run.end_time:.2f} s "
        f"by the {run.end_reason}. `sceml simulate` plays it over the map."
    )
    return Figure(TITLE, ANCHOR, _with_metrics(run), note)


def metric_lines(run: Run) -> list[str]:
    """One line per pair of actors."""
    lines = []
    for m in run.metrics:
        ttc = "—" if m.min_ttc is None else f"{m.min_ttc:.2f} s at {m.min_ttc_time:.2f} s"
        pet = "—" if m.pet is None else f"{m.pet:.2f} s"
        hit = f"collision at {m.collision_time:.2f} s" if m.collision else "no collision"
        lines.append(
            f"{m.a} – {m.b}: least distance {m.min_distance:.2f} m at "
            f"{m.min_distance_time:.2f} s · least TTC {ttc} · PET {pet} · {hit}"
        )
    return lines


def _with_metrics(run: Run) -> str:
    """The timeline SVG with the metrics as text lines below it."""
    svg = timeline_svg(run)
    lines = metric_lines(run)
    head, _, _ = svg.partition(">")
    rows = len([r for r in run.timeline if r.kind != "RootNode"])
    top = ROW * rows + 34
    height = top + 16 * len(lines) + 8
    width = LABEL + WIDTH + 20
    text = "".join(
        f'<text class="metric" x="4" y="{top + 14 + 16 * i}">{escape(line)}</text>'
        for i, line in enumerate(lines)
    )
    body = svg[len(head) + 1 : -len("</svg>")]
    head = (
        f'<svg xmlns="http://www.w3.org/2000/svg" class="sceml-timeline" width="{width}" '
        f'height="{height}" viewBox="0 0 {width} {height}" '
        'font-family="DejaVu Sans, sans-serif" font-size="11"'
    )
    return f"{head}>{body}{text}</svg>"

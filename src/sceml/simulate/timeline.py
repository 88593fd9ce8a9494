"""The timeline of a run as an SVG Gantt chart: one row per node, a bar from start to finish.

Bars take the notation's category colours (render.style). A node still running when the run
ended is drawn open to the end, hatched; one never started has no bar. Rows carry their times
(`data-start`, `data-finish`), so the preview page can mark the nodes running at its clock.
"""

from __future__ import annotations

from html import escape

from ..model import catalog
from ..render import style
from .run import NodeRecord, Run

ROW = 18  # px per node
LABEL = 290  # px for the node names
_NAME_CHARS = 46  # a longer label is shortened (the row's tooltip has it all)
WIDTH = 560  # px of the time axis
_OTHER_FILL = "#bdc1c6"


def shown_nodes(run: Run) -> list[NodeRecord]:
    """The nodes the timeline lists: all but the root, in order of start (never-started last)."""
    records = [r for r in run.timeline if r.kind != "RootNode"]
    return sorted(records, key=lambda r: (r.started is None, r.started or 0.0))


def timeline_svg(run: Run, *, cursor: bool = False) -> str:
    """The timeline as an inline SVG element; `cursor` adds a time line the page moves."""
    rows = shown_nodes(run)
    span = max(run.end_time, run.step)
    scale = WIDTH / span
    height = ROW * len(rows) + 34
    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" class="sceml-timeline" width="{LABEL + WIDTH + 20}" '
        f'height="{height}" viewBox="0 0 {LABEL + WIDTH + 20} {height}" '
        'font-family="DejaVu Sans, sans-serif" font-size="11">',
        '<defs><pattern id="open-end" width="6" height="6" patternUnits="userSpaceOnUse" '
        'patternTransform="rotate(45)"><rect width="3" height="6" fill="#9aa0a6"/></pattern></defs>',
    ]
    for index, record in enumerate(rows):
        parts.append(_row(record, index, scale, run.end_time))
    axis_y = ROW * len(rows) + 4
    parts.append(
        f'<line x1="{LABEL}" y1="{axis_y}" x2="{LABEL + WIDTH}" y2="{axis_y}" stroke="#5f6368"/>'
    )
    for tick in _ticks(span):
        x = LABEL + tick * scale
        parts.append(
            f'<line x1="{x:.1f}" y1="{axis_y}" x2="{x:.1f}" y2="{axis_y + 4}" stroke="#5f6368"/>'
            f'<text x="{x:.1f}" y="{axis_y + 15}" text-anchor="middle">{tick:g} s</text>'
        )
    if cursor:
        parts.append(
            f'<line id="timeline-cursor" x1="{LABEL}" y1="0" x2="{LABEL}" y2="{axis_y}" '
            f'stroke="#d93025" stroke-width="1.5" data-scale="{scale:.6f}" data-left="{LABEL}"/>'
        )
    parts.append("</svg>")
    return "".join(parts)


def _row(record: NodeRecord, index: int, scale: float, end: float) -> str:
    y = index * ROW
    who = f" ({record.actor})" if record.actor else ""
    fill = style.CATEGORY_FILLS.get(catalog.category(record.kind) or "", _OTHER_FILL)
    start = "" if record.started is None else f"{record.started:g}"
    finish = "" if record.finished is None else f"{record.finished:g}"
    title = escape(_describe(record))
    out = [
        f'<g class="timeline-row" data-node="{escape(record.name)}" data-start="{start}" '
        f'data-finish="{finish}"><title>{title}</title>',
        f'<rect class="row-back" x="0" y="{y}" width="{LABEL + WIDTH}" height="{ROW}" fill="none"/>',
        f'<text x="4" y="{y + 13}">{escape(_shorten(record.name + who))}</text>',
    ]
    if record.started is not None:
        x0 = LABEL + record.started * scale
        stop = record.finished if record.finished is not None else end
        bar = max((stop - record.started) * scale, 2.0)
        paint = fill if record.finished is not None else "url(#open-end)"
        out.append(
            f'<rect x="{x0:.1f}" y="{y + 3}" width="{bar:.1f}" height="{ROW - 6}" '
            f'fill="{paint}" stroke="#3c4043" stroke-width="0.6"/>'
        )
    out.append("</g>")
    return "".join(out)


def _shorten(text: str) -> str:
    return text if len(text) <= _NAME_CHARS else "…" + text[-(_NAME_CHARS - 1) :]


def _describe(record: NodeRecord) -> str:
    started = "never started" if record.started is None else f"started {record.started:g} s"
    finished = "did not finish" if record.finished is None else f"finished {record.finished:g} s"
    note = f"; {record.note}" if record.note else ""
    return f"{record.name} ({record.kind}): {started}, {finished}{note}"


def _ticks(span: float) -> list[float]:
    step = next(s for s in (0.5, 1, 2, 5, 10, 20, 30, 60, 120, 300, 600) if span / s <= 12)
    count = int(span / step + 1e-9)
    return [round(i * step, 6) for i in range(count + 1)]

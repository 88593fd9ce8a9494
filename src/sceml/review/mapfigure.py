"""The review page's map view figure (`sceml report`), drawn by `render.mapview`."""

from __future__ import annotations

from pathlib import Path

import scemlmodel as scm

from ..maps import MapError
from ..model.documents import Document
from ..render.mapscene import MapViewError, build_scene
from ..render.mapview import draw, inline_svg, to_bytes
from .figure import Figure as ReportFigure

REPORT_TITLE = "Map view"
REPORT_ANCHOR = "map-view"


def report_figure(document: Document) -> ReportFigure:
    """The map view as a report figure; without a picture, a note saying why there is none."""
    scenario = document.root
    if not isinstance(scenario, scm.Scenario):
        return ReportFigure(REPORT_TITLE, REPORT_ANCHOR, "", "module libraries have no map view")
    try:
        scene = build_scene(scenario, document.path)
        svg = to_bytes(draw(scene), "svg")
    except MapViewError as error:
        return ReportFigure(REPORT_TITLE, REPORT_ANCHOR, "", f"No map view: {error.message}.")
    except MapError as error:
        where = Path(error.file).name if error.file else "the map"
        where += f":{error.line}" if error.line else ""
        note = f"No map view: {where}: {error.message}."
        return ReportFigure(REPORT_TITLE, REPORT_ANCHOR, "", note)
    note = "; ".join(scene.notes)
    return ReportFigure(REPORT_TITLE, REPORT_ANCHOR, inline_svg(svg), note)

"""The figures `sceml report` adds after the diagram."""

from __future__ import annotations

import scemlmodel as scm

from ..model.documents import Document
from .figure import Figure


def report_figures(document: Document) -> list[Figure]:
    """The figures `sceml report` adds after the diagram: a scenario's map view (or why none),
    and for a concrete scenario the preview run's timeline and metrics."""
    if not isinstance(document.root, scm.Scenario):
        return []
    # matplotlib is loaded only when a scenario's report is made.
    from .mapfigure import report_figure
    from .preview import report_figure as preview_figure

    preview = preview_figure(document)
    return [report_figure(document), *([preview] if preview is not None else [])]

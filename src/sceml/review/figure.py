"""A figure of the review page: what a figure module hands to the page, and nothing more.

Kept apart from `page` so that the figure makers (map view, preview run) and the page both read
it without importing each other.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Figure:
    """An extra figure of the report, shown after the diagram under its own heading.

    `svg` is an inline SVG element as text (trusted: made by sceml, never by the input file),
    or empty when there is no picture; `note` is shown with it (e.g. why there is no picture);
    `anchor` is the HTML id of the figure's box, so a page can link to it.
    """

    title: str
    anchor: str
    svg: str
    note: str = ""

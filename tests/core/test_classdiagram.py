"""The class diagrams show every class of the .ecore, so they cannot silently drift from it."""

from __future__ import annotations

from pathlib import Path

from lxml import etree

from sceml.dev.classdiagram import VIEWS, class_diagram
from sceml.model import catalog

DOCS = Path(__file__).resolve().parents[2] / "docs"


def test_every_class_appears_in_some_view() -> None:
    shown = {name for names in VIEWS.values() for name in names}
    assert set(catalog._ecore_classes()) == shown


def test_views_draw_their_classes_and_inheritance() -> None:
    svg = etree.fromstring(class_diagram("actions").pipe(format="svg"))
    titles = {t.text for t in svg.iter("{http://www.w3.org/2000/svg}title")}
    assert {"Accelerate", "TimeToCollision", "Accelerate->LongitudinalManeuver"} <= titles


def test_committed_pictures_exist_for_every_view() -> None:
    for view in VIEWS:
        assert (DOCS / "metamodel" / f"{view}.png").stat().st_size > 10_000
        assert f"metamodel/{view}.png" in (DOCS / "metamodel.md").read_text()

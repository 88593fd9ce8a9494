"""Helpers for the render tests: parse Graphviz SVG and find the groups SceML marks with classes."""

from __future__ import annotations

from lxml import etree

SVG = "{http://www.w3.org/2000/svg}"


def parse(svg: bytes) -> etree._Element:
    """The SVG root element (Graphviz writes a DOCTYPE, which is not loaded)."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
    return etree.fromstring(svg, parser=parser)


def groups(root: etree._Element, css_class: str) -> list[etree._Element]:
    """The <g> elements whose class list contains `css_class`."""
    return [g for g in root.iter(f"{SVG}g") if css_class in (g.get("class") or "").split()]


def text_of(group: etree._Element) -> str:
    """All label text inside a group, joined by spaces."""
    return " ".join("".join(t.itertext()) for t in group.iter(f"{SVG}text"))


def fills(group: etree._Element) -> set[str]:
    """The fill colours of a group's shapes."""
    return {
        shape.get("fill")
        for tag in ("polygon", "ellipse", "path")
        for shape in group.iter(f"{SVG}{tag}")
        if shape.get("fill") not in (None, "none")
    }

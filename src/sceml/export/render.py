"""The OpenSCENARIO template (through the shared Jinja environment) and the text-to-tree step."""

from __future__ import annotations

from functools import cache

import jinja2
from lxml import etree

from ..files.safexml import hardened_parser
from ..templating import environment
from .viewmodel import View

TEMPLATE = "openscenario.xosc.j2"
_DECLARATION = b'<?xml version="1.0" encoding="UTF-8"?>\n'


@cache
def _template() -> jinja2.Template:
    return environment().get_template(TEMPLATE)


def _parser() -> etree.XMLParser:
    # The text is our own, but the parser is locked down anyway; blank text is dropped so the
    # tree pretty-prints with consistent indentation.
    return hardened_parser(drop_blank_text=True)


def render_text(view: View) -> str:
    """The document as rendered by the template (unindented)."""
    return _template().render(view=view)


def render_tree(view: View) -> etree._ElementTree:
    """The document parsed once into an lxml tree."""
    root = etree.fromstring(render_text(view).encode("utf-8"), _parser())
    return etree.ElementTree(root)


def serialise(tree: etree._ElementTree) -> bytes:
    """Indented UTF-8 bytes with an XML declaration: the bytes written to disk."""
    body: bytes = etree.tostring(tree, pretty_print=True, xml_declaration=False, encoding="UTF-8")
    return _DECLARATION + body

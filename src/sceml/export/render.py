"""The Jinja environment (compiled once per process) and the text-to-tree step."""

from __future__ import annotations

from functools import cache

import jinja2
from lxml import etree

from .viewmodel import View

TEMPLATE = "openscenario.xosc.j2"
_DECLARATION = b'<?xml version="1.0" encoding="UTF-8"?>\n'


@cache
def environment() -> jinja2.Environment:
    """Jinja with StrictUndefined and XML autoescaping; templates come from `sceml.templates`."""
    return jinja2.Environment(
        loader=jinja2.PackageLoader("sceml.templates", "."),
        undefined=jinja2.StrictUndefined,
        autoescape=True,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=False,
    )


@cache
def _template() -> jinja2.Template:
    return environment().get_template(TEMPLATE)


def _parser() -> etree.XMLParser:
    # The text is our own, but the parser is locked down anyway; blank text is dropped so the
    # tree pretty-prints with consistent indentation.
    return etree.XMLParser(
        remove_blank_text=True, resolve_entities=False, no_network=True, load_dtd=False
    )


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

"""Opaque nodes (what `sceml import` keeps verbatim): well-formed, and exported where they fit."""

from __future__ import annotations

from collections.abc import Iterator

from lxml import etree

import scemlmodel as scm

from ..diagnostics import Severity
from ..files.safexml import hardened_parser
from .context import Context
from .reads import SELF, Reads
from .registry import Finding, constraint

#: What an OpaqueAction may hold: one element, the node performs it or waits for it.
KEPT_ELEMENTS = ("Action", "Condition")


def kept_element(text: str) -> etree._Element | None:
    """The element an opaque node keeps, or None when it is not one Action or Condition."""
    try:
        element = etree.fromstring(text.encode("utf-8"), hardened_parser())
    except (etree.XMLSyntaxError, ValueError):
        return None
    children = [child for child in element if isinstance(child.tag, str)]
    return element if element.tag in KEPT_ELEMENTS and len(children) == 1 else None


@constraint(
    "SCEML-E006",
    Severity.ERROR,
    "OpaqueAction",
    "an opaque node holds one well-formed OpenSCENARIO Action or Condition element",
    source="SPEC §13",
    reads=Reads(SELF),
)
def opaque_holds_one_element(node: scm.OpaqueAction, context: Context) -> Iterator[Finding]:
    if kept_element(str(node.xml or "")) is None:
        yield (
            node,
            (
                f"opaque node {node.name!r} must hold one OpenSCENARIO <Action> or <Condition> "
                "element with one child; it cannot be exported"
            ),
        )


@constraint(
    "SCEML-E007",
    Severity.WARNING,
    "OpaqueAction",
    "an opaque node is exported to the OpenSCENARIO version it was read from",
    source="SPEC §13",
    # the node's or actor's own controller, activation and overrides (contents)
    reads=Reads(SELF),
)
def opaque_keeps_its_version(node: scm.OpaqueAction, context: Context) -> Iterator[Finding]:
    wanted, read = context.osc_version, node.sourceVersion
    if wanted and read and wanted != read:
        yield (
            node,
            (
                f"opaque node {node.name!r} was read from OpenSCENARIO {read}; its element is "
                f"written unchanged, so an export to {wanted} may not fit that version's XSD"
            ),
        )

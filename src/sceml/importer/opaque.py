"""Opaque nodes: an Action or Condition with no SceML kind, kept verbatim with its line."""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from ..xosc.kept import key_values, kind_text
from .context import Build, kept_xml


def opaque_node(
    build: Build,
    element: etree._Element,
    actor: scm.Participant,
    wanted: str,
    why: str,
    where: tuple[str, int | None] | None = None,
) -> scm.OpaqueAction:
    """An OpaqueAction holding `element` (an Action or Condition), added to the scenario.

    `where` is the file and line to report when `element` was made here (a wrapper).
    """
    file, line = where or build.where(element)
    node = scm.OpaqueAction(
        xml=kept_xml(element), sourceLine=line, sourceVersion=build.source.version
    )
    node.referenceActor = actor
    build.add(node, wanted)
    build.report.add(
        "opaque",
        f"{node.name}: <{kind_text(element)}{_spaced(key_values(element))}> kept verbatim ({why})",
        (file, line),
        node.name,
    )
    return node


def _spaced(text: str) -> str:
    return f" {text}" if text else ""


def summary(element: etree._Element) -> str:
    """What an opaque element is, in a few words (for labels and the report)."""
    return kind_text(element)

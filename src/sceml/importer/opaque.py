"""Opaque nodes: an Action or Condition with no SceML kind, kept verbatim with its line."""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

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
        f"{node.name}: <{_summary(element)}> kept verbatim ({why})",
        (file, line),
        node.name,
    )
    return node


def _summary(element: etree._Element) -> str:
    """The element's tag and what it does, e.g. `Condition TimeHeadwayCondition`."""
    for inner in element.iterdescendants():
        tag = inner.tag
        if isinstance(tag, str) and tag.endswith(("Action", "Condition")) and tag not in WRAPPERS:
            return f"{element.tag} {tag}"
    return str(element.tag)


#: Elements that only group an action or condition; they say nothing about what it does.
WRAPPERS = frozenset(
    {
        "PrivateAction",
        "GlobalAction",
        "LongitudinalAction",
        "LateralAction",
        "RoutingAction",
        "EntityAction",
        "InfrastructureAction",
        "ByEntityCondition",
        "ByValueCondition",
        "EntityCondition",
    }
)


def summary(element: etree._Element) -> str:
    """What an opaque element is, in a few words (for labels and the report)."""
    return _summary(element)

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
        f"{node.name}: <{_summary(element)}{_spaced(key_values(element))}> kept verbatim ({why})",
        (file, line),
        node.name,
    )
    return node


def _summary(element: etree._Element) -> str:
    """The element's tag and what it does, e.g. `Condition TimeHeadwayCondition`."""
    inner = _inner(element)
    return str(element.tag) if inner is None else f"{element.tag} {inner.tag}"


def _inner(element: etree._Element) -> etree._Element | None:
    for inner in element.iterdescendants():
        tag = inner.tag
        if isinstance(tag, str) and tag.endswith(("Action", "Condition")) and tag not in WRAPPERS:
            return inner
    return None


#: Key values shown per opaque element (the rest stays in its XML).
_SHOWN = 6


def key_values(element: etree._Element) -> str:
    """The action's or condition's own attributes, e.g. `value=0.4 rule=lessThan`, so that an
    opaque node says what it waits for or does, not only its type."""
    inner = _inner(element)
    if inner is None:
        return ""
    pairs = [(k, v) for k, v in inner.attrib.items() if isinstance(k, str) and "}" not in k]
    for child in inner.iterdescendants():  # the first valued child (a target, a dynamics)
        if isinstance(child.tag, str) and child.attrib and len(pairs) < _SHOWN:
            pairs += [(f"{child.tag}.{k}", v) for k, v in child.attrib.items() if "}" not in k]
            break
    return " ".join(f"{k}={v}" for k, v in pairs[:_SHOWN])


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


def _spaced(text: str) -> str:
    return f" {text}" if text else ""


def summary(element: etree._Element) -> str:
    """What an opaque element is, in a few words (for labels and the report)."""
    return _summary(element)

"""What a kept OpenSCENARIO Action or Condition is, in a few words: its kind and key values.

One source for the import report and the opaque node's box (render/labels.py), so both say
the same of an element SceML has no kind for.
"""

from __future__ import annotations

from lxml import etree

#: Elements that only group an action or condition; they say nothing about what it does.
WRAPPERS = frozenset(
    {
        "PrivateAction",
        "GlobalAction",
        "UserDefinedAction",
        "LongitudinalAction",
        "LateralAction",
        "RoutingAction",
        "AppearanceAction",
        "ControllerAction",
        "EntityAction",
        "InfrastructureAction",
        "TrafficSignalAction",
        "ByEntityCondition",
        "ByValueCondition",
        "EntityCondition",
    }
)
#: Key values shown per element (the rest stays in its XML).
SHOWN = 6


def inner(element: etree._Element) -> etree._Element | None:
    """The action or condition an Action or Condition element holds, past its wrappers."""
    for found in element.iterdescendants():
        tag = found.tag
        if isinstance(tag, str) and tag.endswith(("Action", "Condition")) and tag not in WRAPPERS:
            return found
    return None


def kind_text(element: etree._Element) -> str:
    """The element's tag and what it does, e.g. `Condition TimeHeadwayCondition`."""
    held = inner(element)
    return str(element.tag) if held is None else f"{element.tag} {held.tag}"


def key_values(element: etree._Element) -> str:
    """The action's or condition's own attributes, e.g. `value=0.4 rule=lessThan`, then those
    of its first valued child (a target, a dynamics, a light), so that what is kept says what
    it waits for or does, not only its type."""
    held = inner(element)
    if held is None:
        return ""
    pairs = [(k, v) for k, v in held.attrib.items() if isinstance(k, str) and "}" not in k]
    for child in held.iterdescendants():
        if isinstance(child.tag, str) and child.attrib and len(pairs) < SHOWN:
            pairs += [(f"{child.tag}.{k}", v) for k, v in child.attrib.items() if "}" not in k]
            break
    return " ".join(f"{k}={v}" for k, v in pairs[:SHOWN])

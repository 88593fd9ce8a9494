"""OpaqueAction: an OpenSCENARIO Action or Condition kept verbatim by `sceml import`, written back.

An Action element becomes the node's event (it finishes when the action completes); a Condition
element becomes a marker event that fires once the node is activated and the condition holds, as
every condition node does (docs/import.md), or, where the node is inlined
(`xosc.flows.inlined`), in its successor's trigger. Only the element's `name` is replaced, so that names
stay unique in the written document; everything else is the text that was read.
"""

from __future__ import annotations

from lxml import etree
from markupsafe import Markup

import scemlmodel as scm

from ..files.safexml import hardened_parser
from .actions import Plan, marker_plan, planner
from .context import Action, Context, Event
from .triggers import Condition, Group


class OpaqueElementError(ValueError):
    """The node's `xml` is not one OpenSCENARIO Action or Condition element."""


def element_of(node: scm.OpaqueAction) -> etree._Element:
    """The stored element, parsed with the hardened parser."""
    try:
        element = etree.fromstring(str(node.xml or "").encode("utf-8"), hardened_parser())
    except etree.XMLSyntaxError as error:
        raise OpaqueElementError(f"{node.name}: its xml is not well-formed: {error}") from None
    if element.tag not in ("Action", "Condition"):
        raise OpaqueElementError(
            f"{node.name}: its xml is a <{element.tag}>, not an Action or Condition"
        )
    return element


def _body(element: etree._Element) -> Markup:
    """The element's single child (GlobalAction, PrivateAction, ByEntityCondition, ...)."""
    children = [child for child in element if isinstance(child.tag, str)]
    if len(children) != 1:
        raise OpaqueElementError(f"<{element.tag}> must hold exactly one element")
    # lxml's serialisation of a parsed element is well-formed XML; the written document is
    # parsed and checked against the XSD as a whole afterwards.
    return Markup(etree.tostring(children[0], encoding="unicode", with_tail=False))


@planner("OpaqueAction", one_event=True)  # a kept Action; a kept Condition is no repeat
def plan_opaque(ctx: Context, node: scm.OpaqueAction, groups: list[Group]) -> Plan:
    """The kept Action as the node's event, or the kept Condition on a marker event.

    The template writes the Action or Condition element around the kept content with a unique
    name; the Condition keeps its own delay and edge.
    """
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    element = element_of(node)
    if element.tag == "Action":
        action = Action(ctx.action_name(name), "opaque", {"body": _body(element)})
        return [Event(name, entity, [action], groups)], name
    data = {"body": _body(element), "edge": element.get("conditionEdge", "none")}
    kept = Condition(f"{name}_kept", "opaque", data, delay=element.get("delay", "0.0"))
    return marker_plan(ctx, node, groups, entity, kept)

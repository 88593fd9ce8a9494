"""One entity condition to SceML condition nodes, or an opaque node keeping the Condition.

ReachPosition and Distance (to a position, less than) to InLocationRadius, RelativeDistance to
InVehicleRadius, Speed to SpeedCondition, TimeToCollision (to an entity) to TimeToCollision.
With several triggering entities there is one node per entity, joined: `any` by JoinOneFinished,
`all` by JoinAllFinished.
"""

from __future__ import annotations

from collections.abc import Callable

from lxml import etree

import scemlmodel as scm

from ..players.meaning import TTC_FREESPACE
from . import traced
from .context import Build
from .opaque import opaque_node
from .placing import place
from .positions import number

#: Comparison rules SceML has, and the 1.2+ ones read as their strict neighbour (a guess).
RULES = {
    "greaterThan": ("greaterThan", False),
    "lessThan": ("lessThan", False),
    "equalTo": ("equalTo", False),
    "greaterOrEqual": ("greaterThan", True),
    "lessOrEqual": ("lessThan", True),
}
_BELOW = ("lessThan", "lessOrEqual")

Mapper = Callable[[Build, etree._Element, scm.Actor, str], "scm.ActionNode | str"]
_MAPPERS: dict[str, Mapper] = {}


def _maps(tag: str) -> Callable[[Mapper], Mapper]:
    def register(function: Mapper) -> Mapper:
        _MAPPERS[tag] = function
        return function

    return register


def condition_after(
    build: Build, condition: etree._Element, before: scm.GraphElement, wanted: str
) -> scm.GraphElement:
    """Nodes for `condition` activated by `before`; returns the node that finishes when it holds."""
    by_entity = condition.find("ByEntityCondition")
    test = None if by_entity is None else by_entity.find("EntityCondition/*")
    triggering = None if by_entity is None else by_entity.find("TriggeringEntities")
    if test is None or triggering is None:
        return _opaque(
            build, condition, build.default_actor(), before, wanted, "no SceML condition kind"
        )
    actors = [build.actor(ref.get("entityRef"), ref) for ref in triggering.iterfind("EntityRef")]
    mapper = _MAPPERS.get(str(test.tag))
    nodes = []
    for actor in actors:
        made = (
            mapper(build, test, actor, wanted)
            if mapper is not None
            else f"SceML has no kind for {test.tag}"
        )
        if isinstance(made, str):
            # One opaque node keeps the whole condition, every triggering entity included.
            return _opaque(build, condition, actors[0], before, wanted, made)
        nodes.append(made)
    for node in nodes:
        build.flow(before, node)
        _report(build, condition, node, test)
        _edge(build, condition, node)
    if len(nodes) == 1:
        return nodes[0]
    any_of = triggering.get("triggeringEntitiesRule") == "any"
    join: scm.GraphElement = scm.JoinOneFinished() if any_of else scm.JoinAllFinished()
    build.add(join, f"{wanted}_{'any' if any_of else 'all'}")
    for node in nodes:
        build.flow(node, join)
    return join


def _opaque(
    build: Build,
    condition: etree._Element,
    actor: scm.Actor,
    before: scm.GraphElement,
    wanted: str,
    why: str,
) -> scm.GraphElement:
    node = opaque_node(build, condition, actor, wanted, why)
    build.flow(before, node)
    return node


def _report(
    build: Build, condition: etree._Element, node: scm.GraphElement, test: etree._Element
) -> None:
    build.report.add(
        "mapped",
        f"{node.name}: <{condition.get('name')}> {test.tag} -> {node.eClass.name}",
        build.where(condition),
        str(node.name),
    )


def _edge(build: Build, condition: etree._Element, node: scm.GraphElement) -> None:
    edge = condition.get("conditionEdge", "none")
    if edge != "none":
        build.report.add(
            "guessed",
            f"{node.name}: conditionEdge {edge} read as 'holds' (SceML conditions finish once they hold)",
            build.where(condition),
        )


def _node(
    build: Build, kind: str, actor: scm.Actor, wanted: str, **values: float
) -> scm.ActionNode:
    node: scm.ActionNode = getattr(scm, kind)()
    node.referenceActor = actor
    for key, value in values.items():
        node.eSet(key, traced.value(value))
    build.add(node, wanted)
    return node


@_maps("ReachPositionCondition")
def _reach(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    where = place(build, test, initial=False)
    if where is None:
        return "the position is not a world or lane position"
    node = _node(build, "InLocationRadius", actor, wanted, radius=number(test, "tolerance"))
    node.position = where
    return node


@_maps("DistanceCondition")
def _distance(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    where = place(build, test, initial=False)
    if where is None or test.get("rule") not in _BELOW:
        return "only 'closer than' a world or lane position maps (InLocationRadius)"
    if test.get("relativeDistanceType", "euclidianDistance") not in (
        "euclidianDistance",
        "cartesianDistance",
    ):
        return f"a {test.get('relativeDistanceType')} distance has no SceML kind"
    if test.get("freespace") == "true":
        build.report.add(
            "guessed",
            f"{wanted}: a freespace distance read as between reference points",
            build.where(test),
        )
    node = _node(build, "InLocationRadius", actor, wanted, radius=number(test, "value"))
    node.position = where
    return node


@_maps("RelativeDistanceCondition")
def _relative(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    kind = test.get("relativeDistanceType")
    if test.get("rule") not in _BELOW or kind == "lateral":
        return "only 'closer than' in distance or along the road maps (InVehicleRadius)"
    if kind == "longitudinal":
        build.report.add(
            "guessed", f"{wanted}: a longitudinal distance read as a radius", build.where(test)
        )
    if test.get("freespace") == "true":
        build.report.add(
            "guessed",
            f"{wanted}: a freespace distance read as between reference points",
            build.where(test),
        )
    node = _node(build, "InVehicleRadius", actor, wanted, radius=number(test, "value"))
    node.targetActor = build.actor(test.get("entityRef"), test)
    return node


@_maps("SpeedCondition")
def _speed(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    rule = RULES.get(str(test.get("rule")))
    if rule is None or test.get("direction") is not None:
        return f"the rule {test.get('rule')} or a speed direction has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    node = _node(build, "SpeedCondition", actor, wanted, speed=number(test, "value"))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    return node


def _ttc_measure(test: etree._Element) -> str | None:
    """How a TimeToCollisionCondition measures, when that is not SceML's way (between the
    bounding boxes, in a straight line); None when it is."""
    # SceML's TimeToCollision is between the boxes (players.meaning.TTC_FREESPACE).
    if (test.get("freespace") == "true") != TTC_FREESPACE:
        return "between reference points" if TTC_FREESPACE else "between bounding boxes"
    kind = test.get("relativeDistanceType")
    if kind in ("longitudinal", "lateral"):
        return f"of {kind} distance"
    if test.get("alongRoute") == "true":
        return "along the route"
    system = test.get("coordinateSystem")
    if system not in (None, "entity"):
        return f"in {system} coordinates"
    return None


@_maps("TimeToCollisionCondition")
def _ttc(build: Build, test: etree._Element, actor: scm.Actor, wanted: str) -> scm.ActionNode | str:
    rule = RULES.get(str(test.get("rule")))
    target = test.find("TimeToCollisionConditionTarget/EntityRef")
    if rule is None or target is None:
        return "a time to collision with a position, or this rule, has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    measured = _ttc_measure(test)
    if measured is not None:
        # Read as SceML's (between the boxes, straight line) it would fire at another time
        # (alks_cut-in: 0.10 s instead of 2.20 s); kept verbatim, it runs as written.
        return f"a time to collision {measured} has no SceML form yet"
    node = _node(build, "TimeToCollision", actor, wanted, time=number(test, "value"))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    node.targetActor = build.actor(target.get("entityRef"), target)
    return node

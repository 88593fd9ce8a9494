"""One entity condition to SceML condition nodes, or an opaque node keeping the Condition.

ReachPosition and Distance (to a position, less than) to InLocationRadius, RelativeDistance to
InVehicleRadius with its measure and rule, Speed to SpeedCondition, TimeToCollision (to an entity) to TimeToCollision with
its measure, TraveledDistance to TraveledDistance, StandStill to StandStill, Acceleration to
AccelerationCondition with its direction.
With several triggering entities there is one node per entity, joined: `any` by JoinOneFinished,
`all` by JoinAllFinished.
"""

from __future__ import annotations

from collections.abc import Callable
from copy import deepcopy

from lxml import etree

import scemlmodel as scm

from . import traced
from .context import Build
from .global_kinds import signal_condition, value_condition
from .opaque import opaque_node
from .placing import place
from .positions import number

#: Comparison rules SceML has (the ComparisonRule literal, whether it is a guess); 1.1's
#: notEqualTo has no SceML form.
RULES = {
    name: (name, False)
    for name in ("greaterThan", "lessThan", "equalTo", "greaterOrEqual", "lessOrEqual")
}
_BELOW = ("lessThan", "lessOrEqual")

#: The ByValueConditions no actor fulfils, read by global_kinds.py.
GLOBAL_CONDITIONS = ("ParameterCondition", "VariableCondition", "TrafficSignalCondition")

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
    by_value = condition.find("ByValueCondition/*")
    if by_value is not None and by_value.tag in GLOBAL_CONDITIONS:
        return _global(build, condition, by_value, before, wanted)
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


def _global(
    build: Build,
    condition: etree._Element,
    test: etree._Element,
    before: scm.GraphElement,
    wanted: str,
) -> scm.GraphElement:
    """A condition no actor fulfils: ParameterCondition or VariableCondition."""
    if test.tag == "TrafficSignalCondition":
        made: scm.ActionNode | str = signal_condition(build, test, wanted)
    else:
        made = value_condition(build, test, wanted, RULES)
    if isinstance(made, str):
        return _opaque(build, condition, build.default_actor(), before, wanted, made)
    build.flow(before, made)
    _report(build, condition, made, test)
    _edge(build, condition, made)
    return made


def _opaque(
    build: Build,
    condition: etree._Element,
    actor: scm.Actor,
    before: scm.GraphElement,
    wanted: str,
    why: str,
) -> scm.GraphElement:
    kept = condition
    if condition.get("delay") not in (None, "0", "0.0"):
        # The trigger reader already made the delay a TimeElapsed after this node: kept in
        # the XML as well, the export would wait for it twice.
        kept = deepcopy(condition)
        kept.set("delay", "0")
    node = opaque_node(build, kept, actor, wanted, why, build.where(condition))
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
    """The conditionEdge, kept on the node (release 1.3) so the preview and the export keep it."""
    edge = str(condition.get("conditionEdge", "none"))
    if edge == "none" or not isinstance(node, scm.Condition):
        return
    literal = scm.ConditionEdge.getEEnumLiteral(edge)
    if literal is None:
        build.report.add(
            "guessed",
            f"{node.name}: conditionEdge {edge} is not an OpenSCENARIO edge, read as none",
            build.where(condition),
        )
        return
    node.edge = literal


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
    rule = RULES.get(str(test.get("rule")))
    if rule is None:
        return f"the rule {test.get('rule')} has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    # Read as a straight line between the reference points it would fire at another time
    # (ALKS 4.4.x: a longitudinal freespace gap, the cut-in 0.95 s late), so the measure is kept.
    measure = measure_of(test, wanted)
    if isinstance(measure, str):
        return measure
    node = _node(build, "InVehicleRadius", actor, wanted, radius=number(test, "value"))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    for feature, value in measure.items():
        node.eSet(feature, value)
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


@_maps("TraveledDistanceCondition")
def _traveled(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    # The same odometer from the simulation's start in OpenSCENARIO and SceML.
    return _node(build, "TraveledDistance", actor, wanted, distance=number(test, "value"))


@_maps("TimeHeadwayCondition")
def _headway(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    rule = RULES.get(str(test.get("rule")))
    if rule is None:
        return f"the rule {test.get('rule')} has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    measure = measure_of(test, wanted)
    if isinstance(measure, str):
        return measure
    node = _node(build, "TimeHeadway", actor, wanted, time=number(test, "value"))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    node.targetActor = build.actor(test.get("entityRef"), test)
    for feature, value in measure.items():
        node.eSet(feature, value)
    return node


#: OpenSCENARIO's relativeDistanceType values as SceML's RelativeDistanceType literals
#: (cartesianDistance is 1.0's name, deprecated in 1.1, for the same straight line).
DISTANCE_TYPES = {
    "euclidianDistance": "euclidean",
    "cartesianDistance": "euclidean",
    "longitudinal": "longitudinal",
    "lateral": "lateral",
}
#: OpenSCENARIO's coordinateSystem values, the same names in SceML.
COORDINATE_SYSTEMS = ("entity", "lane", "road", "trajectory")


def measure_of(test: etree._Element, wanted: str) -> dict[str, object] | str:
    """How a measuring condition measures (freespace, distance type, coordinate system) as
    node feature values; why not when SceML cannot say it."""
    if test.get("alongRoute") == "true":
        # Deprecated in 1.1 and never defined beyond "along the route"; no SceML form.
        return "a distance along the route (alongRoute) has no SceML form"
    kind = DISTANCE_TYPES.get(test.get("relativeDistanceType") or "euclidianDistance")
    system = test.get("coordinateSystem") or "entity"
    if kind is None or system not in COORDINATE_SYSTEMS:
        return f"the distance type or coordinate system of {wanted} has no SceML form"
    return {
        "freespace": test.get("freespace") == "true",
        "relativeDistanceType": scm.RelativeDistanceType.getEEnumLiteral(kind),
        "coordinateSystem": scm.CoordinateSystem.getEEnumLiteral(system),
    }


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
    # Read as the default measure it would fire at another time (alks_cut-in: 0.10 s instead
    # of 2.20 s), so the measure is kept as written.
    measure = measure_of(test, wanted)
    if isinstance(measure, str):
        return measure
    node = _node(build, "TimeToCollision", actor, wanted, time=number(test, "value"))
    for feature, value in measure.items():
        node.eSet(feature, value)
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    node.targetActor = build.actor(target.get("entityRef"), target)
    return node


@_maps("StandStillCondition")
def _stand_still(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    # esmini counts from when the actor stopped, also before the condition was evaluated.
    return _node(build, "StandStill", actor, wanted, duration=number(test, "duration"))


@_maps("AccelerationCondition")
def _acceleration(
    build: Build, test: etree._Element, actor: scm.Actor, wanted: str
) -> scm.ActionNode | str:
    rule = RULES.get(str(test.get("rule")))
    direction = test.get("direction") or "total"  # absent: the magnitude (esmini's GetAcc)
    literal = scm.AccelerationDirection.getEEnumLiteral(direction)
    if rule is None or literal is None or direction == "total" and test.get("direction"):
        return f"the rule {test.get('rule')} or the direction {direction} has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    node = _node(build, "AccelerationCondition", actor, wanted, acceleration=number(test, "value"))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    node.direction = literal
    return node

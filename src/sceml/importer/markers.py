"""SceML's own exports read back exactly: marker events and the extra events of a node.

An export (docs/openscenario-mapping.md) declares the string `SceML_marker`; a *marker* event
only sets it. A node's further events are named `<node>__<suffix>`: `__arrived` (the arrival of
TurnLeft/TurnRight/Cross/FollowTrajectory: its tolerance), `__driven` (DriveDistance: its
distance, or its duration distance / speed as the delay), `__gap_reached` (Follow), `__back` (Overtake: the lane change back and the gap),
`__kept` (KeepVelocity, whose own event holds the speed: its duration is the delay). They are folded into the node of `<node>`; and the node's kind is the kind its name states.
"""

from __future__ import annotations

import re
from functools import cache

from lxml import etree

import scemlmodel as scm

from ..model import catalog
from .actions import Motion, Request, _add
from .context import Build, last_name
from .positions import number

MARKER = "SceML_marker"
SEPARATOR = "__"
SUFFIXES = ("arrived", "driven", "gap_reached", "back", "kept")


def marker_name(root: etree._Element) -> str | None:
    """The marker a SceML export declares (parameter in 1.0/1.1, variable in 1.2+), or None."""
    for declaration in root.iterfind("ParameterDeclarations/ParameterDeclaration"):
        if declaration.get("name") == MARKER:
            return MARKER
    for declaration in root.iterfind("VariableDeclarations/VariableDeclaration"):
        if declaration.get("name") == MARKER:
            return MARKER
    return None


def is_marker(build: Build, event: etree._Element) -> bool:
    """Whether every action of the event only sets the SceML marker."""
    actions = event.findall("Action")
    if not build.from_sceml or not actions:
        return False
    for action in actions:
        setter = action.find("GlobalAction/ParameterAction")
        ref = None if setter is None else setter.get("parameterRef")
        if setter is None:
            setter = action.find("GlobalAction/VariableAction")
            ref = None if setter is None else setter.get("variableRef")
        if setter is None or setter.find("SetAction") is None or ref != build.marker:
            return False
    return True


def base_of(build: Build, name: str, events: dict[str, etree._Element]) -> tuple[str, str] | None:
    """(base event, suffix) when `name` is a further event of a SceML export's node."""
    if not build.from_sceml or SEPARATOR not in name:
        return None
    base, _, suffix = name.rpartition(SEPARATOR)
    if suffix.rstrip("_0123456789") in SUFFIXES and base in events:
        return base, suffix
    return None


@cache
def _kind_names() -> tuple[str, ...]:
    return tuple(
        cls.__name__ for cls in catalog.action_node_kinds() if cls.__name__ != "OpaqueAction"
    )


def hint(build: Build, name: str) -> str | None:
    """The node kind a SceML export's event name states: the last kind name in it."""
    if not build.from_sceml:
        return None
    found = [(m.start(), kind) for kind in _kind_names() for m in re.finditer(kind, name)]
    return max(found)[1] if found else None


def tolerance(extra: etree._Element) -> float | None:
    """The arrival tolerance an `__arrived` event waits for."""
    for test in extra.iter("ReachPositionCondition", "DistanceCondition"):
        return number(test, "tolerance" if test.tag == "ReachPositionCondition" else "value")
    return None


def drive_distance(
    build: Build, request: Request, driven: etree._Element, motion: Motion
) -> scm.ActionNode | None:
    """A DriveDistance from its step speed action and its `__driven` event: a
    TraveledDistanceCondition (carla profile), or the activation delayed by distance / speed
    (`xosc.meaning.drive_distance_duration`)."""
    speed = request.element.find(".//AbsoluteTargetSpeed")
    if speed is None:
        return None
    value = number(speed, "value")
    traveled = driven.find(".//TraveledDistanceCondition")
    if traveled is not None:
        distance = number(traveled, "value")
    else:
        delays = {c.get("delay") for c in driven.iterfind("StartTrigger/ConditionGroup/Condition")}
        if len(delays) != 1:
            return None
        condition = driven.find("StartTrigger/ConditionGroup/Condition")
        # The export wrote the duration as Python's repr: undo the division's rounding.
        distance = round(number(condition, "delay") * value, 9)
    motion.speed[str(request.actor.name)] = value
    return _add(build, request, "DriveDistance", speed=value, distance=distance)


def overtake(
    build: Build, event: etree._Element, request: Request, back: etree._Element, motion: Motion
) -> scm.ActionNode | None:
    """An Overtake from its lane change + speed event and its `__back` event."""
    lane = event.find(".//LaneChangeAction")
    speed = event.find(".//AbsoluteTargetSpeed")
    ahead = back.find(".//RelativeObjectPosition")
    lanes = None if lane is None else lane.find(".//RelativeTargetLane")
    if lane is None or lanes is None or speed is None or ahead is None:
        return None
    side = "left" if number(lanes, "value") > 0 else "right"
    distance = lane.find("LaneChangeActionDynamics")
    value = number(speed, "value")
    motion.speed[str(request.actor.name)] = value
    node = _add(
        build,
        request,
        "Overtake",
        speed=value,
        gap=number(ahead, "dx"),
        laneChangeDistance=None if distance is None else number(distance, "value"),
    )
    node.side = scm.LaneChangeDirection.getEEnumLiteral(side)
    node.targetActor = build.actor(last_name(str(ahead.get("entityRef"))), ahead)
    return node


def keep_velocity(build: Build, request: Request, kept: etree._Element) -> scm.ActionNode | None:
    """A KeepVelocity from its speed-holding event and its delayed `__kept` marker."""
    conditions = list(kept.iterfind("StartTrigger/ConditionGroup/Condition"))
    if len({c.get("delay") for c in conditions}) != 1:
        return None
    return _add(build, request, "KeepVelocity", duration=number(conditions[0], "delay"))

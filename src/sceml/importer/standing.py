"""Whether an event's StartTrigger says its actor stands when the event starts.

The import reads a speed change given in time or distance as a rate from the speed before,
which it takes to be the last speed set (`actions.Motion`). An event that waits for its actor
to stand still, or to be at the end of the road, starts at 0 m/s whatever was set before:
players stop an actor that reaches the end of its road (esmini holds it there at 0 m/s until
something moves it). `lane_change_simple`'s "End Of Road speed event" (0 to 25 m/s in 4 s,
after its car stood at the end of the road and was teleported back) was read as a change from
25 m/s: no change, so the language's default rate, and the car reached 25 m/s 11 s late.

Events on the same standing trigger may run a different number of times: when one with no
speed change runs more often than those with one, the trigger's last run leaves the actor
standing (`lane_change_simple`'s teleport runs three times, its speed change twice: its second
act starts with the car at 0 m/s, read as at 25 m/s).
"""

from __future__ import annotations

from collections.abc import Sequence

from lxml import etree

import scemlmodel as scm

from .context import Build

#: Entity conditions that hold only while the triggering entity stands.
_STANDING = ("EndOfRoadCondition", "StandStillCondition")
#: Of those, where players hold the entity until an action moves it: the end of its road. An
#: entity that stood still may drive on by a controller or a running action.
_HELD = ("EndOfRoadCondition",)


def stands_at_start(
    build: Build,
    trigger: etree._Element | None,
    actor: scm.Actor,
    kinds: tuple[str, ...] = _STANDING,
) -> bool:
    """Whether every ConditionGroup of `trigger` holds only while `actor` stands: each has a
    condition of `kinds` (StandStill, EndOfRoad) whose triggering entities are `actor` alone,
    or all of them ("all"). A condition with a delay may no longer describe the start: not
    counted."""
    groups = [] if trigger is None else trigger.findall("ConditionGroup")
    return bool(groups) and all(
        any(_says(build, condition, actor, kinds) for condition in group.iterfind("Condition"))
        for group in groups
    )


def _says(
    build: Build, condition: etree._Element, actor: scm.Actor, kinds: tuple[str, ...]
) -> bool:
    delay = condition.get("delay", "0")
    by_entity = condition.find("ByEntityCondition")
    if by_entity is None or _number(delay) != 0.0:
        return False
    triggering = by_entity.find("TriggeringEntities")
    test = by_entity.find("EntityCondition/*")
    if triggering is None or test is None or test.tag not in kinds:
        return False
    refs = [build.actor(ref.get("entityRef"), ref) for ref in triggering.iterfind("EntityRef")]
    every = triggering.get("triggeringEntitiesRule") == "all"
    return actor in refs and (every or refs == [actor])


def _number(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:  # a parameter or expression: not known to be zero
        return None


def on_same_trigger(
    build: Build,
    events: Sequence[tuple[etree._Element, Sequence[scm.Actor]]],
    event: etree._Element,
    actor: scm.Actor,
) -> list[etree._Element]:
    """The events of `actor` (`event` among them) on `event`'s StartTrigger as written, but
    for condition names, if that trigger holds only while `actor` is held at the end of its
    road; else none."""
    trigger = event.find("StartTrigger")
    if not stands_at_start(build, trigger, actor, _HELD):
        return []
    key = _trigger_key(trigger)
    return [
        element
        for element, actors in events
        if actor in actors and _trigger_key(element.find("StartTrigger")) == key
    ]


def left_standing(same: Sequence[etree._Element]) -> bool:
    """Whether the actor stands after the last run of a standing trigger, given the events on
    it (`on_same_trigger`): one without a speed change runs more times than every one with."""
    changing = [_runs(e) for e in same if e.find("Action//SpeedAction") is not None]
    still = [_runs(e) for e in same if e.find("Action//SpeedAction") is None]
    return bool(still) and max(still) > max(changing, default=0)


def _trigger_key(
    trigger: etree._Element | None,
) -> tuple[tuple[str, tuple[tuple[str, str], ...]], ...]:
    """A trigger as its elements and attributes in document order, condition names left out."""
    if trigger is None:
        return ()
    return tuple(
        (str(element.tag), tuple(sorted((k, v) for k, v in element.attrib.items() if k != "name")))
        for element in trigger.iter()
        if isinstance(element.tag, str)
    )


def _runs(event: etree._Element) -> int:
    try:
        return int(event.get("maximumExecutionCount", "1"))
    except ValueError:  # a parameter: taken as once
        return 1

"""Repair OSC-Generator 0.2.0's output so that an OpenSCENARIO 1.0 player can read it.

OSC-Generator writes `revMajor="1" revMinor="0"` but the element and attribute names of the
pre-1.0 draft (0.9.1): `Object` for `ScenarioObject`, `Logics` for `LogicFile`, `Private
object=` for `entityRef=`, `Position/World` for `TeleportAction/Position/WorldPosition`,
`Speed/Dynamics shape rate` for `SpeedAction/SpeedActionDynamics dynamicsShape value
dynamicsDimension`, and so on; the OpenSCENARIO 1.0 XSD rejects it and esmini 3.6 refuses it.
`repair` renames each of them to its 1.0 name, keeping every value. Where 1.0 needs what the
file does not say, the repair adds as little as it can and says so in `REPAIRS` (the table in
docs/extract.md is this list). Nothing else is changed: the same actors, positions, speeds,
actions and start times, including what makes little sense (a lane change whose start
condition is a point 5,800 km away, speed changes "at rate 0").

    .venv/bin/python benchmarks/osc_generator_repair.py IN.xosc OUT.xosc
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import TypeAlias

from lxml import etree

#: What the repair does beyond renaming, element by element (docs/extract.md lists it).
REPAIRS = (
    "FileHeader: the date ' ' (no xs:dateTime) becomes 1970-01-01T00:00:00",
    "ParameterDeclaration (empty) becomes ParameterDeclarations",
    "Catalogs becomes an empty CatalogLocations: the file refers to no catalog entry, and "
    "its DriverCatalog and PedestrianControllerCatalog have no 1.0 counterpart",
    "RoadNetwork: Logics and SceneGraph become LogicFile and SceneGraphFile; the empty "
    "Signals is dropped",
    "Object becomes ScenarioObject; Vehicle@category becomes vehicleCategory; Front and Rear "
    "become FrontAxle and RearAxle; Performance@mass is dropped and maxAcceleration (required "
    "in 1.0, not said) is set to the file's maxDeceleration; the Driver controller (a "
    "description of a person, no 1.0 controller) is dropped",
    "Private@object becomes entityRef; Action becomes PrivateAction; Position/World becomes "
    "TeleportAction/Position/WorldPosition",
    "Longitudinal/Speed becomes LongitudinalAction/SpeedAction; Dynamics shape, rate becomes "
    "SpeedActionDynamics dynamicsShape, value, dynamicsDimension rate (a step: time, 0); "
    "Target/Absolute becomes SpeedActionTarget/AbsoluteTargetSpeed",
    "Lateral/LaneChange becomes LateralAction/LaneChangeAction; Dynamics time, shape becomes "
    "LaneChangeActionDynamics value, dynamicsShape, dynamicsDimension time; Target/Relative "
    "object becomes LaneChangeTarget/RelativeTargetLane entityRef",
    "Story@owner is dropped; Sequence@numberOfExecutions becomes ManeuverGroup@"
    "maximumExecutionCount; Actors/Entity becomes Actors (selectTriggeringEntities false)/"
    "EntityRef",
    "StartConditions and Act Conditions/Start become StartTrigger; ByValue/SimulationTime "
    "becomes ByValueCondition/SimulationTimeCondition; ByEntity becomes ByEntityCondition "
    "with TriggeringEntities@rule as triggeringEntitiesRule and EntityRef; Distance becomes "
    "DistanceCondition with freespace and alongRoute 0/1 as false/true; rules greater_than, "
    "less_than, equal_to become greaterThan, lessThan, equalTo",
    "Storyboard gets the StopTrigger 1.0 requires: SimulationTime > the given end (the "
    "recording's length), so that a run ends where the recording does",
)

_RULES = {"greater_than": "greaterThan", "less_than": "lessThan", "equal_to": "equalTo"}
_BOOLEANS = {"0": "false", "1": "true", "false": "false", "true": "true"}

Element: TypeAlias = etree._Element


def repair(tree: etree._ElementTree, stop_time: float) -> etree._ElementTree:
    """The OpenSCENARIO 1.0 document that says what OSC-Generator's `tree` says."""
    old = tree.getroot()
    root = etree.Element("OpenSCENARIO")
    header = _child(old, "FileHeader")
    etree.SubElement(
        root,
        "FileHeader",
        revMajor="1",
        revMinor="0",
        date="1970-01-01T00:00:00",
        description=header.get("description", ""),
        author=header.get("author", ""),
    )
    etree.SubElement(root, "ParameterDeclarations")
    etree.SubElement(root, "CatalogLocations")
    network = etree.SubElement(root, "RoadNetwork")
    old_network = _child(old, "RoadNetwork")
    for name, new in (("Logics", "LogicFile"), ("SceneGraph", "SceneGraphFile")):
        found = old_network.find(name)
        if found is not None:
            etree.SubElement(network, new, filepath=found.get("filepath", ""))
    entities = etree.SubElement(root, "Entities")
    for item in _child(old, "Entities").findall("Object"):
        _scenario_object(entities, item)
    storyboard = etree.SubElement(root, "Storyboard")
    old_storyboard = _child(old, "Storyboard")
    init = etree.SubElement(etree.SubElement(storyboard, "Init"), "Actions")
    for private in _child(_child(old_storyboard, "Init"), "Actions").findall("Private"):
        made = etree.SubElement(init, "Private", entityRef=private.get("object", ""))
        for action in private.findall("Action"):
            _private_action(made, action)
    for story in old_storyboard.findall("Story"):
        _story(storyboard, story)
    stop = etree.SubElement(etree.SubElement(storyboard, "StopTrigger"), "ConditionGroup")
    condition = etree.SubElement(stop, "Condition", name="end", delay="0", conditionEdge="rising")
    etree.SubElement(
        etree.SubElement(condition, "ByValueCondition"),
        "SimulationTimeCondition",
        value=f"{stop_time:g}",
        rule="greaterThan",
    )
    return etree.ElementTree(root)


def _child(element: Element, tag: str) -> Element:
    found = element.find(tag)
    if found is None:
        raise ValueError(f"no {tag} in {element.tag} (line {element.sourceline})")
    return found


def _scenario_object(entities: Element, item: Element) -> None:
    made = etree.SubElement(entities, "ScenarioObject", name=item.get("name", ""))
    vehicle = _child(item, "Vehicle")
    new = etree.SubElement(
        made, "Vehicle", name=vehicle.get("name", ""), vehicleCategory=vehicle.get("category", "")
    )
    etree.SubElement(new, "ParameterDeclarations")
    box = _child(vehicle, "BoundingBox")
    new_box = etree.SubElement(new, "BoundingBox")
    etree.SubElement(new_box, "Center", dict(_child(box, "Center").attrib))
    etree.SubElement(new_box, "Dimensions", dict(_child(box, "Dimension").attrib))
    performance = _child(vehicle, "Performance")
    etree.SubElement(
        new,
        "Performance",
        maxSpeed=performance.get("maxSpeed", ""),
        maxAcceleration=performance.get("maxDeceleration", ""),
        maxDeceleration=performance.get("maxDeceleration", ""),
    )
    axles = _child(vehicle, "Axles")
    new_axles = etree.SubElement(new, "Axles")
    etree.SubElement(new_axles, "FrontAxle", dict(_child(axles, "Front").attrib))
    etree.SubElement(new_axles, "RearAxle", dict(_child(axles, "Rear").attrib))
    properties = etree.SubElement(new, "Properties")
    for prop in _child(vehicle, "Properties").findall("Property"):
        etree.SubElement(properties, "Property", dict(prop.attrib))


def _private_action(parent: Element, action: Element) -> None:
    """An Init `Action` or a story action's `Private`: its one Position, Longitudinal or
    Lateral part."""
    made = etree.SubElement(parent, "PrivateAction")
    for part in action:
        if not isinstance(part.tag, str):
            continue
        _PRIVATE[part.tag](made, part)


def _teleport(parent: Element, position: Element) -> None:
    _position(etree.SubElement(parent, "TeleportAction"), position)


def _position(parent: Element, position: Element) -> None:
    world = _child(position, "World")
    etree.SubElement(etree.SubElement(parent, "Position"), "WorldPosition", dict(world.attrib))


def _longitudinal(parent: Element, longitudinal: Element) -> None:
    speed = _child(longitudinal, "Speed")
    action = etree.SubElement(etree.SubElement(parent, "LongitudinalAction"), "SpeedAction")
    dynamics = _child(speed, "Dynamics")
    shape = dynamics.get("shape", "step")
    etree.SubElement(
        action,
        "SpeedActionDynamics",
        dynamicsShape=shape,
        value=dynamics.get("rate", "0"),
        dynamicsDimension="time" if shape == "step" else "rate",
    )
    target = _child(_child(speed, "Target"), "Absolute")
    etree.SubElement(
        etree.SubElement(action, "SpeedActionTarget"), "AbsoluteTargetSpeed", dict(target.attrib)
    )


def _lateral(parent: Element, lateral: Element) -> None:
    change = _child(lateral, "LaneChange")
    action = etree.SubElement(etree.SubElement(parent, "LateralAction"), "LaneChangeAction")
    if change.get("targetLaneOffset") is not None:
        action.set("targetLaneOffset", change.get("targetLaneOffset", "0"))
    dynamics = _child(change, "Dynamics")
    etree.SubElement(
        action,
        "LaneChangeActionDynamics",
        dynamicsShape=dynamics.get("shape", "sinusoidal"),
        value=dynamics.get("time", "0"),
        dynamicsDimension="time",
    )
    relative = _child(_child(change, "Target"), "Relative")
    etree.SubElement(
        etree.SubElement(action, "LaneChangeTarget"),
        "RelativeTargetLane",
        entityRef=relative.get("object", ""),
        value=relative.get("value", "0"),
    )


_PRIVATE: dict[str, Callable[[Element, Element], None]] = {
    "Position": _teleport,
    "Longitudinal": _longitudinal,
    "Lateral": _lateral,
}


def _story(storyboard: Element, story: Element) -> None:
    made = etree.SubElement(storyboard, "Story", name=story.get("name", ""))
    for act in story.findall("Act"):
        new_act = etree.SubElement(made, "Act", name=act.get("name", ""))
        for sequence in act.findall("Sequence"):
            _maneuver_group(new_act, sequence)
        start = _child(_child(act, "Conditions"), "Start")
        _trigger(new_act, "StartTrigger", start)


def _maneuver_group(act: Element, sequence: Element) -> None:
    group = etree.SubElement(
        act,
        "ManeuverGroup",
        name=sequence.get("name", ""),
        maximumExecutionCount=sequence.get("numberOfExecutions", "1"),
    )
    actors = etree.SubElement(group, "Actors", selectTriggeringEntities="false")
    for entity in _child(sequence, "Actors").findall("Entity"):
        etree.SubElement(actors, "EntityRef", entityRef=entity.get("name", ""))
    for maneuver in sequence.findall("Maneuver"):
        new = etree.SubElement(group, "Maneuver", name=maneuver.get("name", ""))
        for event in maneuver.findall("Event"):
            made = etree.SubElement(
                new, "Event", name=event.get("name", ""), priority=event.get("priority", "")
            )
            for action in event.findall("Action"):
                new_action = etree.SubElement(made, "Action", name=action.get("name", ""))
                _private_action(new_action, _child(action, "Private"))
            _trigger(made, "StartTrigger", _child(event, "StartConditions"))


def _trigger(parent: Element, tag: str, conditions: Element) -> None:
    trigger = etree.SubElement(parent, tag)
    for group in conditions.findall("ConditionGroup"):
        new_group = etree.SubElement(trigger, "ConditionGroup")
        for condition in group.findall("Condition"):
            made = etree.SubElement(
                new_group,
                "Condition",
                name=condition.get("name", ""),
                delay=condition.get("delay", "0"),
                conditionEdge=condition.get("edge", "none"),
            )
            for by_value in condition.findall("ByValue"):
                time = _child(by_value, "SimulationTime")
                etree.SubElement(
                    etree.SubElement(made, "ByValueCondition"),
                    "SimulationTimeCondition",
                    value=time.get("value", "0"),
                    rule=_RULES[time.get("rule", "greater_than")],
                )
            for by_entity in condition.findall("ByEntity"):
                _by_entity(made, by_entity)


def _by_entity(condition: Element, by_entity: Element) -> None:
    made = etree.SubElement(condition, "ByEntityCondition")
    entities = _child(by_entity, "TriggeringEntities")
    triggering = etree.SubElement(
        made, "TriggeringEntities", triggeringEntitiesRule=entities.get("rule", "any")
    )
    for entity in entities.findall("Entity"):
        etree.SubElement(triggering, "EntityRef", entityRef=entity.get("name", ""))
    distance = _child(_child(by_entity, "EntityCondition"), "Distance")
    new = etree.SubElement(
        etree.SubElement(made, "EntityCondition"),
        "DistanceCondition",
        value=distance.get("value", "0"),
        freespace=_BOOLEANS[distance.get("freespace", "0")],
        alongRoute=_BOOLEANS[distance.get("alongRoute", "0")],
        rule=_RULES[distance.get("rule", "less_than")],
    )
    _position(new, _child(distance, "Position"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source", type=Path)
    parser.add_argument("target", type=Path)
    parser.add_argument("--stop", type=float, default=60.0, help="end of the run (s)")
    options = parser.parse_args()
    fixed = repair(etree.parse(str(options.source)), options.stop)
    fixed.write(str(options.target), xml_declaration=True, encoding="utf-8", pretty_print=True)


if __name__ == "__main__":
    main()

"""Files other tools wrote: built at test time with scenariogeneration's own API, and written by
hand in the style of public scenarios (tests/importer/files). Each imports to a graph a person
can read, with what SceML cannot express kept as opaque nodes, validates, draws, and exports
back to a file that passes the XSD and ASAM's checker."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from scenariogeneration import xosc

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model.loading import load_scenario
from sceml.render import diagram, to_bytes
from sceml.validation import validate
from sceml.xosc.check import check_file

FILES = Path(__file__).resolve().parent / "files"


def map_folders(source: Path) -> list[Path]:
    """Where the maps these files name lie: they are read only from allowed folders."""
    return [source.parent, FILES, FILES.parents[2] / "maps"]


def kinds(scenario: scm.Scenario) -> list[str]:
    return sorted(str(node.eClass.name) for node in scenario.nodes)


def opaque_tags(scenario: scm.Scenario) -> set[str]:
    """What each opaque node keeps, as `Element Kind` (e.g. `Condition TimeHeadwayCondition`)."""
    from sceml.render.labels import opaque_lines

    return {opaque_lines(n)[0] for n in scenario.nodes if isinstance(n, scm.OpaqueAction)}


def round_trip(source: Path, tmp_path: Path, version: str) -> Path:
    """Import, validate, draw, export back at `version`; returns the exported file."""
    model = tmp_path / f"{source.stem}.xmi"
    import_to_file(source, model)
    document = load_scenario(model, allow=map_folders(source))
    errors = [d for d in validate(document.root, document=document) if d.severity is Severity.ERROR]
    assert errors == []
    for view in ("flow", "bt"):
        drawn = to_bytes(diagram(document.root, view=view), "svg")
        assert (b"sceml&#45;opaque" in drawn) == ("OpaqueAction" in kinds(document.root))
    back = tmp_path / f"{source.stem}-back.xosc"
    export_to_file(document.root, back, version=version, source_path=model)
    report = check_file(back, allow=map_folders(source))
    assert [str(d) for d in report.diagnostics if d.severity is Severity.ERROR] == []
    return back


# --- written by hand -----------------------------------------------------------------------


HAND_WRITTEN = {
    "cut-in": (
        "1.1",
        ["Car", "Car"],
        [
            "Decelerate",
            "EndNode",
            "LaneChange",
            "OpaqueAction",
            "RootNode",
            "TimeElapsed",
            "TimeElapsed",
            # `SimulationTime > 0`: it first holds a step after the start (0.05 s).
            "TimeElapsed",
        ],
        {"Condition TimeHeadwayCondition"},
    ),
    "pedestrian-crossing": (
        "1.1",
        ["Car", "Pedestrian"],
        [
            "Accelerate",
            "EndNode",
            "FollowTrajectory",
            "InLocationRadius",
            "JoinAllFinished",
            # The walk's speed change and path start together: the event's own join.
            "JoinAllFinished",
            # The unnamed branches joined with the StopTrigger's wait: they reach the end, and
            # the StopTrigger alone decides when the run ends.
            "JoinAllFinished",
            "OpaqueAction",
            "OpaqueAction",
            "RootNode",
            "Stop",
            "TimeElapsed",
            # `SimulationTime > 0`: it first holds a step after the start (0.05 s).
            "TimeElapsed",
            # Between reference points (freespace="false"), kept as the node's freespace.
            "TimeToCollision",
        ],
        {"Action VisibilityAction"},
    ),
    "follow-and-brake": (
        "1.2",
        ["Car", "Truck"],
        [
            # The ACC switched on (1.2 still reads 1.0's unwrapped ActivateControllerAction).
            "ActivateController",
            "EndNode",
            "Follow",
            # The StopTrigger's two events, and the Follow's branch joined with them (the
            # ego's Stop interrupts the Follow, release 1.5: it no longer waits for it).
            "JoinAllFinished",
            "JoinAllFinished",
            "RootNode",
            "Stop",
            "Stop",
            "TimeElapsed",
            # Between the boxes (freespace), as SceML's TimeToCollision measures.
            "TimeToCollision",
        ],
        set(),
    ),
    "alks-lane-keeping": (
        "1.3",
        ["Car", "Car"],
        [
            "Decelerate",
            "EndNode",
            "InVehicleRadius",
            # The unnamed branch joined with the StopTrigger's condition: it reaches the end,
            # and the condition alone decides when the run ends.
            "JoinAllFinished",
            "LaneChange",
            "LaneOffset",
            "RootNode",
            "SpeedCondition",
            "TimeElapsed",
            # `SimulationTime > 0`: it first holds a step after the start (0.05 s).
            "TimeElapsed",
            # The odometer since the start, as SceML's TraveledDistance counts.
            "TraveledDistance",
        ],
        set(),
    ),
}


@pytest.mark.parametrize("name", sorted(HAND_WRITTEN))
def test_hand_written_files_import_to_readable_graphs(name: str, tmp_path: Path) -> None:
    version, actors, nodes, opaque = HAND_WRITTEN[name]
    imported = import_file(FILES / f"{name}.xosc")
    root = next(n for n in imported.scenario.nodes if isinstance(n, scm.RootNode))
    assert sorted(a.eClass.name for a in root.actors) == actors
    assert [a.name for a in root.actors if a.isEgo] == [root.actors[0].name]
    assert kinds(imported.scenario) == nodes
    assert opaque_tags(imported.scenario) == opaque
    # Every opaque node is in the report with its line.
    kept = imported.report.section("opaque")
    assert len(kept) == len([n for n in imported.scenario.nodes if isinstance(n, scm.OpaqueAction)])
    assert all(entry.line for entry in kept)
    round_trip(FILES / f"{name}.xosc", tmp_path, version)


def test_cut_in_reads_parameters_expressions_catalog_and_geometry() -> None:
    imported = import_file(FILES / "cut-in.xosc")
    root = next(n for n in imported.scenario.nodes if isinstance(n, scm.RootNode))
    ego, target = root.actors
    assert (ego.name, ego.isEgo, target.isEgo) == ("Ego", True, False)
    assert target.initialSpeed.value == 30.0  # ${$EgoSpeed + $SpeedDelta}
    assert target.startPosition.s.value == 25.0  # ${$EgoStart - 25}
    assert ego.length.value == 5.04  # from the vehicle catalog
    change = next(n for n in imported.scenario.nodes if isinstance(n, scm.LaneChange))
    # Into the ego's lane (RelativeTargetLane Ego 0), not read as one lane to the right.
    assert (change.targetActor.name, change.lanes) == ("Ego", 0)
    brake = next(n for n in imported.scenario.nodes if isinstance(n, scm.Decelerate))
    assert (brake.targetSpeed.value, brake.rate.value) == (15.0, 4.0)
    assert root.maxDuration.value == 30.0
    assert imported.report.catalog_entries == [
        "VehicleCatalog/car_white",
        "VehicleCatalog/car_white",
    ]


def test_follow_and_brake_reads_a_maneuver_from_its_catalog() -> None:
    imported = import_file(FILES / "follow-and-brake.xosc")
    lead_stop = next(
        n
        for n in imported.scenario.nodes
        if isinstance(n, scm.Stop) and n.referenceActor.name == "Lead"
    )
    assert lead_stop.rate.value == 7.0  # the reference's ParameterAssignment
    wait = lead_stop.incoming[0].source
    # `SimulationTime > 5`: first holds a step after 5 s, as esmini starts it.
    assert isinstance(wait, scm.TimeElapsed) and wait.duration.value == 5.05
    # The ego's controller, from the controller catalog, is the actor's.
    ego = next(a for a in imported.scenario.nodes[0].actors if a.name == "Ego")
    assert ego.controller.name == "ACCController"
    assert "controller" not in " ".join(
        e.message for e in imported.report.section("not represented")
    )


def test_a_lane_offset_and_the_stop_trigger_export_back(tmp_path: Path) -> None:
    back = round_trip(FILES / "alks-lane-keeping.xosc", tmp_path, "1.3")
    text = back.read_text()
    # The lane offset, once kept opaque, is a LaneOffset node written back as it was read.
    assert '<LaneOffsetAction continuous="false">' in text
    assert 'maxLateralAcc="0.3" dynamicsShape="sinusoidal"' in text
    assert '<AbsoluteTargetLaneOffset value="-0.8"/>' in text
    # The StopTrigger's TraveledDistance is a SceML kind now, written as a marker's condition.
    assert '<TraveledDistanceCondition value="400.0"/>' in text


# --- built with scenariogeneration ---------------------------------------------------------


def _car(name: str) -> xosc.Vehicle:
    box = xosc.BoundingBox(2, 5, 1.8, 2.0, 0, 0.9)
    front = xosc.Axle(0.523598775598, 0.8, 1.68, 2.98, 0.4)
    rear = xosc.Axle(0, 0.8, 1.68, 0, 0.4)
    return xosc.Vehicle(name, xosc.VehicleCategory.car, box, front, rear, 69, 10, 10)


def _priority(version: int) -> xosc.Priority:
    return xosc.Priority.override if version >= 2 else xosc.Priority.overwrite


def _speed(value: float) -> xosc.AbsoluteSpeedAction:
    return xosc.AbsoluteSpeedAction(
        value, xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    )


def _scenario(
    name: str,
    entities: xosc.Entities,
    init: xosc.Init,
    story: xosc.Story,
    stop: xosc.ValueTrigger,
    road: str,
    version: int,
) -> xosc.Scenario:
    storyboard = xosc.StoryBoard(init, stop)
    storyboard.add_story(story)
    return xosc.Scenario(
        name,
        "scenariogeneration",
        xosc.ParameterDeclarations(),
        entities,
        storyboard,
        xosc.RoadNetwork(road),
        xosc.Catalog(),
        osc_minor_version=version,
    )


def sg_cut_in(path: Path, version: int) -> None:
    """A cut-in: the target, faster in the left lane, changes into the ego's lane once close."""
    entities = xosc.Entities()
    entities.add_scenario_object("Ego", _car("ego_car"))
    entities.add_scenario_object("Target", _car("target_car"))
    init = xosc.Init()
    init.add_init_action("Ego", xosc.TeleportAction(xosc.LanePosition(50, 0, -2, 1)))
    init.add_init_action("Ego", _speed(20))
    init.add_init_action("Target", xosc.TeleportAction(xosc.LanePosition(30, 0, -1, 1)))
    init.add_init_action("Target", _speed(25))
    close = xosc.EntityTrigger(
        "close",
        0,
        xosc.ConditionEdge.none,
        xosc.RelativeDistanceCondition(
            15, xosc.Rule.lessThan, xosc.RelativeDistanceType.longitudinal, "Ego"
        ),
        "Target",
    )
    change = xosc.Event("cut_in", _priority(version))
    change.add_action(
        "lane_change",
        xosc.AbsoluteLaneChangeAction(
            -2,
            xosc.TransitionDynamics(
                xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.distance, 40
            ),
        ),
    )
    change.add_trigger(close)
    brake = xosc.Event("brake", _priority(version))
    brake.add_action(
        "brake_action",
        xosc.AbsoluteSpeedAction(
            15, xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, 3)
        ),
    )
    brake.add_trigger(
        xosc.ValueTrigger(
            "after_cut_in",
            0,
            xosc.ConditionEdge.none,
            xosc.StoryboardElementStateCondition(
                xosc.StoryboardElementType.event,
                "cut_in",
                xosc.StoryboardElementState.endTransition,
            ),
        )
    )
    maneuver = xosc.Maneuver("cut_in_maneuver")
    maneuver.add_event(change)
    maneuver.add_event(brake)
    group = xosc.ManeuverGroup("target_group")
    group.add_actor("Target")
    group.add_maneuver(maneuver)
    act = xosc.Act(
        "cut_in_act",
        xosc.ValueTrigger(
            "start",
            0,
            xosc.ConditionEdge.none,
            xosc.SimulationTimeCondition(0, xosc.Rule.greaterThan),
        ),
    )
    act.add_maneuver_group(group)
    story = xosc.Story("cut_in_story")
    story.add_act(act)
    stop = xosc.ValueTrigger(
        "stop",
        0,
        xosc.ConditionEdge.none,
        xosc.SimulationTimeCondition(20, xosc.Rule.greaterThan),
        "stop",
    )
    _scenario(
        "cut-in", entities, init, story, stop, str(FILES / "highway.xodr"), version
    ).write_xml(str(path))


def sg_pedestrian(path: Path, version: int) -> None:
    """A pedestrian crosses when the ego is near; the ego stops when the pedestrian is close."""
    entities = xosc.Entities()
    entities.add_scenario_object("hero", _car("hero_car"))
    walker = xosc.Pedestrian(
        "walker", 80, xosc.PedestrianCategory.pedestrian, xosc.BoundingBox(0.5, 0.6, 1.8, 0, 0, 0.9)
    )
    entities.add_scenario_object("walker", walker)
    init = xosc.Init()
    init.add_init_action("hero", xosc.TeleportAction(xosc.WorldPosition(1.75, -40, 0, math.pi / 2)))
    init.add_init_action("hero", _speed(8))
    init.add_init_action("walker", xosc.TeleportAction(xosc.WorldPosition(-4.5, -14, 0, 0)))
    there = xosc.WorldPosition(1.75, -20, 0, math.pi / 2)
    arrived = (
        xosc.DistanceCondition(
            3,
            xosc.Rule.lessThan,
            there,
            freespace=False,
            distance_type=xosc.RelativeDistanceType.euclidianDistance,
        )
        if version >= 2
        else xosc.ReachPositionCondition(there, 3)
    )
    near = xosc.EntityTrigger("hero_near", 0, xosc.ConditionEdge.none, arrived, "hero")
    walk = xosc.Event("walk", _priority(version))
    walk.add_action("walk_speed", _speed(1.5))
    walk.add_action("walk_route", xosc.AcquirePositionAction(xosc.WorldPosition(4.5, -14, 0, 0)))
    walk.add_trigger(near)
    stop_event = xosc.Event("hero_stops", _priority(version))
    stop_event.add_action(
        "hero_brakes",
        xosc.AbsoluteSpeedAction(
            0, xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, 5)
        ),
    )
    stop_event.add_trigger(
        xosc.EntityTrigger(
            "walker_close",
            0,
            xosc.ConditionEdge.none,
            xosc.RelativeDistanceCondition(
                10, xosc.Rule.lessThan, xosc.RelativeDistanceType.euclidianDistance, "walker"
            ),
            "hero",
        )
    )
    groups = []
    for actor, event in (("walker", walk), ("hero", stop_event)):
        maneuver = xosc.Maneuver(f"{actor}_maneuver")
        maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{actor}_group")
        group.add_actor(actor)
        group.add_maneuver(maneuver)
        groups.append(group)
    act = xosc.Act(
        "act",
        xosc.ValueTrigger(
            "start",
            0,
            xosc.ConditionEdge.none,
            xosc.SimulationTimeCondition(0, xosc.Rule.greaterThan),
        ),
    )
    for group in groups:
        act.add_maneuver_group(group)
    story = xosc.Story("crossing")
    story.add_act(act)
    stop = xosc.ValueTrigger(
        "stop",
        0,
        xosc.ConditionEdge.none,
        xosc.SimulationTimeCondition(25, xosc.Rule.greaterThan),
        "stop",
    )
    _scenario(
        "pedestrian",
        entities,
        init,
        story,
        stop,
        str(FILES.parents[2] / "maps" / "intersection.xodr"),
        version,
    ).write_xml(str(path))


@pytest.mark.parametrize("version", (0, 2, 3))
def test_scenariogeneration_cut_in(version: int, tmp_path: Path) -> None:
    source = tmp_path / "cut-in.xosc"
    sg_cut_in(source, version)
    imported = import_file(source)
    # The StopTrigger is only a time: the end also waits for that time (the run lasts it).
    assert kinds(imported.scenario) == [
        "Decelerate",
        "EndNode",
        "InVehicleRadius",
        "LaneChange",
        "RootNode",
        "TimeElapsed",
        # scenariogeneration's `SimulationTime > 0`: a step after the start (0.05 s).
        "TimeElapsed",
    ]
    # An absolute target lane is the LaneChange's targetLane.
    assert opaque_tags(imported.scenario) == set()
    change = next(n for n in imported.scenario.nodes if isinstance(n, scm.LaneChange))
    assert change.targetLane is not None
    brake = next(n for n in imported.scenario.nodes if isinstance(n, scm.Decelerate))
    assert (brake.targetSpeed.value, brake.rate.value) == (15.0, 3.0)  # from 25 m/s
    round_trip(source, tmp_path, f"1.{version}")


@pytest.mark.parametrize("version", (1, 3))
def test_scenariogeneration_pedestrian_crossing(version: int, tmp_path: Path) -> None:
    source = tmp_path / "pedestrian.xosc"
    sg_pedestrian(source, version)
    imported = import_file(source)
    assert kinds(imported.scenario) == [
        "Accelerate",
        "Cross",
        "EndNode",
        "InLocationRadius",
        "InVehicleRadius",
        # The walk's step speed and its crossing start together (a Cross leaves the speed
        # alone): the event's join.
        "JoinAllFinished",
        "RootNode",
        "Stop",
        "TimeElapsed",
        # scenariogeneration's `SimulationTime > 0`: a step after the start (0.05 s).
        "TimeElapsed",
    ]
    cross = next(n for n in imported.scenario.nodes if isinstance(n, scm.Cross))
    assert cross.referenceActor.name == "walker"
    round_trip(source, tmp_path, f"1.{version}")

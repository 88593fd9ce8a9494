"""Files read as esmini reads them (issue 24): parameters everywhere, `$` declarations, catalogs
found by folder or --catalog-path, MiscObjects, positions computed from the map, act states,
repeated event names and StopTriggers that end the run when they hold.

Each test writes a small file in the style of the public corpora; the expected values are worked
out by hand from the map `files/highway.xodr` (one straight road "1" along x, 1000 m, three
lanes of 3.5 m each side: lane -2 spans t = -3.5 .. -7, centre -5.25).
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

import scemlmodel as scm
from sceml.cli import cli
from sceml.export import build_xosc
from sceml.importer import XoscImportError, import_file
from sceml.maps import load_map
from sceml.maps.resolve import start_poses
from sceml.model.loading import load_scenario

FILES = Path(__file__).resolve().parent / "files"

CAR = """<Vehicle name="car" vehicleCategory="car">
  <BoundingBox><Center x="1.4" y="0" z="0.75"/><Dimensions width="2" length="5" height="1.5"/>
  </BoundingBox><Performance maxSpeed="50" maxAcceleration="5" maxDeceleration="8"/>
  <Axles><FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.6" positionX="2.8"
  positionZ="0.3"/><RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0"
  positionZ="0.3"/></Axles><Properties/></Vehicle>"""

LANE_START = """<Private entityRef="{name}"><PrivateAction><TeleportAction><Position>
  {position}</Position></TeleportAction></PrivateAction></Private>"""

SPEED_EVENT = """<Event name="{name}" priority="overwrite"><Action name="{name}Action">
  <PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="linear"
  value="2" dynamicsDimension="rate"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/>
  </SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Action>
  <StartTrigger><ConditionGroup><Condition name="{name}When" delay="0" conditionEdge="none">
  <ByValueCondition>{condition}</ByValueCondition></Condition></ConditionGroup></StartTrigger>
  </Event>"""

AT_START = '<SimulationTimeCondition value="0" rule="greaterThan"/>'

SCENARIO = """<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="t" author="t"/>
  <ParameterDeclarations>{declarations}</ParameterDeclarations>
  <CatalogLocations>{catalogs}</CatalogLocations>
  <RoadNetwork><LogicFile filepath="highway.xodr"/></RoadNetwork>
  <Entities>{entities}</Entities>
  <Storyboard>
    <Init><Actions>{init}</Actions></Init>
    <Story name="S"><Act name="A">
      <ManeuverGroup name="G" maximumExecutionCount="1">
        <Actors selectTriggeringEntities="false"><EntityRef entityRef="Ego"/></Actors>
        {maneuvers}
      </ManeuverGroup>
      <StartTrigger><ConditionGroup><Condition name="Go" delay="0" conditionEdge="none">
        <ByValueCondition>{act_start}</ByValueCondition></Condition></ConditionGroup>
      </StartTrigger>
    </Act></Story>
    <StopTrigger>{stop}</StopTrigger>
  </Storyboard>
</OpenSCENARIO>
"""

EGO_START = '<LanePosition roadId="1" laneId="-2" s="50" offset="0"/>'


def scenario(tmp_path: Path, **parts: str) -> Path:
    """A scenario beside the highway map; `parts` replace the template's defaults."""
    values = {
        "declarations": "",
        "catalogs": "",
        "entities": f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>',
        "init": LANE_START.format(name="Ego", position=EGO_START),
        "maneuvers": '<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=AT_START)
        + "</Maneuver>",
        "act_start": AT_START,
        "stop": "",
    }
    values.update(parts)
    shutil.copy(FILES / "highway.xodr", tmp_path / "highway.xodr")
    path = tmp_path / "scenario.xosc"
    path.write_text(SCENARIO.format(**values))
    return path


def actors(imported: scm.Scenario) -> list[scm.Actor]:
    root = next(n for n in imported.nodes if isinstance(n, scm.RootNode))
    return list(root.actors)


def actor(imported: scm.Scenario, name: str) -> scm.Actor:
    return next(a for a in actors(imported) if a.name == name)


def guessed(imported, words: str) -> list[str]:  # type: ignore[no-untyped-def]
    return [e.message for e in imported.report.section("guessed") if words in e.message]


# --- parameters and catalogs ---------------------------------------------------------------


def test_dollar_declarations_and_parameter_entry_and_catalog_names(tmp_path: Path) -> None:
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    path = scenario(
        tmp_path,
        # As scenariogeneration writes them: the declared name carries the `$`.
        declarations='<ParameterDeclaration name="$Model" parameterType="string" '
        'value="truck_yellow"/><ParameterDeclaration name="$Cat" parameterType="string" '
        'value="VehicleCatalog"/><ParameterDeclaration name="$Speed" parameterType="double" '
        'value="12"/>',
        catalogs='<VehicleCatalog><Directory path="catalogs"/></VehicleCatalog>',
        entities='<ScenarioObject name="Ego"><CatalogReference catalogName="$Cat" '
        'entryName="$Model"/></ScenarioObject>',
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed="$Speed", condition=AT_START)
        + "</Maneuver>",
    )
    imported = import_file(path)
    assert isinstance(actor(imported.scenario, "Ego"), scm.Truck)
    assert imported.report.catalog_entries == ["VehicleCatalog/truck_yellow"]
    go = next(n for n in imported.scenario.nodes if isinstance(n, scm.Accelerate))
    assert go.targetSpeed.value == 12.0


def test_catalog_path_finds_what_catalog_locations_do_not(tmp_path: Path) -> None:
    elsewhere = tmp_path / "shared"
    shutil.copytree(FILES / "catalogs", elsewhere)
    (tmp_path / "here").mkdir()
    path = scenario(
        tmp_path / "here",
        entities='<ScenarioObject name="Ego"><CatalogReference catalogName="VehicleCatalog" '
        'entryName="car_white"/></ScenarioObject>',
    )
    runner = CliRunner()
    out = str(tmp_path / "out.xmi")
    refused = runner.invoke(cli, ["import", str(path), "-o", out])
    assert refused.exit_code == 2 and "catalog 'VehicleCatalog' not found" in refused.output
    found = runner.invoke(cli, ["import", str(path), "-o", out, "--catalog-path", str(elsewhere)])
    assert found.exit_code == 0, found.output
    model = load_scenario(out).root
    assert [type(a).__name__ for a in actors(model)] == ["Car"]


def test_an_entry_missing_from_its_named_catalog_is_found_in_another(tmp_path: Path) -> None:
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    path = scenario(
        tmp_path,
        catalogs='<VehicleCatalog><Directory path="catalogs"/></VehicleCatalog>',
        entities='<ScenarioObject name="Ego"><CatalogReference catalogName="CarCatalog" '
        'entryName="car_white"/></ScenarioObject>',
    )
    imported = import_file(path)
    assert isinstance(actor(imported.scenario, "Ego"), scm.Car)
    assert guessed(imported, "catalog 'CarCatalog' has no entry 'car_white': taken from")


def test_a_misc_object_is_a_car_of_its_size_and_the_report_keeps_its_category(
    tmp_path: Path,
) -> None:
    barrier = (
        '<ScenarioObject name="Barrier"><MiscObject mass="100" miscObjectCategory="barrier" '
        'name="barrier"><BoundingBox><Center x="0" y="0" z="0.5"/><Dimensions width="0.5" '
        'length="10" height="1"/></BoundingBox><Properties/></MiscObject></ScenarioObject>'
    )
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>{barrier}',
        init=LANE_START.format(name="Ego", position=EGO_START)
        + LANE_START.format(
            name="Barrier", position='<LanePosition roadId="1" laneId="-1" s="80" offset="0"/>'
        ),
    )
    imported = import_file(path)
    made = actor(imported.scenario, "Barrier")
    assert isinstance(made, scm.Car) and not made.isEgo
    assert (made.length.value, made.width.value, made.height.value) == (10.0, 0.5, 1.0)
    assert guessed(imported, "MiscObject of category barrier as a Car")


# --- positions -------------------------------------------------------------------------------


def start_of(tmp_path: Path, position: str) -> tuple[scm.Position, list[str]]:
    """The start of a second car placed by `position` (relative ones refer to Ego)."""
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Other">{CAR}</ScenarioObject>',
        init=LANE_START.format(name="Ego", position=EGO_START)
        + LANE_START.format(name="Other", position=position),
    )
    imported = import_file(path)
    start = actor(imported.scenario, "Other").startPosition
    assert start is not None
    return start, guessed(imported, "computed as the")


def lane(position: scm.Position) -> tuple[str, int, float, float]:
    assert isinstance(position, scm.LanePosition)
    return (
        str(position.roadId),
        int(position.laneId),
        round(position.s.value, 6),
        round(position.offset.value, 6),
    )


def test_a_road_position_stays_a_road_position(tmp_path: Path) -> None:
    start, told = start_of(
        tmp_path,
        '<RoadPosition roadId="1" s="120" t="-5.5"><Orientation type="relative" h="0.25"/>'
        "</RoadPosition>",
    )
    assert isinstance(start, scm.RoadPosition)
    assert (start.roadId, start.s.value, start.t.value, start.h.value) == ("1", 120.0, -5.5, 0.25)
    assert not told  # nothing computed: the road coordinate is kept as written


def test_a_road_position_with_an_absolute_heading_keeps_it_relative_to_the_road(
    tmp_path: Path,
) -> None:
    # Road 1 runs along x (heading 0): an absolute 0.3 is 0.3 relative to the road.
    start, _ = start_of(
        tmp_path,
        '<RoadPosition roadId="1" s="120" t="-5.5"><Orientation type="absolute" h="0.3"/>'
        "</RoadPosition>",
    )
    assert isinstance(start, scm.RoadPosition)
    assert (start.s.value, start.t.value, start.h.value) == (120.0, -5.5, pytest.approx(0.3))


def where(tmp_path: Path, position: str) -> tuple[scm.Position, tuple[float, float, float]]:
    """The start of the second car, and the world pose it resolves to among the starts."""
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Other">{CAR}</ScenarioObject>',
        init=LANE_START.format(name="Ego", position=EGO_START)
        + LANE_START.format(name="Other", position=position),
    )
    actors = import_file(path).scenario.nodes[0].actors
    poses = start_poses(actors, load_map(FILES / "highway.xodr"))
    other = next(a for a in actors if a.name == "Other")
    pose = poses[other]
    return other.startPosition, (round(pose.x, 6), round(pose.y, 6), round(pose.heading, 6))


@pytest.mark.parametrize(
    ("relative", "kind", "expected"),
    [
        # Ego is in lane -2 at s = 50: one lane to the left is -1 (centre -1.75), 20 m behind
        # is s = 30, 0.5 m left of the centre.
        (
            '<RelativeLanePosition entityRef="Ego" dLane="1" ds="-20" offset="0.5"/>',
            "RelativeLanePosition",
            (30.0, -1.25, 0.0),
        ),
        # Three lanes to the left crosses the reference line: -2, -1, (no 0), 1, 2 (centre
        # 5.25), whose traffic runs against s.
        (
            '<RelativeLanePosition entityRef="Ego" dLane="3" ds="0"/>',
            "RelativeLanePosition",
            (50.0, 5.25, 3.141593),
        ),
        # Ego's t is -5.25; 3.5 m further left is -1.75, the centre of lane -1.
        (
            '<RelativeRoadPosition entityRef="Ego" ds="15" dt="3.5"/>',
            "RelativeRoadPosition",
            (65.0, -1.75, 0.0),
        ),
        # Ego stands at (50, -5.25) heading along x: 10 ahead, 2 left, turned by 0.5.
        (
            '<RelativeObjectPosition entityRef="Ego" dx="10" dy="2"><Orientation type="relative" '
            'h="0.5"/></RelativeObjectPosition>',
            "RelativeObjectPosition",
            (60.0, -3.25, 0.5),
        ),
        (
            '<RelativeWorldPosition entityRef="Ego" dx="-3" dy="4"/>',
            "RelativeWorldPosition",
            (47.0, -1.25, 0.0),
        ),
    ],
)
def test_relative_positions_are_kept_and_resolve_from_the_entity(
    tmp_path: Path, relative: str, kind: str, expected: tuple[float, float, float]
) -> None:
    start, pose = where(tmp_path, relative)
    assert start.eClass.name == kind
    assert start.entity.name == "Ego"
    assert pose == pytest.approx(expected)


def test_a_relative_lane_position_measured_along_the_lane_is_computed(tmp_path: Path) -> None:
    # dsLane (1.1+) is measured along the lane, SceML's ds along the road: computed as the lane
    # position it stands for at the start, and reported.
    start, told = start_of(
        tmp_path, '<RelativeLanePosition entityRef="Ego" dLane="1" dsLane="-20" offset="0.5"/>'
    )
    assert lane(start) == ("1", -1, 30.0, 0.5)
    assert told


def test_a_relative_position_reads_a_road_position_start(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Other">{CAR}</ScenarioObject>',
        init=LANE_START.format(name="Ego", position='<RoadPosition roadId="1" s="50" t="-5.5"/>')
        + LANE_START.format(
            name="Other", position='<RelativeLanePosition entityRef="Ego" dLane="1" ds="10"/>'
        ),
    )
    # Ego's t = -5.5 lies in lane -2 (-3.5 .. -7); one lane to the left is -1 (centre -1.75).
    actors = import_file(path).scenario.nodes[0].actors
    poses = start_poses(actors, load_map(FILES / "highway.xodr"))
    pose = poses[next(a for a in actors if a.name == "Other")]
    assert (pose.x, pose.y) == pytest.approx((60.0, -1.75))


@pytest.mark.parametrize("d_lane", [1, -1])
def test_a_change_into_the_lane_of_an_actor_placed_relative_keeps_that_actor(
    tmp_path: Path, d_lane: int
) -> None:
    # LaneChange names the actor whose lane it goes into (metamodel 1.1): no left/right guess.
    change = (
        '<Maneuver name="M"><Event name="Change" priority="overwrite"><Action name="ChangeAction">'
        "<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics "
        'dynamicsShape="sinusoidal" value="3" dynamicsDimension="time"/><LaneChangeTarget>'
        '<RelativeTargetLane entityRef="Other" value="0"/></LaneChangeTarget></LaneChangeAction>'
        "</LateralAction></PrivateAction></Action><StartTrigger><ConditionGroup>"
        f'<Condition name="When" delay="0" conditionEdge="none"><ByValueCondition>{AT_START}'
        "</ByValueCondition></Condition></ConditionGroup></StartTrigger></Event></Maneuver>"
    )
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Other">{CAR}</ScenarioObject>',
        # Ego's t = -5.5 is in lane -2; Other starts a lane to the left (-1) or right (-3).
        init=LANE_START.format(name="Ego", position='<RoadPosition roadId="1" s="50" t="-5.5"/>')
        + LANE_START.format(
            name="Other",
            position=f'<RelativeLanePosition entityRef="Ego" dLane="{d_lane}" ds="20"/>',
        ),
        maneuvers=change,
    )
    node = next(n for n in import_file(path).scenario.nodes if n.name == "Change")
    assert node.eClass.name == "LaneChange"
    assert (node.targetActor.name, node.lanes) == ("Other", 0)


# --- storyboard --------------------------------------------------------------------------


def test_an_event_waiting_for_its_own_act_to_start_is_no_circular_trigger(tmp_path: Path) -> None:
    own_act = (
        '<StoryboardElementStateCondition storyboardElementType="act" '
        'storyboardElementRef="A" state="startTransition"/>'
    )
    path = scenario(
        tmp_path,
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=own_act)
        + "</Maneuver>",
        act_start='<SimulationTimeCondition value="2" rule="greaterThan"/>',
    )
    imported = import_file(path)
    go = next(n for n in imported.scenario.nodes if isinstance(n, scm.Accelerate))
    # The act starts once more than 2 s have passed (2.05 s, as esmini starts it): the event
    # follows that wait, not itself.
    before = go.incoming[0].source
    assert isinstance(before, scm.TimeElapsed) and before.duration.value == 2.05


def test_one_event_name_in_two_maneuvers(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        maneuvers='<Maneuver name="M1">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=AT_START)
        + '</Maneuver><Maneuver name="M2">'
        + SPEED_EVENT.format(
            name="Go",
            speed=0,
            condition='<SimulationTimeCondition value="5" rule="greaterThan"/>',
        )
        + "</Maneuver>",
    )
    imported = import_file(path)
    assert {n.eClass.name for n in imported.scenario.nodes} >= {"Accelerate", "Stop"}
    assert guessed(imported, "a second event named 'Go' (in maneuver 'M2') is 'Go_in_M2'")


def test_a_stop_trigger_ends_the_run_without_waiting_for_branches_it_does_not_name(
    tmp_path: Path,
) -> None:
    path = scenario(
        tmp_path,
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=AT_START)
        + SPEED_EVENT.format(
            name="Never",
            speed=0,
            condition='<SimulationTimeCondition value="1000" rule="greaterThan"/>',
        )
        + "</Maneuver>",
        stop='<ConditionGroup><Condition name="Done" delay="3" conditionEdge="rising">'
        '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" '
        'storyboardElementRef="Go" state="endTransition"/></ByValueCondition></Condition>'
        "</ConditionGroup>",
    )
    imported = import_file(path)
    end = next(n for n in imported.scenario.nodes if isinstance(n, scm.EndNode))
    assert end.policy is scm.JoinPolicy.joinOne
    inputs = {f.source.eClass.name: f.source for f in end.incoming}
    # Three seconds after Go; the branch the StopTrigger does not name reaches the end only
    # together with those three seconds, so it can neither end the run sooner nor later.
    assert set(inputs) == {"TimeElapsed", "JoinAllFinished"}
    assert inputs["TimeElapsed"].duration.value == 3.0
    rest = {f.source.eClass.name: f.source for f in inputs["JoinAllFinished"].incoming}
    assert set(rest) == {"Stop", "TimeElapsed"}
    assert rest["TimeElapsed"] is inputs["TimeElapsed"]
    # Written back, the StopTrigger is Go's end and 3 s, and the time limit: Never is not in it.
    stop = build_xosc(imported.scenario, version="1.1", source_path=path).tree.find(
        "Storyboard/StopTrigger"
    )
    refs = [c.get("storyboardElementRef") for c in stop.iter("StoryboardElementStateCondition")]
    assert refs == ["Go"]
    assert [c.get("delay") for c in stop.iter("Condition")][0] == "3.0"


def test_a_time_only_stop_trigger_makes_the_run_last_that_long(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        stop='<ConditionGroup><Condition name="Time" delay="0" conditionEdge="rising">'
        '<ByValueCondition><SimulationTimeCondition value="120" rule="greaterThan"/>'
        "</ByValueCondition></Condition></ConditionGroup>",
    )
    imported = import_file(path)
    root = next(n for n in imported.scenario.nodes if isinstance(n, scm.RootNode))
    end = next(n for n in imported.scenario.nodes if isinstance(n, scm.EndNode))
    assert root.maxDuration.value == 120.0
    # The end waits until the limit holds: `> 120` a step after 120 s, as esmini stops.
    waits = [f.source for f in end.incoming if isinstance(f.source, scm.TimeElapsed)]
    assert [w.duration.value for w in waits] == [pytest.approx(120.05)]
    assert end.policy is scm.JoinPolicy.joinAll


def test_pi_and_names_that_are_not_numbers(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        init=LANE_START.format(
            name="Ego",
            position='<WorldPosition x="10" y="-5.25" h="${$Half * pi}"/>',
        ),
        declarations='<ParameterDeclaration name="Half" parameterType="double" value="0.5"/>',
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=AT_START).replace(
            'name="GoWhen"', 'name="${When + _ + $Half}"'
        )
        + "</Maneuver>",
    )
    imported = import_file(path)
    start = actor(imported.scenario, "Ego").startPosition
    assert isinstance(start, scm.WorldPosition)
    assert round(start.h.value, 9) == round(3.141592653589793 / 2, 9)


def test_an_uncomputable_number_is_still_refused(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed="${When + 1}", condition=AT_START)
        + "</Maneuver>",
    )
    with pytest.raises(XoscImportError, match="unexpected 'When'") as caught:
        import_file(path)
    assert caught.value.line is not None


def test_a_gradual_init_speed_change_is_a_maneuver_from_the_start(tmp_path: Path) -> None:
    gradual = (
        '<Private entityRef="Ego"><PrivateAction><LongitudinalAction><SpeedAction>'
        '<SpeedActionDynamics dynamicsShape="linear" value="4" dynamicsDimension="rate"/>'
        '<SpeedActionTarget><AbsoluteTargetSpeed value="20"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction></Private>"
    )
    path = scenario(
        tmp_path,
        init=LANE_START.format(name="Ego", position=EGO_START) + gradual,
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(
            name="Slow",
            speed=5,
            condition='<SimulationTimeCondition value="10" rule="greaterThan"/>',
        )
        + "</Maneuver>",
    )
    imported = import_file(path)
    ego = actor(imported.scenario, "Ego")
    # esmini starts the car at rest and speeds it up at 4 m/s² (20 m/s after 5 s).
    assert ego.initialSpeed is None or ego.initialSpeed.value == 0.0
    speed_up = next(n for n in imported.scenario.nodes if isinstance(n, scm.Accelerate))
    assert isinstance(speed_up.incoming[0].source, scm.RootNode)
    assert (speed_up.targetSpeed.value, speed_up.rate.value) == (20.0, 4.0)
    # The later change is read from 20 m/s: down to 5 is a deceleration.
    assert any(isinstance(n, scm.Decelerate) for n in imported.scenario.nodes)


def test_a_lane_offset_reaching_into_the_next_lane_is_that_lane(tmp_path: Path) -> None:
    # Lane -1's centre is t = -1.75; 3.5 m further right is -5.25, the centre of lane -2.
    start, _ = start_of(tmp_path, '<LanePosition roadId="1" laneId="-1" s="70" offset="-3.5"/>')
    assert lane(start) == ("1", -2, 70.0, 0.0)
    # Within its lane, a position stays as written.
    start, _ = start_of(tmp_path, '<LanePosition roadId="1" laneId="-1" s="70" offset="-1"/>')
    assert lane(start) == ("1", -1, 70.0, -1.0)
    assert start.h is None


def test_a_lane_offset_reaching_across_the_centre_keeps_facing_its_own_lanes_way(
    tmp_path: Path,
) -> None:
    # 3.5 m left of lane -1's centre (t = -1.75) is t = 1.75, the centre of lane 1, whose traffic
    # runs the other way: without an Orientation the actor faces along lane -1 (increasing s),
    # so in lane 1 it faces backwards (speed-profile's Car2 drove the wrong way).
    start, _ = start_of(tmp_path, '<LanePosition roadId="1" laneId="-1" s="70" offset="3.5"/>')
    assert lane(start) == ("1", 1, 70.0, 0.0)
    assert abs(start.h.value) == pytest.approx(math.pi)
    # A written heading is kept relative to the lane it now lies in: 0.2 rad off lane -1's way.
    start, _ = start_of(
        tmp_path,
        '<LanePosition roadId="1" laneId="-1" s="70" offset="3.5">'
        '<Orientation type="relative" h="0.2"/></LanePosition>',
    )
    assert start.h.value == pytest.approx(0.2 - math.pi)


def test_with_a_time_limit_too_it_is_the_maximum_duration_and_the_stop_alone_ends_the_run(
    tmp_path: Path,
) -> None:
    path = scenario(
        tmp_path,
        maneuvers='<Maneuver name="M">'
        + SPEED_EVENT.format(name="Go", speed=10, condition=AT_START)
        + SPEED_EVENT.format(
            name="Later",
            speed=0,
            condition='<SimulationTimeCondition value="5" rule="greaterThan"/>',
        )
        + "</Maneuver>",
        stop='<ConditionGroup><Condition name="Done" delay="0" conditionEdge="rising">'
        '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" '
        'storyboardElementRef="Go" state="endTransition"/></ByValueCondition></Condition>'
        '</ConditionGroup><ConditionGroup><Condition name="Time" delay="0" conditionEdge="rising">'
        '<ByValueCondition><SimulationTimeCondition value="300" rule="greaterThan"/>'
        "</ByValueCondition></Condition></ConditionGroup>",
    )
    imported = import_file(path)
    root = next(n for n in imported.scenario.nodes if isinstance(n, scm.RootNode))
    assert root.maxDuration.value == 300.0
    rest = next(n for n in imported.scenario.nodes if n.name == "branches_done")
    # Later (the branch not named) joined with Go (what the StopTrigger waits for).
    assert sorted(f.source.name for f in rest.incoming) == ["Go", "Later"]


def test_the_conditions_of_one_group_are_a_group_not_a_chain(tmp_path: Path) -> None:
    def speed(name: str, value: int) -> str:
        return (
            f'<Condition name="{name}" delay="0" conditionEdge="none"><ByEntityCondition>'
            '<TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/>'
            f'</TriggeringEntities><EntityCondition><SpeedCondition value="{value}" '
            'rule="greaterThan"/></EntityCondition></ByEntityCondition></Condition>'
        )

    path = scenario(
        tmp_path,
        stop='<ConditionGroup><Condition name="Late" delay="0" conditionEdge="none">'
        '<ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" '
        'storyboardElementRef="Go" state="completeState"/></ByValueCondition></Condition>'
        f"{speed('Fast', 8)}{speed('Faster', 9)}</ConditionGroup>",
    )
    imported = import_file(path)
    checks = [n for n in imported.scenario.nodes if isinstance(n, scm.SpeedCondition)]
    go = next(n for n in imported.scenario.nodes if isinstance(n, scm.Accelerate))
    # Both speeds are watched from the moment Go has finished, side by side, and meet in one join.
    assert sorted(c.name for c in checks) == ["Fast", "Faster"]
    assert all([f.source for f in c.incoming] == [go] for c in checks)
    joins = {f.target.name for c in checks for f in c.outgoing}
    assert len(joins) == 1


# --- same run: opaque conditions and relative speeds ---------------------------------------

# An end of road condition: a kind SceML keeps opaque (StandStill maps since release 1.4).
END_OF_ROAD = (
    '<ConditionGroup><Condition name="RoadEnd" delay="4" conditionEdge="rising"><ByEntityCondition>'
    '<TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/>'
    '</TriggeringEntities><EntityCondition><EndOfRoadCondition duration="1"/>'
    "</EntityCondition></ByEntityCondition></Condition></ConditionGroup>"
)


def test_an_opaque_conditions_delay_is_waited_for_once(tmp_path: Path) -> None:
    imported = import_file(scenario(tmp_path, stop=END_OF_ROAD))
    kept = next(n for n in imported.scenario.nodes if isinstance(n, scm.OpaqueAction))
    wait = next(f.target for f in kept.outgoing)
    # The 4 s are the TimeElapsed after the node; the kept XML no longer waits for them too.
    assert isinstance(wait, scm.TimeElapsed)
    assert wait.duration.value == 4.0
    assert 'delay="0"' in kept.xml
    assert 'conditionEdge="rising"' in kept.xml
    stop = build_xosc(imported.scenario, version="1.1", source_path=tmp_path / "s.xosc").tree
    kept_xml = [c for c in stop.iter("Condition") if c.find(".//EndOfRoadCondition") is not None]
    waits = [
        c.get("delay")
        for c in stop.iterfind("Storyboard/StopTrigger//Condition")
        if c.find(".//StoryboardElementStateCondition") is not None
    ]
    # Written back: the kept condition without its delay, and 4 s on what follows it, once.
    assert [c.get("delay") for c in kept_xml] == ["0"]
    assert waits == ["4.0"]


def test_a_story_relative_target_speed_is_worked_out_and_a_later_timed_change_kept(
    tmp_path: Path,
) -> None:
    relative = (
        '<Event name="Follow" priority="overwrite"><Action name="FollowAction"><PrivateAction>'
        '<LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" '
        'dynamicsDimension="time"/><SpeedActionTarget><RelativeTargetSpeed entityRef="Lead" '
        'value="1.5" speedTargetValueType="factor" continuous="true"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction></Action><StartTrigger>"
        '<ConditionGroup><Condition name="FollowWhen" delay="0" conditionEdge="none">'
        f"<ByValueCondition>{AT_START}</ByValueCondition></Condition></ConditionGroup>"
        "</StartTrigger></Event>"
    )
    change = (
        '<Event name="Change" priority="overwrite"><Action name="ChangeAction"><PrivateAction>'
        '<LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" '
        'value="3" dynamicsDimension="time"/><LaneChangeTarget><RelativeTargetLane '
        'entityRef="Ego" value="1"/></LaneChangeTarget></LaneChangeAction></LateralAction>'
        '</PrivateAction></Action><StartTrigger><ConditionGroup><Condition name="ChangeWhen" '
        'delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="2" '
        'rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>'
        "</Event>"
    )
    lead_speed = (
        '<Private entityRef="Lead"><PrivateAction><TeleportAction><Position>'
        '<LanePosition roadId="1" laneId="-1" s="80" offset="0"/></Position></TeleportAction>'
        "</PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics "
        'dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget>'
        '<AbsoluteTargetSpeed value="20"/></SpeedActionTarget></SpeedAction>'
        "</LongitudinalAction></PrivateAction></Private>"
    )
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Lead">{CAR}</ScenarioObject>',
        init=LANE_START.format(name="Ego", position=EGO_START) + lead_speed,
        maneuvers=f'<Maneuver name="M">{relative}{change}</Maneuver>',
    )
    imported = import_file(path)
    lane_change = next(n for n in imported.scenario.nodes if isinstance(n, scm.LaneChange))
    # Lead drives 20 m/s, Ego 1.5 times that: the speed is still worked out (a change given
    # as a rate needs it), but a change given in time keeps its 3 s (release 1.5), whatever
    # the speed then.
    assert (lane_change.distance, lane_change.duration.value) == (None, 3.0)
    assert guessed(imported, "relative target speed taken as 30 m/s")


def test_a_lane_change_in_time_after_a_continuous_init_relative_speed_keeps_its_time(
    tmp_path: Path,
) -> None:
    # As `lane_change_crest`: the Ego's Init speed is 1.3 times the Lead's, continuously (kept
    # as an Init action: SceML has no field for it); its 2 s lane change stays 2 s, neither
    # metres at that speed nor LaneChange's default 30 m.
    lead = (
        '<Private entityRef="Lead"><PrivateAction><TeleportAction><Position>'
        '<LanePosition roadId="1" laneId="-1" s="80" offset="0"/></Position></TeleportAction>'
        "</PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics "
        'dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget>'
        '<AbsoluteTargetSpeed value="15"/></SpeedActionTarget></SpeedAction>'
        "</LongitudinalAction></PrivateAction></Private>"
    )
    ego = (
        '<Private entityRef="Ego"><PrivateAction><TeleportAction><Position>'
        f"{EGO_START}</Position></TeleportAction></PrivateAction><PrivateAction>"
        '<LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" '
        'dynamicsDimension="time"/><SpeedActionTarget><RelativeTargetSpeed entityRef="Lead" '
        'value="1.3" speedTargetValueType="factor" continuous="true"/></SpeedActionTarget>'
        "</SpeedAction></LongitudinalAction></PrivateAction></Private>"
    )
    change = (
        '<Event name="Change" priority="overwrite"><Action name="ChangeAction"><PrivateAction>'
        '<LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="cubic" '
        'value="2" dynamicsDimension="time"/><LaneChangeTarget><RelativeTargetLane '
        'entityRef="Lead" value="0"/></LaneChangeTarget></LaneChangeAction></LateralAction>'
        '</PrivateAction></Action><StartTrigger><ConditionGroup><Condition name="ChangeWhen" '
        f'delay="0" conditionEdge="none"><ByValueCondition>{AT_START}</ByValueCondition>'
        "</Condition></ConditionGroup></StartTrigger></Event>"
    )
    path = scenario(
        tmp_path,
        entities=f'<ScenarioObject name="Lead">{CAR}</ScenarioObject>'
        f'<ScenarioObject name="Ego">{CAR}</ScenarioObject>',
        init=lead + ego,
        maneuvers=f'<Maneuver name="M">{change}</Maneuver>',
    )
    imported = import_file(path)
    lane_change = next(n for n in imported.scenario.nodes if isinstance(n, scm.LaneChange))
    # Kept as the 2 s it was given in (release 1.5), not as metres at 1.3 * 15 = 19.5 m/s.
    assert (lane_change.distance, lane_change.duration.value) == (None, 2.0)
    assert not guessed(imported, "the lane change's time taken at")

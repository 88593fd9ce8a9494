"""Build the corpus of invalid models (one fault or several per file) and its MANIFEST.

    python tests/validation/make_corpus.py [--out DIR]

Each case is built with the public builder API and saved with io_save; faults the builder cannot
express (dangling flows, broken hrefs) are made by editing the saved XML. MANIFEST lists every
case with the rule codes validation must report for it, nothing more and nothing less; a line
with no codes is a model that must validate clean. The committed corpus must equal this output.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path

from lxml import etree

import scemlmodel as scm
from sceml.files.writing import write_atomically
from sceml.model.build import (
    LibraryBuilder,
    ScenarioBuilder,
    activation,
    controller,
    lane,
    override,
    relative_lane,
    relative_object,
    road,
    world,
)
from sceml.model.loading import load_library
from sceml.model.params import discrete, normal, span, uniform
from sceml.model.saving import save as io_save

HERE = Path(__file__).resolve().parent / "corpus"
DATE = "2026-01-01T00:00:00"
LIBRARY = "lib/modules.xmi"
#: The repository's intersection map, from the corpus folder: the map rules (SCEML-R) read it.
MAP = "../../../maps/intersection.xodr"

Case = Callable[[Path], None]
CASES: list[tuple[str, str, Case]] = []


def case(name: str, codes: str) -> Callable[[Case], Case]:
    """Register a case writing `<name>.xmi` that must give exactly `codes`."""

    def register(build: Case) -> Case:
        CASES.append((f"{name}.xmi", codes, build))
        return build

    return register


def scenario(level: str = "concrete", **options: object) -> tuple[ScenarioBuilder, scm.Actor]:
    """A scenario with a map and one ego car, ready for one fault to be added."""
    b = ScenarioBuilder("Case", map=MAP, level=level, date=DATE, **options)  # type: ignore[arg-type]
    ego = b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0), speed=5.0)
    return b, ego


def save(root: object, out: Path, name: str) -> Path:
    return io_save(root, out / name)  # type: ignore[arg-type]


def edit_xml(path: Path, change: Callable[[etree._Element], None]) -> None:
    """Change a saved file's XML in place (for faults no API call produces)."""
    tree = etree.parse(str(path))
    change(tree.getroot())
    path.write_bytes(etree.tostring(tree, xml_declaration=True, encoding="UTF-8"))


def library() -> scm.Library:
    """A small valid library: CrossingManeuver (as in the examples) and Speedup for any road user."""
    lib = LibraryBuilder("Corpus library")
    crossing = lib.module("CrossingManeuver")
    crosser = crossing.role("crosser", "TwoWheeler", "Pedestrian")
    trigger = crossing.role("trigger", "FourWheeler")
    radius = crossing.parameter("triggerRadius", "m", 10.0)
    speed = crossing.parameter("crossingSpeed", "m/s", 1.5)
    x, y = crossing.parameter("destinationX", "m"), crossing.parameter("destinationY", "m")
    wait = crossing.add("InVehicleRadius", crosser, target=trigger, radius=radius)
    go = crossing.add("Accelerate", crosser, targetSpeed=speed)
    cross = crossing.add("Cross", crosser, destination=world(x, y))
    crossing.chain(crossing.in_port, wait, go, cross, crossing.out_port)
    speedup = lib.module("Speedup")
    driver = speedup.role("driver")
    target = speedup.parameter("target", "m/s", 10.0)
    faster = speedup.add("Accelerate", driver, targetSpeed=target)
    speedup.chain(speedup.in_port, faster, speedup.out_port)
    return lib.library


@case("lib/modules", "")
def valid_library(out: Path) -> None:
    save(library(), out, LIBRARY)


def definition(out: Path, name: str) -> scm.ModuleDefinition:
    """A module of the corpus library, loaded from `out` so that uses refer to it across files."""
    if not (out / LIBRARY).exists():
        save(library(), out, LIBRARY)
    return next(m for m in load_library(out / LIBRARY).root.modules if m.name == name)


def crossing_scenario(level: str = "concrete") -> tuple[ScenarioBuilder, dict[str, scm.Actor]]:
    """A scenario with an ego car, a second car and a pedestrian, for module-use cases."""
    b, ego = scenario(level)
    car = b.actor("Car", "car", start=lane(1, 1, 30.0))
    walker = b.actor("Pedestrian", "walker", start=lane(4, 2, 1.0))
    return b, {"ego": ego, "car": car, "walker": walker}


DESTINATION = {"destinationX": -10.0, "destinationY": 4.5}


def crossing_use(
    out: Path,
    name: str,
    bindings: Callable[[dict[str, scm.Actor]], dict[str, scm.Actor]],
    overrides: dict | None = None,
    level: str = "concrete",
) -> None:
    """A scenario whose only part is one use of CrossingManeuver, bound and overridden as given."""
    b, cast = crossing_scenario(level)
    given = DESTINATION if overrides is None else overrides
    use = b.use(definition(out, "CrossingManeuver"), bindings(cast), given)
    b.chain(b.root, use, b.end)
    save(b.scenario, out, name)


# Structure -----------------------------------------------------------------------------------


@case("s001-two-roots", "SCEML-S001 SCEML-S007 SCEML-A007")
def two_roots(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    b.scenario.nodes.append(scm.RootNode(name="Root2", map=MAP))
    save(b.scenario, out, "s001-two-roots.xmi")


@case("s001-no-root", "SCEML-S001")
def no_root(out: Path) -> None:
    bare = scm.Scenario()
    bare.nodes.append(scm.EndNode(name="End"))
    save(bare, out, "s001-no-root.xmi")


@case("s002-no-end", "SCEML-S002")
def no_end(out: Path) -> None:
    b, ego = scenario()
    b.scenario.nodes.remove(b.end)
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0))
    save(b.scenario, out, "s002-no-end.xmi")


@case("s003-root-incoming", "SCEML-S003 SCEML-S006")
def root_incoming(out: Path) -> None:
    b, ego = scenario()
    orphan = b.add("TimeElapsed", ego, name="Orphan", duration=1.0)
    b.chain(orphan, b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "s003-root-incoming.xmi")


@case("s004-join-one-input", "SCEML-S004")
def join_one_input(out: Path) -> None:
    b, ego = scenario()
    accelerate = b.add("Accelerate", ego, targetSpeed=8.0)
    b.chain(b.root, accelerate)
    b.chain(b.join_all(accelerate), b.end)
    save(b.scenario, out, "s004-join-one-input.xmi")


@case("s005-end-outgoing", "SCEML-S005 SCEML-S007")
def end_outgoing(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    b.flow(b.end, b.add("TimeElapsed", ego, name="After", duration=1.0))
    save(b.scenario, out, "s005-end-outgoing.xmi")


@case("s006-unreachable", "SCEML-S006")
def unreachable(out: Path) -> None:
    b, ego = scenario()
    accelerate = b.add("Accelerate", ego, targetSpeed=8.0)
    island = b.add("TimeElapsed", ego, name="Island", duration=2.0)
    b.chain(b.root, accelerate)
    b.chain(b.join_all(accelerate, island), b.end)
    save(b.scenario, out, "s006-unreachable.xmi")


@case("s007-dead-end", "SCEML-S007")
def dead_end(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("TimeElapsed", ego, name="Nowhere", duration=1.0))
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "s007-dead-end.xmi")


@case("s008-cycle", "SCEML-S008")
def cycle(out: Path) -> None:
    b, ego = scenario()
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    hold = b.add("KeepVelocity", ego, duration=3.0)
    join = b.join_all(b.root)
    b.chain(join, speed_up, hold, b.end)
    b.flow(hold, join)
    save(b.scenario, out, "s008-cycle.xmi")


@case("s009-merge-without-join", "SCEML-S009")
def merge_without_join(out: Path) -> None:
    b, ego = scenario()
    first = b.add("TimeElapsed", ego, duration=1.0)
    second = b.add("TimeElapsed", ego, duration=2.0)
    accelerate = b.add("Accelerate", ego, targetSpeed=8.0)
    b.chain(b.root, first, accelerate, b.end)
    b.chain(b.root, second, accelerate)
    save(b.scenario, out, "s009-merge-without-join.xmi")


@case("s010-dangling-flow", "SCEML-S006 SCEML-S007 SCEML-S010")
def dangling_flow(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    path = save(b.scenario, out, "s010-dangling-flow.xmi")
    edit_xml(path, lambda root: root.findall("flows")[-1].attrib.pop("target"))


@case("s011-flow-other-graph", "SCEML-S011 SCEML-S009")
def flow_other_graph(out: Path) -> None:
    lib = LibraryBuilder("Crossed wires")
    first, second = lib.module("First"), lib.module("Second")
    a = first.add("TimeElapsed", first.role("r"), duration=1.0)
    b = second.add("TimeElapsed", second.role("r"), duration=1.0)
    first.chain(first.in_port, a, first.out_port)
    second.chain(second.in_port, b, second.out_port)
    first.flow(a, b)
    save(lib.library, out, "s011-flow-other-graph.xmi")


@case("s012-duplicate-flow", "SCEML-S012")
def duplicate_flow(out: Path) -> None:
    b, ego = scenario()
    first = b.add("TimeElapsed", ego, duration=1.0)
    second = b.add("SpeedCondition", ego, speed=3.0)
    b.chain(b.root, first)
    b.chain(b.root, second)
    join = b.join_all(first, second)
    b.flow(first, join)
    b.chain(join, b.end)
    save(b.scenario, out, "s012-duplicate-flow.xmi")


@case("s013-duplicate-names", "SCEML-S013")
def duplicate_names(out: Path) -> None:
    b, ego = scenario()
    b.chain(
        b.root,
        b.add("TimeElapsed", ego, name="Wait", duration=1.0),
        b.add("TimeElapsed", ego, name="Wait", duration=2.0),
        b.end,
    )
    save(b.scenario, out, "s013-duplicate-names.xmi")


@case("s014-runs", "SCEML-S014")
def impossible_runs(out: Path) -> None:
    b, ego = scenario()
    b.chain(
        b.root,
        b.add("TimeElapsed", ego, name="Again", duration=1.0, maxRuns=2),
        b.add("Accelerate", ego, name="Never", targetSpeed=10.0, rate=1.0, maxRuns=0),
        b.add("Accelerate", ego, name="Thrice", targetSpeed=12.0, rate=1.0, maxRuns=3),
        # Written as its event and the event of its finish: players cannot repeat both.
        b.add("KeepVelocity", ego, name="HoldTwice", duration=2.0, maxRuns=2),
        b.end,
    )
    save(b.scenario, out, "s014-runs.xmi")


# Actors --------------------------------------------------------------------------------------


@case("a001-no-reference-actor", "SCEML-A001")
def no_reference_actor(out: Path) -> None:
    b, ego = scenario()
    wait = b.add("TimeElapsed", ego, duration=1.0)
    wait.referenceActor = None
    b.chain(b.root, wait, b.end)
    save(b.scenario, out, "a001-no-reference-actor.xmi")


@case("a002-foreign-role", "SCEML-A002")
def foreign_role(out: Path) -> None:
    lib = LibraryBuilder("Borrowed roles")
    owner, borrower = lib.module("Owner"), lib.module("Borrower")
    role = owner.role("driver", "Car")
    borrower.role("walker", "Pedestrian")
    owner.chain(owner.in_port, owner.add("TimeElapsed", role, duration=1.0), owner.out_port)
    node = borrower.add("TimeElapsed", role, duration=1.0)
    borrower.chain(borrower.in_port, node, borrower.out_port)
    save(lib.library, out, "a002-foreign-role.xmi")


@case("a003-missing-target", "SCEML-A003")
def missing_target(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Follow", ego), b.end)
    save(b.scenario, out, "a003-missing-target.xmi")


@case("a004-unused-target", "SCEML-A004")
def unused_target(out: Path) -> None:
    b, ego = scenario()
    car = b.actor("Car", "car", start=lane(1, 1, 30.0))
    b.chain(b.root, b.add("Accelerate", ego, target=car, targetSpeed=8.0), b.end)
    save(b.scenario, out, "a004-unused-target.xmi")


@case("a005-self-target", "SCEML-A005")
def self_target(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Follow", ego, target=ego), b.end)
    save(b.scenario, out, "a005-self-target.xmi")


@case("a006-duplicate-actor-names", "SCEML-A006")
def duplicate_actor_names(out: Path) -> None:
    b, ego = scenario()
    b.actor("Car", "car", start=lane(1, 1, 30.0))
    b.actor("Van", "car", start=lane(1, 1, 50.0))
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "a006-duplicate-actor-names.xmi")


@case("a007-two-egos", "SCEML-A007")
def two_egos(out: Path) -> None:
    b, ego = scenario()
    b.actor("Car", "other", ego=True, start=lane(1, 1, 30.0))
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "a007-two-egos.xmi")


# Parameters and levels -----------------------------------------------------------------------


@case("p001-range-in-concrete", "SCEML-P001")
def range_in_concrete(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=span(6.0, 10.0)), b.end)
    save(b.scenario, out, "p001-range-in-concrete.xmi")


@case("p002-logical-missing-values", "SCEML-P002")
def logical_missing_values(out: Path) -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("Accelerate", ego), b.add("TurnRight", ego), b.end)
    save(b.scenario, out, "p002-logical-missing-values.xmi")


@case("p003-range-reversed", "SCEML-P003")
def range_reversed(out: Path) -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=span(10.0, 6.0)), b.end)
    save(b.scenario, out, "p003-range-reversed.xmi")


@case("p004-range-step-zero", "SCEML-P004")
def range_step_zero(out: Path) -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=span(6.0, 10.0, 0.0)), b.end)
    save(b.scenario, out, "p004-range-step-zero.xmi")


@case("p005-negative-deviation", "SCEML-P005")
def negative_deviation(out: Path) -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=normal(8.0, -1.0)), b.end)
    save(b.scenario, out, "p005-negative-deviation.xmi")


@case("p006-empty-discrete", "SCEML-P006")
def empty_discrete(out: Path) -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=discrete([])), b.end)
    save(b.scenario, out, "p006-empty-discrete.xmi")


@case("p007-negative-radius", "SCEML-P007")
def negative_radius(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("InLocationRadius", ego, position=world(0, 0), radius=-2.0), b.end)
    save(b.scenario, out, "p007-negative-radius.xmi")


@case("p007-negative-light-transition", "SCEML-P007")
def negative_light_transition(out: Path) -> None:
    b, ego = scenario()
    light = b.add("LightState", ego, lightType="brakeLights", transitionTime=-0.5)
    b.chain(b.root, light, b.end)
    save(b.scenario, out, "p007-negative-light-transition.xmi")


@case("p007-negative-follow-limit", "SCEML-P007")
def negative_follow_limit(out: Path) -> None:
    """A Follow's maxDeceleration written as a negative number (release 1.5): a magnitude."""
    b, ego = scenario()
    lead = b.actor("Car", "lead", start=lane(1, -1, 40.0), speed=5.0)
    follow = b.add("Follow", ego, target=lead, distance=10.0, maxDeceleration=-6.0)
    b.chain(b.root, follow, b.end)
    save(b.scenario, out, "p007-negative-follow-limit.xmi")


@case("p000-distance-keeping-clean", "")
def distance_keeping_clean(out: Path) -> None:
    """Release 1.5's measure and limits of Follow and Approach, set as the corpora set them:
    between the boxes within stated limits and jerks; a time gap ahead of the target."""
    b, ego = scenario()
    lead = b.actor("Car", "lead", start=lane(1, -1, 40.0), speed=5.0)
    follow = b.add(
        "Follow",
        ego,
        target=lead,
        distance=10.0,
        freespace=True,
        maxAcceleration=15.0,
        maxDeceleration=15.0,
        maxSpeed=40.0,
        maxAccelerationRate=2.0,
        maxDecelerationRate=5.0,
    )
    ahead = b.add("Approach", ego, target=lead, timeGap=1.5, displacement="leading")
    b.chain(b.root, follow, ahead, b.end)
    save(b.scenario, out, "p000-distance-keeping-clean.xmi")


@case("p007-negative-stand-still", "SCEML-P007")
def negative_stand_still(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("StandStill", ego, duration=-1.0), b.end)
    save(b.scenario, out, "p007-negative-stand-still.xmi")


@case("p000-lights-and-motion-conditions-clean", "")
def lights_and_motion_conditions_clean(out: Path) -> None:
    """Release 1.4's kinds, set as the corpora set them: a braking below -0.9 m/s² along the
    road, a stop of 0.1 s, the warning lights on."""
    b, ego = scenario()
    braking = b.add(
        "AccelerationCondition", ego, acceleration=-0.9, rule="lessThan", direction="longitudinal"
    )
    stop = b.add("Stop", ego, rate=3.0)
    still = b.add("StandStill", ego, duration=0.1)
    lights = b.add("LightState", ego, lightType="warningLights", transitionTime=0.5)
    b.chain(b.root, stop, b.end)
    b.chain(b.root, braking, still, lights, b.end)
    save(b.scenario, out, "p000-lights-and-motion-conditions-clean.xmi")


@case("p008-parameter-ref-in-scenario", "SCEML-P008")
def parameter_ref_in_scenario(out: Path) -> None:
    b, ego = scenario()
    accelerate = b.add("Accelerate", ego)
    accelerate.targetSpeed = scm.ParameterRef()
    b.chain(b.root, accelerate, b.end)
    save(b.scenario, out, "p008-parameter-ref-in-scenario.xmi")


@case("p009-undeclared-parameter", "SCEML-P009")
def undeclared_parameter(out: Path) -> None:
    b, _ = scenario()
    b.declare("Declared", 1.0)
    setter = b.add("SetParameter", None, parameter="Undeclared", value="2")
    b.chain(b.root, setter, b.end)
    save(b.scenario, out, "p009-undeclared-parameter.xmi")


@case("p010-lane-change-distance-and-duration", "SCEML-P010")
def lane_change_distance_and_duration(out: Path) -> None:
    b, ego = scenario()
    change = b.add("LaneChange", ego, distance=40.0, duration=3.0)
    b.chain(b.root, change, b.end)
    save(b.scenario, out, "p010-lane-change-distance-and-duration.xmi")


@case("p000-lane-change-duration-clean", "")
def lane_change_duration(out: Path) -> None:
    b, ego = scenario()
    change = b.add("LaneChange", ego, direction="right", duration=3.0)
    b.chain(b.root, change, b.end)
    save(b.scenario, out, "p000-lane-change-duration-clean.xmi")


# Simultaneity --------------------------------------------------------------------------------


@case("c001-parallel-longitudinal", "SCEML-C001")
def parallel_longitudinal(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0))
    b.chain(b.root, b.add("Decelerate", ego, targetSpeed=2.0))
    b.chain(b.join_all(*b.scenario.nodes[2:4]), b.end)
    save(b.scenario, out, "c001-parallel-longitudinal.xmi")


@case("c001-after-join-one", "SCEML-C001")
def after_join_one(out: Path) -> None:
    b, ego = scenario()
    wait = b.add("TimeElapsed", ego, duration=2.0)
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    b.chain(b.root, wait)
    b.chain(b.root, speed_up)
    # The join finishes with the first branch: the Accelerate may still be running.
    b.chain(b.join_one(wait, speed_up), b.add("Decelerate", ego, targetSpeed=2.0), b.end)
    save(b.scenario, out, "c001-after-join-one.xmi")


@case("c001-composite-and-lateral", "SCEML-C001")
def composite_and_lateral(out: Path) -> None:
    b, ego = scenario()
    car = b.actor("Car", "car", start=lane(1, -1, 40.0), speed=3.0)
    overtake = b.add("Overtake", ego, target=car, speed=12.0)
    change = b.add("LaneChange", ego, direction="right")
    b.chain(b.root, overtake)
    b.chain(b.root, change)
    b.chain(b.join_all(overtake, change), b.end)
    save(b.scenario, out, "c001-composite-and-lateral.xmi")


@case("c001-trajectory-beside-lane-change", "SCEML-C001")
def trajectory_beside_lane_change(out: Path) -> None:
    # A FollowTrajectory drives the path: a lane change beside it conflicts (a speed change
    # beside it does not: see c001-trajectory-beside-speed-clean).
    b, ego = scenario()
    path = b.add("FollowTrajectory", ego, waypoints=[lane(1, -1, 30.0), lane(1, -1, 50.0)])
    change = b.add("LaneChange", ego, direction="left")
    b.chain(b.root, path)
    b.chain(b.root, change)
    b.chain(b.join_all(path, change), b.end)
    save(b.scenario, out, "c001-trajectory-beside-lane-change.xmi")


@case("c001-trajectory-beside-speed-clean", "")
def trajectory_beside_speed(out: Path) -> None:
    # Followed at the actor's speed, a FollowTrajectory leaves the speed to an Accelerate that
    # starts with it, as an OpenSCENARIO event with both actions does.
    b, ego = scenario()
    path = b.add("FollowTrajectory", ego, waypoints=[lane(1, -1, 30.0), lane(1, -1, 50.0)])
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    b.chain(b.root, path)
    b.chain(b.root, speed_up)
    b.chain(b.join_all(path, speed_up), b.end)
    save(b.scenario, out, "c001-trajectory-beside-speed-clean.xmi")


@case("c001-interrupting-clean", "")
def interrupting(out: Path) -> None:
    # The Decelerate may start while the Accelerate runs: it interrupts it (release 1.5), as
    # an OpenSCENARIO event that overrides a running one, and the pair is allowed.
    b, ego = scenario()
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    wait = b.add("TimeElapsed", ego, duration=2.0)
    brake = b.add("Decelerate", ego, targetSpeed=2.0, interrupts=True)
    b.chain(b.root, speed_up)
    b.chain(b.root, wait, brake)
    b.chain(b.join_all(speed_up, brake), b.end)
    save(b.scenario, out, "c001-interrupting-clean.xmi")


@case("c001-through-module", "SCEML-C001")
def through_module(out: Path) -> None:
    b, ego = scenario()
    use = b.use(definition(out, "Speedup"), {"driver": ego}, {"target": 12.0})
    keep = b.add("KeepVelocity", ego, duration=3.0)
    b.chain(b.root, use)
    b.chain(b.root, keep)
    b.chain(b.join_all(use, keep), b.end)
    save(b.scenario, out, "c001-through-module.xmi")


# Plausibility --------------------------------------------------------------------------------


@case("l001-pedestrian-50kmh", "SCEML-L001")
def pedestrian_50kmh(out: Path) -> None:
    b, ego = scenario()
    walker = b.actor("Pedestrian", "walker", start=lane(4, 2, 1.0))
    b.chain(b.root, b.add("Accelerate", walker, targetSpeed=13.9), b.end)
    save(b.scenario, out, "l001-pedestrian-50kmh.xmi")


@case("l001-through-module", "SCEML-L001")
def fast_crossing(out: Path) -> None:
    overrides = {**DESTINATION, "crossingSpeed": uniform(1.0, 14.0)}
    crossing_use(
        out,
        "l001-through-module.xmi",
        lambda c: {"crosser": c["walker"], "trigger": c["car"]},
        overrides,
        level="logical",
    )


@case("l002-bicycle-acceleration", "SCEML-L002")
def bicycle_acceleration(out: Path) -> None:
    b, ego = scenario()
    bike = b.actor("Bicycle", "bike", start=lane(1, -2, 5.0))
    b.chain(b.root, b.add("Accelerate", bike, targetSpeed=6.0, rate=5.0), b.end)
    save(b.scenario, out, "l002-bicycle-acceleration.xmi")


@case("l003-truck-braking", "SCEML-L003")
def truck_braking(out: Path) -> None:
    b, ego = scenario()
    truck = b.actor("Truck", "truck", start=lane(1, 1, 40.0), speed=20.0)
    b.chain(b.root, b.add("Stop", truck, rate=10.0), b.end)
    save(b.scenario, out, "l003-truck-braking.xmi")


def _own_truck(b: ScenarioBuilder, rate: float, **own: float) -> None:
    """A truck stating its own limits (release 1.4) that brakes to a stop at `rate`."""
    truck = b.actor("Truck", "truck", start=lane(1, 1, 40.0), speed=20.0)
    for feature, value in own.items():
        truck.eSet(feature, scm.Value(value=value))
    b.chain(b.root, b.add("Stop", truck, rate=rate), b.end)


@case("l004-own-braking-beyond-the-table", "SCEML-L004")
def own_braking_beyond_the_table(out: Path) -> None:
    # 10 m/s2 is above the Truck table's 8 but within the truck's own maxDeceleration: no L003;
    # the own limit itself is above the table (L004, a warning).
    b, ego = scenario()
    _own_truck(b, 10.0, maxDeceleration=10.0)
    save(b.scenario, out, "l004-own-braking-beyond-the-table.xmi")


@case("l005-own-braking-held", "SCEML-L005")
def own_braking_held(out: Path) -> None:
    # 6 m/s2 is within the Truck table's 8 but above the truck's own maxDeceleration of 5: a
    # warning (players hold it to 5), not L003.
    b, ego = scenario()
    _own_truck(b, 6.0, maxDeceleration=5.0)
    save(b.scenario, out, "l005-own-braking-held.xmi")


@case("l003-above-a-raised-own-limit", "SCEML-L003 SCEML-L004")
def above_a_raised_own_limit(out: Path) -> None:
    # The truck's own maxDeceleration (10) raises the ceiling from the table's 8; 12 is above it.
    b, ego = scenario()
    _own_truck(b, 12.0, maxDeceleration=10.0)
    save(b.scenario, out, "l003-above-a-raised-own-limit.xmi")


@case("l004-own-top-speed-implausible", "SCEML-L004")
def own_top_speed_implausible(out: Path) -> None:
    # A truck that says it is good for 90 m/s (324 km/h), above the Truck table's 35.
    b, ego = scenario()
    _own_truck(b, 5.0, maxSpeed=90.0)
    save(b.scenario, out, "l004-own-top-speed-implausible.xmi")


@case("p007-own-acceleration-negative", "SCEML-P007")
def own_acceleration_negative(out: Path) -> None:
    b, ego = scenario()
    _own_truck(b, 5.0, maxAcceleration=-1.0)
    save(b.scenario, out, "p007-own-acceleration-negative.xmi")


# Modules -------------------------------------------------------------------------------------


@case("m001-role-unbound", "SCEML-M001 SCEML-M017")
def role_unbound(out: Path) -> None:
    crossing_use(out, "m001-role-unbound.xmi", lambda c: {"crosser": c["walker"]})


@case("m002-role-bound-twice", "SCEML-M002")
def role_bound_twice(out: Path) -> None:
    b, cast = crossing_scenario()
    use = b.use(
        definition(out, "CrossingManeuver"),
        {"crosser": cast["walker"], "trigger": cast["car"]},
        DESTINATION,
    )
    use.bindings.append(scm.RoleBinding(role="trigger", actor=cast["car"]))
    b.chain(b.root, use, b.end)
    save(b.scenario, out, "m002-role-bound-twice.xmi")


@case("m003-unknown-role", "SCEML-M003")
def unknown_role(out: Path) -> None:
    crossing_use(
        out,
        "m003-unknown-role.xmi",
        lambda c: {"crosser": c["walker"], "trigger": c["car"], "driver": c["ego"]},
    )


# The car's destination is the pedestrian's, on the sidewalk, so the map rule objects too.
@case("m004-car-as-crosser", "SCEML-M004 SCEML-R004")
def car_as_crosser(out: Path) -> None:
    crossing_use(
        out, "m004-car-as-crosser.xmi", lambda c: {"crosser": c["car"], "trigger": c["ego"]}
    )


@case("m005-unknown-override", "SCEML-M005 SCEML-M017")
def unknown_override(out: Path) -> None:
    crossing_use(
        out,
        "m005-unknown-override.xmi",
        lambda c: {"crosser": c["walker"], "trigger": c["car"]},
        {**DESTINATION, "speed": 2.0},
    )


@case("m006-required-parameter", "SCEML-M006 SCEML-P002")
def required_parameter(out: Path) -> None:
    crossing_use(
        out,
        "m006-required-parameter.xmi",
        lambda c: {"crosser": c["walker"], "trigger": c["car"]},
        {},
        level="logical",
    )


def module_library(out: Path, name: str, shape: Callable[[LibraryBuilder], None]) -> None:
    lib = LibraryBuilder("Broken modules")
    shape(lib)
    save(lib.library, out, name)


@case("m007-no-out-port", "SCEML-M007")
def no_out_port(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        m = lib.module("Endless")
        m.definition.nodes.remove(m.out_port)
        m.chain(m.in_port, m.add("TimeElapsed", m.role("r"), duration=1.0))

    module_library(out, "m007-no-out-port.xmi", shape)


@case("m008-in-port-unwired", "SCEML-M008 SCEML-S006 SCEML-S007")
def in_port_unwired(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        m = lib.module("Unfed")
        m.chain(m.add("TimeElapsed", m.role("r"), duration=1.0), m.out_port)

    module_library(out, "m008-in-port-unwired.xmi", shape)


@case("m009-out-port-merges", "SCEML-M009")
def out_port_merges(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        m = lib.module("TwoWays")
        r = m.role("r")
        m.chain(m.in_port, m.add("TimeElapsed", r, duration=1.0), m.out_port)
        m.chain(m.in_port, m.add("TimeElapsed", r, duration=2.0), m.out_port)

    module_library(out, "m009-out-port-merges.xmi", shape)


@case("m010-root-in-module", "SCEML-M010 SCEML-S006 SCEML-S007")
def root_in_module(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        m = lib.module("Rooted")
        m.chain(m.in_port, m.add("TimeElapsed", m.role("r"), duration=1.0), m.out_port)
        m.definition.nodes.append(scm.RootNode(name="Root"))

    module_library(out, "m010-root-in-module.xmi", shape)


@case("m011-port-in-scenario", "SCEML-M011 SCEML-S006 SCEML-S007")
def port_in_scenario(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    b.scenario.nodes.append(scm.InPort(name="In"))
    save(b.scenario, out, "m011-port-in-scenario.xmi")


@case("m012-recursion", "SCEML-M012")
def recursion(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        outer, inner = lib.module("Outer"), lib.module("Inner")
        r, s = outer.role("r"), inner.role("s")
        outer.chain(outer.in_port, outer.use(inner.definition, {"s": r}), outer.out_port)
        inner.chain(inner.in_port, inner.use(outer.definition, {"r": s}), inner.out_port)

    module_library(out, "m012-recursion.xmi", shape)


@case("m013-missing-library", "SCEML-M013 SCEML-M017")
def missing_library(out: Path) -> None:
    crossing_use(
        out, "m013-missing-library.xmi", lambda c: {"crosser": c["walker"], "trigger": c["car"]}
    )

    def break_href(root: etree._Element) -> None:
        for element in root.iter("definition"):
            element.set("href", "lib/no-such-library.xmi#CrossingManeuver")

    edit_xml(out / "m013-missing-library.xmi", break_href)


@case("m015-binding-to-nothing", "SCEML-M015 SCEML-M017")
def binding_to_nothing(out: Path) -> None:
    b, cast = crossing_scenario()
    use = b.use(definition(out, "CrossingManeuver"), {"trigger": cast["car"]}, DESTINATION)
    use.bindings.append(scm.RoleBinding(role="crosser"))
    b.chain(b.root, use, b.end)
    save(b.scenario, out, "m015-binding-to-nothing.xmi")


@case("m016-duplicate-role-names", "SCEML-M016")
def duplicate_role_names(out: Path) -> None:
    def shape(lib: LibraryBuilder) -> None:
        m = lib.module("Twins")
        r = m.role("r", "Car")
        m.role("r", "Bicycle")
        m.chain(m.in_port, m.add("TimeElapsed", r, duration=1.0), m.out_port)

    module_library(out, "m016-duplicate-role-names.xmi", shape)


# Export readiness ----------------------------------------------------------------------------


@case("e001-no-map", "SCEML-E001")
def no_map(out: Path) -> None:
    b, ego = scenario()
    b.root.map = None
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "e001-no-map.xmi")


@case("e002-no-start-position", "SCEML-E002")
def no_start_position(out: Path) -> None:
    b, ego = scenario()
    b.actor("Bicycle", "bike")
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "e002-no-start-position.xmi")


@case("e002-logical-no-start-position", "SCEML-E002")
def logical_no_start_position(out: Path) -> None:
    # Sampling only changes numbers: a logical scenario must already have what every sample
    # needs to be a valid concrete scenario (SPEC §5).
    b, ego = scenario("logical")
    b.actor("Bicycle", "bike", speed=0.0)
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=span(6.0, 10.0, 1.0)), b.end)
    save(b.scenario, out, "e002-logical-no-start-position.xmi")


@case("e001-logical-no-map", "SCEML-E001")
def logical_no_map(out: Path) -> None:
    b, ego = scenario("logical")
    b.root.map = None
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=span(6.0, 10.0, 1.0)), b.end)
    save(b.scenario, out, "e001-logical-no-map.xmi")


def _time_of_day(text: str) -> Case:
    def build(out: Path) -> None:
        b, ego = scenario()
        b.environment(time_of_day=text)
        b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
        save(b.scenario, out, f"e004-time-of-day-{text.replace(':', '-')}.xmi")

    return build


for _text in ("noon", "25:61:00", "12:00"):
    case(f"e004-time-of-day-{_text.replace(':', '-')}", "SCEML-E004")(_time_of_day(_text))


@case("e004-time-of-day-functional", "SCEML-E004")
def time_of_day_functional(out: Path) -> None:
    b = ScenarioBuilder("Case", level="functional", date=DATE)
    ego = b.actor("Car", "ego", ego=True)
    b.environment(time_of_day="7pm")
    b.chain(b.root, b.add("Accelerate", ego), b.end)
    save(b.scenario, out, "e004-time-of-day-functional.xmi")


@case("e005-date-yesterday", "SCEML-E005")
def date_not_iso(out: Path) -> None:
    b, ego = scenario()
    b.root.date = "yesterday"  # the builder refuses it; a hand-edited file can have it
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    save(b.scenario, out, "e005-date-yesterday.xmi")


@case("e006-opaque-not-an-action", "SCEML-E006")
def opaque_not_an_action(out: Path) -> None:
    b, ego = scenario()
    kept = scm.OpaqueAction(name="Kept", xml="<Event name='x'/>", sourceLine=7, sourceVersion="1.3")
    kept.referenceActor = ego
    b.scenario.nodes.append(kept)
    b.chain(b.root, kept, b.end)
    save(b.scenario, out, "e006-opaque-not-an-action.xmi")


# Controllers (issue 24) ---------------------------------------------------------------------------


@case("k001-unnamed-controller", "SCEML-K001")
def unnamed_controller(out: Path) -> None:
    b, ego = scenario()
    ego.controller = controller("ACCController", properties={"timeGap": "1.5"})
    assign = b.add("AssignController", ego, controller=controller(""))
    b.chain(b.root, assign, b.end)
    save(b.scenario, out, "k001-unnamed-controller.xmi")


@case("k002-input-overridden-twice", "SCEML-K002")
def input_overridden_twice(out: Path) -> None:
    b, ego = scenario()
    twice = b.add("OverrideController", ego, overrides=[override("brake", 0.2), override("brake")])
    b.chain(b.root, twice, b.end)
    save(b.scenario, out, "k002-input-overridden-twice.xmi")


@case("k003-pedal-beyond-travel", "SCEML-K003")
def pedal_beyond_travel(out: Path) -> None:
    b, ego = scenario()
    # A steering wheel in rad may exceed 1; a pedal may not.
    pressed = [override("throttle", 1.5), override("steeringWheel", 2.0)]
    b.chain(b.root, b.add("OverrideController", ego, overrides=pressed), b.end)
    save(b.scenario, out, "k003-pedal-beyond-travel.xmi")


@case("k004-activation-of-nothing", "SCEML-K004")
def activation_of_nothing(out: Path) -> None:
    b, ego = scenario()
    b.chain(b.root, b.add("ActivateController", ego), b.end)
    save(b.scenario, out, "k004-activation-of-nothing.xmi")


@case("k000-controllers-clean", "")
def controllers_clean(out: Path) -> None:
    b, ego = scenario()
    ego.controller = controller("ACCController", "longitudinal", {"timeGap": "1.5"})
    ego.controllerActivation = activation(longitudinal=True)
    assign = b.add(
        "AssignController",
        ego,
        controller=controller("InteractiveController"),
        activation=activation(lateral=True),
    )
    brake = b.add("OverrideController", ego, overrides=[override("brake", 1.0)])
    off = b.add("ActivateController", ego, longitudinal=False, lateral=False)
    b.chain(b.root, assign, brake, off, b.end)
    save(b.scenario, out, "k000-controllers-clean.xmi")


# The map (SPEC §12): maps/intersection.xodr, see docs/map.md -------------------------------------


def on_map(
    name: str, codes: str, *, level: str = "concrete", map_text: str = MAP
) -> Callable[[Callable[[ScenarioBuilder, scm.Actor], None]], Case]:
    """A case whose scenario (ego on road 1, lane -1 at s=10) gets one more part from `add`."""

    def register(add: Callable[[ScenarioBuilder, scm.Actor], None]) -> Case:
        def build(out: Path) -> None:
            b, ego = scenario(level)
            b.root.map = map_text
            add(b, ego)
            save(b.scenario, out, f"{name}.xmi")

        return case(name, codes)(build)

    return register


def _accelerate(b: ScenarioBuilder, ego: scm.Actor) -> None:
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)


on_map("r001-missing-map", "SCEML-R001", map_text="../../../maps/missing.xodr")(_accelerate)
on_map("r001-not-opendrive", "SCEML-R001", map_text="lib/modules.xmi")(_accelerate)
on_map("r002-town-name", "SCEML-R002", map_text="Town03")(_accelerate)


def _start(
    position: scm.Position, kind: str = "Car"
) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        other = b.actor(kind, "other", start=position)
        b.chain(b.root, b.add("Accelerate", other, targetSpeed=1.0), b.end)

    return add


on_map("r003-unknown-road", "SCEML-R003")(_start(lane(99, -1, 10.0)))
on_map("r003-unknown-lane", "SCEML-R003")(_start(lane(1, -3, 10.0)))
on_map("r003-s-beyond-road", "SCEML-R003")(_start(lane(1, -1, 150.0)))
on_map("r003-offset-outside-lane", "SCEML-R003")(_start(lane(1, -1, 20.0, offset=3.0)))
on_map("r003-logical-s-range-beyond-road", "SCEML-R003", level="logical")(
    _start(lane(1, -1, span(20.0, 120.0)))
)
on_map("r008-unknown-road", "SCEML-R008")(_start(road(99, 10.0, -1.75)))
on_map("r008-s-beyond-road", "SCEML-R008")(_start(road(1, 150.0, -1.75)))
on_map("r008-t-off-road", "SCEML-R008")(_start(road(1, 20.0, -30.0)))
# A road position in a driving lane, with a heading relative to the road: clean.
on_map("r008-road-position-on-lane", "")(_start(road(1, 20.0, -1.75, h=0.1)))


def _route(path_s: float) -> scm.RoutePosition:
    """A route from road 1, lane -1 at s=10 to s=90 (lane -1 drives along s), the actor
    `path_s` along it in lane -1."""
    return scm.RoutePosition(
        routeName="along_road_1",
        waypoints=[
            scm.RouteWaypoint(position=lane(1, -1, 10.0)),
            scm.RouteWaypoint(position=lane(1, -1, 90.0)),
        ],
        pathS=scm.Value(value=path_s),
        laneId=-1,
    )


# 140 m from s=10 leaves road 1 (100 m): SceML places a route position on its first road only.
on_map("r010-route-beyond-its-first-road", "SCEML-R010")(_start(_route(140.0)))
# 30 m along the route, still on road 1: clean.
on_map("r010-route-on-its-first-road", "")(_start(_route(30.0)))
on_map("r004-car-on-sidewalk", "SCEML-R004")(_start(lane(1, -2, 10.0)))


def _relative_starts(entities: str) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """Car `other` starts 20 m ahead of `ego` (clean), of itself, of a third car that starts
    relative to it (a cycle), or of nobody."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        other = b.actor("Car", "other", start=lane(1, -1, 40.0))
        if entities == "cycle":
            third = b.actor("Car", "third", start=relative_object(other, -20.0))
            other.startPosition = relative_object(third, -20.0)
        else:
            named = {"ego": ego, "itself": other, "nobody": None}[entities]
            other.startPosition = relative_lane(named, 0, 20.0)
        b.chain(b.root, b.add("Accelerate", other, targetSpeed=1.0), b.end)

    return add


on_map("a008-relative-start-clean", "")(_relative_starts("ego"))


def _beside_ego(b: ScenarioBuilder, ego: scm.Actor) -> None:
    """Car `other` starts one lane right of ego's lane -1 on road 1: lane -2, a sidewalk."""
    other = b.actor("Car", "other", start=relative_lane(ego, -1, 10.0))
    b.chain(b.root, b.add("Accelerate", other, targetSpeed=1.0), b.end)


on_map("r004-relative-start-on-sidewalk", "SCEML-R004")(_beside_ego)
on_map("a008-start-relative-to-itself", "SCEML-A008")(_relative_starts("itself"))
on_map("a008-starts-relative-in-a-cycle", "SCEML-A008 SCEML-A008")(_relative_starts("cycle"))
on_map("a008-relative-start-names-nobody", "SCEML-A008")(_relative_starts("nobody"))


def _towing(how: str) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """Release 1.4: ego tows `trailer`, which has no start (it starts at the hitch: clean); or
    ego tows itself, or ego and a truck tow each other (SCEML-A009)."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        if how == "itself":
            ego.trailer = ego
        elif how == "loop":
            truck = b.actor("Truck", "truck", start=lane(1, -1, 40.0))
            ego.trailer, truck.trailer = truck, ego
        else:
            ego.trailer = b.actor("Truck", "trailer")
            ego.hitchX, ego.trailer.couplerX = scm.Value(value=-1.2), scm.Value(value=3.25)
        b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)

    return add


on_map("a009-trailer-clean", "")(_towing("clean"))
on_map("a009-tows-itself", "SCEML-A009")(_towing("itself"))
on_map("a009-towing-loop", "SCEML-A009")(_towing("loop"))


def _coupling(trailer_kind: str) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """Release 1.5: ego reverses to a standing `trailer`, couples it, drives off and uncouples
    it (a Truck: clean; a Pedestrian coupled: SCEML-A010)."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        trailer = b.actor(trailer_kind, "trailer", start=lane(1, -1, 4.0))
        ego.hitchX = scm.Value(value=-1.2)
        connect = b.add("ConnectTrailer", ego, target=trailer)
        b.chain(
            b.root,
            b.add("TimeElapsed", ego, duration=1.0),
            connect,
            b.add("DriveDistance", ego, distance=10.0, speed=5.0),
            b.add("DisconnectTrailer", ego),
            b.end,
        )

    return add


on_map("a010-coupling-clean", "")(_coupling("Truck"))
on_map("a010-pedestrian-coupled", "SCEML-A010")(_coupling("Pedestrian"))


#: The import tests' vehicle catalogs, from the corpus folder (release 1.5's vehicleCatalog).
VEHICLE_CATALOG = "../../importer/files/catalogs"


def _catalog_entry(entry: str) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """Release 1.5: ego read from catalog entry `entry`. car_white says ego's box when it is
    5.04 x 2.0 x 1.5 m with its centre 1.4 m ahead (clean; its $MaxSpeed is assigned);
    truck_yellow is a truck, and car_blue is no entry (SCEML-A011)."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        b.root.vehicleCatalog = VEHICLE_CATALOG
        ego.catalogEntry = entry
        for feature, value in (("length", 5.04), ("width", 2.0), ("height", 1.5)):
            ego.eSet(feature, scm.Value(value=value))
        ego.boxCenterX = scm.Value(value=1.4)
        b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)

    return add


on_map("a011-catalog-entry-clean", "")(_catalog_entry("car_white"))
on_map("a011-catalog-entry-unknown", "SCEML-A011")(_catalog_entry("car_blue"))
on_map("a011-catalog-entry-unsaid", "SCEML-A011")(_catalog_entry("truck_yellow"))


def _reverse(speed: float) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """Release 1.4: ego slows to a negative target speed, reversing (clean within its limit)."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        b.chain(b.root, b.add("Decelerate", ego, targetSpeed=speed), b.end)

    return add


on_map("p007-reverse-target-speed-clean", "")(_reverse(-3.0))
on_map("l001-reversing-too-fast", "SCEML-L001")(_reverse(-80.0))
on_map("r004-car-off-road", "SCEML-R004")(_start(world(30.0, 30.0, h=0.0)))
# A pedestrian may stand on the roadway (it crosses it): clean.
on_map("r004-pedestrian-on-roadway", "")(_start(lane(1, -1, 30.0), kind="Pedestrian"))
# Lane 1 of the north arm carries traffic south; the car faces north on it.
on_map("r005-heading-against-lane", "SCEML-R005")(_start(world(-1.75, 30.0, h=1.5708)))


def _turn(kind: str, destination: scm.Position) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """The car `other` comes from the north (road 1, lane 1) and turns to `destination`."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        other = b.actor("Car", "other", start=lane(1, 1, 30.0), speed=5.0)
        b.chain(b.root, b.add(kind, other, destination=destination), b.end)

    return add


# From the north, the west arm (road 4) is a right turn and the east arm (road 2) a left one.
on_map("r006-turn-left-clean", "")(_turn("TurnLeft", lane(2, -1, 20.0)))
on_map("r006-turn-left-is-a-right-turn", "SCEML-R006")(_turn("TurnLeft", lane(4, -1, 20.0)))
on_map("r006-turn-right-unreachable", "SCEML-R006")(_turn("TurnRight", lane(1, -1, 20.0)))


@on_map("r006-turn-after-the-junction-is-passed", "SCEML-R006")
def _turn_once_through(b: ScenarioBuilder, ego: scm.Actor) -> None:
    """The car `other` from the north turns left only once it is within 2 m of a point on the
    south arm, past the junction: from there no junction is ahead (from its start, the left
    turn would be fine)."""
    other = b.actor("Car", "other", start=lane(1, 1, 30.0), speed=5.0)
    through = b.add("InLocationRadius", other, position=lane(3, -1, 30.0), radius=2.0)
    b.chain(b.root, through, b.add("TurnLeft", other, destination=lane(2, -1, 20.0)), b.end)


def _walk(destination: scm.Position) -> Callable[[ScenarioBuilder, scm.Actor], None]:
    """A pedestrian on the west arm's south sidewalk (road 4, lane 2) crosses to `destination`."""

    def add(b: ScenarioBuilder, ego: scm.Actor) -> None:
        walker = b.actor("Pedestrian", "walker", start=lane(4, 2, 1.0))
        b.chain(b.root, b.add("Cross", walker, destination=destination), b.end)

    return add


on_map("r007-cross-clean", "")(_walk(lane(4, -2, 1.0)))
on_map("r007-cross-along-the-sidewalk", "SCEML-R007")(_walk(lane(4, 2, 20.0)))


def _drive_at_rest(b: ScenarioBuilder, ego: scm.Actor) -> None:
    b.chain(b.root, b.add("DriveDistance", ego, distance=20.0, speed=0.0), b.end)


def _turn_after_trajectory(b: ScenarioBuilder, ego: scm.Actor) -> None:
    """The car `other` from the north follows its lane to 10 m behind the ego (a place relative
    to it, which the exported route cannot start from), then turns left (east)."""
    other = b.actor("Car", "other", start=lane(1, 1, 30.0), speed=5.0)
    behind = relative_object(ego, -10.0)
    b.chain(
        b.root,
        b.add("FollowTrajectory", other, waypoints=[lane(1, 1, 25.0), behind]),
        b.add("TurnLeft", other, destination=lane(2, -1, 20.0)),
        b.end,
    )


def _wait_on_an_edge(b: ScenarioBuilder, ego: scm.Actor) -> None:
    wait = b.add("TimeElapsed", ego, duration=2.0)
    wait.edge = scm.ConditionEdge.rising
    b.chain(b.root, wait, b.end)


on_map("y001-drive-distance-at-rest", "SCEML-Y001")(_drive_at_rest)
on_map("y002-turn-after-a-trajectory", "SCEML-Y002")(_turn_after_trajectory)
on_map("y004-wait-on-an-edge", "SCEML-Y004")(_wait_on_an_edge)


# Several faults at once ----------------------------------------------------------------------


@case(
    "multi-actors-and-values",
    "SCEML-A003 SCEML-A007 SCEML-L001 SCEML-P001 SCEML-P007 SCEML-E002",
)
def actors_and_values(out: Path) -> None:
    b = ScenarioBuilder("Many", map=MAP, level="concrete", date=DATE)
    walker = b.actor("Pedestrian", "walker", start=lane(4, 2, 1.0))
    car = b.actor("Car", "car")
    run = b.add("Accelerate", walker, targetSpeed=span(2.0, 20.0))
    follow = b.add("Follow", car)
    near = b.add("InVehicleRadius", walker, target=car, radius=0.0)
    b.chain(b.root, run, near)
    b.chain(b.root, follow)
    b.chain(b.join_all(near, follow), b.end)
    save(b.scenario, out, "multi-actors-and-values.xmi")


@case(
    "multi-structure",
    "SCEML-S002 SCEML-S004 SCEML-S006 SCEML-S007 SCEML-S008 SCEML-S009 SCEML-S010 SCEML-S013",
)
def structure_faults(out: Path) -> None:
    b, ego = scenario()
    second_end = scm.EndNode(name="End")
    b.scenario.nodes.append(second_end)
    left = b.add("Accelerate", ego, targetSpeed=8.0)
    right = b.add("Decelerate", ego, targetSpeed=3.0)
    b.chain(b.root, left)
    b.chain(b.root, right)
    b.chain(b.join_all(left, right), b.end)
    loop_a = b.add("TimeElapsed", ego, duration=1.0)
    loop_b = b.add("TimeElapsed", ego, duration=1.0)
    lonely = b.join_one(right)
    b.chain(right, loop_a, loop_b, loop_a)
    b.chain(lonely, second_end)
    path = save(b.scenario, out, "multi-structure.xmi")
    edit_xml(path, lambda root: root.findall("flows")[-1].attrib.pop("source"))


@case(
    "multi-levels",
    "SCEML-C001 SCEML-M004 SCEML-M006 SCEML-P002 SCEML-P003 SCEML-P005 SCEML-P006",
)
def level_faults(out: Path) -> None:
    b, cast = crossing_scenario("logical")
    ego = cast["ego"]
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=uniform(9.0, 4.0), rate=span(3.0, 1.0)))
    shaky = b.add("Decelerate", ego, targetSpeed=discrete([1.0, 2.0], [0.0, 0.0]))
    b.chain(b.scenario.nodes[-2], shaky, b.add("FollowTrajectory", ego, waypoints=[world(0, 0)]))
    use = b.use(
        definition(out, "CrossingManeuver"), {"crosser": cast["ego"], "trigger": cast["car"]}
    )
    b.chain(b.root, use)
    b.chain(b.join_all(b.scenario.nodes[-2], use), b.end)
    save(b.scenario, out, "multi-levels.xmi")


def build_all(out: Path) -> list[Path]:
    """Write every case and the MANIFEST under `out`; returns the files written."""
    out.mkdir(parents=True, exist_ok=True)
    lines = []
    for name, codes, build in CASES:
        build(out)
        lines.append(f"{name} {codes}".rstrip())
    manifest = out / "MANIFEST"
    write_atomically(manifest, ("\n".join(lines) + "\n").encode("utf-8"))
    return [out / name for name, _, _ in CASES] + [manifest]


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=HERE, help="folder to write into")
    for path in build_all(parser.parse_args(argv).out):
        print(path)


if __name__ == "__main__":
    main()

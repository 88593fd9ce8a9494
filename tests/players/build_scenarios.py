"""Build the scenarios that check a player keeps SceML's meaning (issues 13 and 25).

    python tests/players/build_scenarios.py [OUT_DIR]     (default: tests/players/scenarios)

Together with the reference examples they cover every maneuver and condition kind, join-one
nodes and a join-one end node, conditions after conditions, modules nested three deep with
joins inside, and the combinations whose meaning used to differ between the export, the preview
and esmini. All positions lie on `maps/intersection.xodr` (docs/map.md: the junction is at the
origin, each arm a straight 100 m road whose s counts away from it). The committed files must
equal this script's output (tests/players/test_scenarios.py).

  longitudinal.xmi        east arm: Accelerate, Follow, KeepVelocity, Decelerate, Approach, Stop,
                          DriveDistance; SpeedCondition -> TimeToCollision -> InVehicleRadius
  junction.xmi            TurnRight, TurnLeft, LaneChange, Cross, FollowTrajectory,
                          InLocationRadius, TimeElapsed; a JoinOneFinished and a JoinAllFinished
  join-one-end.xmi        Overtake; the end node waits for the first of three branches
  nested.xmi              library/players-library.xmi: Outer uses Middle uses Inner (three deep),
                          with a JoinOneFinished inside Middle, used twice
  drive-after-moving.xmi  a DriveDistance that starts after the actor has driven for 3 s
  turn-while-speeding.xmi a TurnRight while an Accelerate of the same actor runs
  follow-in-turn.xmi      a Follow of a car that turns, while the follower turns too
  join-one-race.xmi       two cars race; a JoinOneFinished of their arrivals ends it
  parallel.xmi            two actors, each with a lateral and a longitudinal maneuver at once
  stop-on-arrival.xmi     a condition that ends the run on its own (written into the StopTrigger)
  interrupts.xmi          a Decelerate that interrupts a running Accelerate (release 1.5)
  follow-interrupted.xmi  a Decelerate that interrupts a Follow before its gap is reached
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

import scemlmodel as scm
from sceml.model.build import LibraryBuilder, ScenarioBuilder, lane, world
from sceml.model.saving import save

HERE = Path(__file__).resolve().parent
MAP = HERE.parent.parent / "maps" / "intersection.xodr"
OUT = HERE / "scenarios"
DATE = "2026-01-01T00:00:00"
NORTH, EAST, SOUTH, WEST = "1", "2", "3", "4"


def new_scenario(
    name: str, map_text: str, description: str, end_policy: str = "joinAll"
) -> ScenarioBuilder:
    """A concrete scenario on the intersection map (`map_text`, relative to the file) with a
    60 s limit."""
    return ScenarioBuilder(
        name,
        map=map_text,
        level="concrete",
        date=DATE,
        max_duration=60.0,
        description=description,
        end_policy=end_policy,
    )


def build_longitudinal(map_text: str) -> scm.Scenario:
    """Every longitudinal maneuver on the east arm, and a chain of three conditions."""
    b = new_scenario(
        "Longitudinal", map_text, "Follow and approach a truck that stops; an oncoming car."
    )
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=5.0)
    truck = b.actor("Truck", "truck", start=lane(EAST, -1, 35.0), speed=4.0)
    oncoming = b.actor("Car", "oncoming", start=lane(EAST, 1, 95.0), speed=0.0)
    b.chain(
        b.root,
        b.add("Accelerate", ego, targetSpeed=8.0, rate=2.0),
        b.add("Follow", ego, target=truck, distance=15.0),
        b.add("KeepVelocity", ego, duration=1.0),
        b.add("Decelerate", ego, targetSpeed=3.0, rate=2.0),
        b.add("Approach", ego, target=truck, distance=10.0),
        b.add("Stop", ego, rate=4.0),
        b.end,
    )
    b.chain(
        b.root,
        b.add("KeepVelocity", truck, duration=6.0),
        b.add("Stop", truck, rate=2.0),
        b.end,
    )
    b.chain(
        b.root,
        b.add("TimeElapsed", oncoming, duration=1.0),
        b.add("DriveDistance", oncoming, distance=40.0, speed=6.0),
        b.end,
    )
    b.chain(
        b.root,
        b.add("SpeedCondition", ego, rule="greaterThan", speed=7.0),
        b.add("TimeToCollision", ego, target=truck, rule="lessThan", time=6.0),
        b.add("InVehicleRadius", ego, target=truck, radius=20.0),
        b.end,
    )
    return b.scenario


def build_junction(map_text: str) -> scm.Scenario:
    """Turns, a lane change, a crossing pedestrian and a bike on a trajectory; joins of both kinds."""
    b = new_scenario(
        "Junction", map_text, "Two cars turn, a pedestrian crosses, a bike rides round a corner."
    )
    ego = b.actor("Car", "ego", ego=True, start=lane(SOUTH, 1, 30.0), speed=5.0)
    car = b.actor("Car", "car", start=lane(NORTH, 1, 10.0), speed=0.0)
    walker = b.actor("Pedestrian", "walker", start=world(-4.5, 10.0, h=0.0), speed=0.0)
    bike = b.actor("Bicycle", "bike", start=lane(SOUTH, 2, 15.0), speed=3.0)
    ego_arrived = b.add("InLocationRadius", ego, position=world(34.0, -1.75), radius=3.0)
    b.chain(
        b.root,
        b.add("Accelerate", ego, targetSpeed=8.0, rate=2.0),
        b.add("TurnRight", ego, destination=world(34.0, -1.75), tolerance=3.0),
        ego_arrived,
        b.add("LaneChange", ego, direction="left", distance=40.0),
    )
    car_arrived = b.add("InLocationRadius", car, position=world(44.0, -1.75), radius=3.0)
    b.chain(
        b.root,
        b.add("TimeElapsed", car, duration=1.0),
        b.add("Accelerate", car, targetSpeed=6.0, rate=2.0),
        b.add("TurnLeft", car, destination=world(44.0, -1.75), tolerance=3.0),
        car_arrived,
    )
    lane_change = ego_arrived.outgoing[0].target
    first = b.join_one(lane_change, car_arrived)
    crossing = [
        b.add("InVehicleRadius", walker, target=car, radius=6.0),
        b.add("Accelerate", walker, targetSpeed=1.5, rate=1.0),
        b.add("Cross", walker, destination=world(4.5, 10.0), tolerance=1.0),
        b.add("InLocationRadius", walker, position=world(4.5, 10.0), radius=1.0),
    ]
    b.chain(b.root, *crossing)
    corner = [world(4.5, -12.0, h=math.pi / 2), world(10.0, -4.5)]
    ride = b.add("FollowTrajectory", bike, waypoints=corner, tolerance=1.5)
    b.chain(b.root, ride)
    b.chain(b.join_all(first, crossing[-1], ride), b.end)
    return b.scenario


def build_join_one_end(map_text: str) -> scm.Scenario:
    """An overtaking that ends the scenario while two slower branches still run."""
    b = new_scenario(
        "JoinOneEnd",
        map_text,
        "The ego overtakes a truck; the first of three branches ends it.",
        "joinOne",
    )
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 2.0), speed=8.0)
    truck = b.actor("Truck", "truck", start=lane(EAST, -1, 22.0), speed=4.0)
    overtake = b.add(
        "Overtake", ego, target=truck, side="left", speed=12.0, gap=8.0, laneChangeDistance=15.0
    )
    b.chain(b.root, overtake, b.end)
    b.chain(b.root, b.add("KeepVelocity", truck, duration=40.0), b.end)
    b.chain(b.root, b.add("TimeElapsed", ego, duration=45.0), b.end)
    return b.scenario


def build_drive_after_moving(map_text: str) -> scm.Scenario:
    """Issue 25, 1: 20 m driven from where the node starts, after 3 s at 8 m/s."""
    b = new_scenario("DriveAfterMoving", map_text, "The ego drives 3 s, then 20 m more at 8 m/s.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=8.0)
    b.chain(
        b.root,
        b.add("KeepVelocity", ego, duration=3.0),
        b.add("DriveDistance", ego, distance=20.0, speed=8.0),
        b.add("Stop", ego, rate=4.0),
        b.end,
    )
    return b.scenario


def build_turn_while_speeding(map_text: str) -> scm.Scenario:
    """Issue 25, 2: a right turn while the same actor still accelerates."""
    b = new_scenario("TurnWhileSpeeding", map_text, "The ego speeds up while it turns right.")
    ego = b.actor("Car", "ego", ego=True, start=lane(SOUTH, 1, 25.0), speed=3.0)
    faster = b.add("Accelerate", ego, targetSpeed=9.0, rate=1.0)
    turn = b.add("TurnRight", ego, destination=world(44.0, -1.75), tolerance=3.0)
    b.chain(b.root, faster)
    b.chain(b.root, turn)
    b.chain(b.join_all(faster, turn), b.end)
    return b.scenario


def build_follow_in_turn(map_text: str) -> scm.Scenario:
    """Issue 25, 2: the ego follows a car through a right turn, turning itself."""
    b = new_scenario("FollowInTurn", map_text, "The ego follows a car that turns right.")
    ego = b.actor("Car", "ego", ego=True, start=lane(SOUTH, 1, 40.0), speed=6.0)
    lead = b.actor("Car", "lead", start=lane(SOUTH, 1, 20.0), speed=6.0)
    b.chain(
        b.root,
        b.add("TurnRight", lead, destination=world(54.0, -1.75), tolerance=3.0),
        b.add("Stop", lead, rate=2.0),
        b.end,
    )
    follow = b.add("Follow", ego, target=lead, distance=15.0)
    turn = b.add("TurnRight", ego, destination=world(34.0, -1.75), tolerance=3.0)
    b.chain(b.root, follow)
    b.chain(b.root, turn)
    b.chain(b.join_all(follow, turn), b.end)
    return b.scenario


def build_join_one_race(map_text: str) -> scm.Scenario:
    """Two cars race along parallel arms; the first arrival ends the scenario."""
    b = new_scenario("JoinOneRace", map_text, "Two cars race; the first to arrive ends it.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=0.0)
    rival = b.actor("Car", "rival", start=lane(WEST, -1, 5.0), speed=0.0)
    ego_there = b.add("InLocationRadius", ego, position=lane(EAST, -1, 60.0), radius=2.0)
    rival_there = b.add("InLocationRadius", rival, position=lane(WEST, -1, 60.0), radius=2.0)
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=10.0, rate=3.0), ego_there)
    b.chain(b.root, b.add("DriveDistance", rival, distance=70.0, speed=9.0), rival_there)
    b.chain(b.join_one(ego_there, rival_there), b.end)
    return b.scenario


def build_parallel(map_text: str) -> scm.Scenario:
    """Two actors, each changing lane while its speed changes."""
    b = new_scenario("Parallel", map_text, "Two cars each change lane while changing speed.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=6.0)
    other = b.actor("Car", "other", start=lane(WEST, -1, 5.0), speed=8.0)
    moves = [
        b.add("LaneChange", ego, direction="left", distance=30.0),
        b.add("Accelerate", ego, targetSpeed=10.0, rate=2.0),
        b.add("LaneChange", other, direction="left", distance=25.0),
        b.add("Decelerate", other, targetSpeed=4.0, rate=2.0),
    ]
    for move in moves:
        b.chain(b.root, move)
    b.chain(b.join_all(*moves), b.end)
    return b.scenario


def build_stop_on_arrival(map_text: str) -> scm.Scenario:
    """The ego's arrival ends the scenario while a truck still keeps its speed: the condition
    stands in the StopTrigger itself (`xosc.flows`), so the run stops in the step it holds."""
    b = new_scenario(
        "StopOnArrival", map_text, "The ego's arrival ends it; the truck's 40 s do not.", "joinOne"
    )
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=10.0)
    truck = b.actor("Truck", "truck", start=lane(WEST, -1, 5.0), speed=5.0)
    there = b.add("InLocationRadius", ego, position=lane(EAST, -1, 60.0), radius=2.0)
    b.chain(b.root, there, b.end)
    b.chain(b.root, b.add("KeepVelocity", truck, duration=40.0), b.end)
    return b.scenario


def build_interrupts(map_text: str) -> scm.Scenario:
    """Release 1.5: a Decelerate at 2 s interrupts an Accelerate of 10 s (players end the
    running speed action when another starts); a KeepVelocity waits for the Accelerate, which
    counts as finished when it is interrupted."""
    b = new_scenario("Interrupts", map_text, "The ego brakes at 2 s, ending its speed-up.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=5.0)
    faster = b.add("Accelerate", ego, targetSpeed=15.0, rate=1.0)
    brake = b.add("Decelerate", ego, targetSpeed=3.0, rate=2.0, interrupts=True)
    b.chain(b.root, faster)
    b.chain(b.root, b.add("TimeElapsed", ego, duration=2.0), brake)
    after = b.add("LaneChange", ego, direction="left", distance=20.0)
    b.chain(faster, after)
    b.chain(b.join_all(after, brake), b.end)
    return b.scenario


def build_follow_interrupted(map_text: str) -> scm.Scenario:
    """Release 1.5: a Decelerate at 2 s interrupts a Follow that has not reached its gap; the
    lane change after the Follow starts as the Follow counts as finished then."""
    b = new_scenario("FollowInterrupted", map_text, "The ego brakes at 2 s, ending its Follow.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=8.0)
    lead = b.actor("Car", "lead", start=lane(EAST, -1, 40.0), speed=4.0)
    follow = b.add("Follow", ego, target=lead, distance=10.0)
    brake = b.add("Decelerate", ego, targetSpeed=3.0, rate=2.0, interrupts=True)
    change = b.add("LaneChange", ego, direction="left", distance=20.0)
    b.chain(b.root, follow, change)
    b.chain(b.root, b.add("TimeElapsed", ego, duration=2.0), brake)
    b.chain(b.join_all(change, brake), b.end)
    return b.scenario


def build_library() -> scm.Library:
    """Inner in Middle in Outer, each with a role `driver` and a parameter passed down."""
    library = LibraryBuilder("player checks", "Modules nested three deep, with joins inside.")
    inner = library.module("Inner", "Wait, then wait for a speed.")
    driver = inner.role("driver", "FourWheeler")
    inner.chain(
        inner.in_port,
        inner.add("TimeElapsed", driver, duration=1.0),
        inner.add(
            "SpeedCondition",
            driver,
            rule="greaterThan",
            speed=inner.parameter("threshold", "m/s", 3.0),
        ),
        inner.out_port,
    )
    middle = library.module(
        "Middle", "Speed up; go on after a pause or a timer, the first of both."
    )
    driver = middle.role("driver", "FourWheeler")
    faster = middle.add("Accelerate", driver, targetSpeed=middle.parameter("speed", "m/s", 6.0))
    waited = middle.use(inner.definition, {"driver": driver})
    timer = middle.add("TimeElapsed", driver, duration=20.0)
    middle.chain(middle.in_port, faster, waited)
    middle.chain(faster, timer)
    middle.chain(middle.join_one(waited, timer), middle.out_port)
    outer = library.module("Outer", "Speed up, then slow down.")
    driver = outer.role("driver", "FourWheeler")
    speed = outer.parameter("speed", "m/s", 6.0)
    outer.chain(
        outer.in_port,
        outer.use(middle.definition, {"driver": driver}, {"speed": speed}),
        outer.add("Decelerate", driver, targetSpeed=2.0, rate=2.0),
        outer.out_port,
    )
    return library.library


def build_nested(map_text: str, library: scm.Library) -> scm.Scenario:
    """Two uses of Outer, one per car, joined at the end."""
    b = new_scenario("Nested", map_text, "Two cars run a module nested three deep.")
    ego = b.actor("Car", "ego", ego=True, start=lane(EAST, -1, 5.0), speed=2.0)
    other = b.actor("Car", "other", start=lane(WEST, -1, 5.0), speed=2.0)
    outer = next(m for m in library.modules if m.name == "Outer")
    b.chain(b.root, b.use(outer, {"driver": ego}, {"speed": 7.0}), b.end)
    b.chain(b.root, b.use(outer, {"driver": other}), b.end)
    return b.scenario


def build_all(out: Path) -> list[Path]:
    """Write every scenario (and the library they use) under `out`."""
    # Relative to the committed folder, so that a build elsewhere (the test's) is the same bytes.
    map_text = Path(os.path.relpath(MAP, OUT)).as_posix()
    library = build_library()
    written = [save(library, out / "library" / "players-library.xmi")]
    scenarios = {
        "longitudinal.xmi": build_longitudinal(map_text),
        "junction.xmi": build_junction(map_text),
        "join-one-end.xmi": build_join_one_end(map_text),
        "nested.xmi": build_nested(map_text, library),
        "drive-after-moving.xmi": build_drive_after_moving(map_text),
        "turn-while-speeding.xmi": build_turn_while_speeding(map_text),
        "follow-in-turn.xmi": build_follow_in_turn(map_text),
        "join-one-race.xmi": build_join_one_race(map_text),
        "parallel.xmi": build_parallel(map_text),
        "stop-on-arrival.xmi": build_stop_on_arrival(map_text),
        "interrupts.xmi": build_interrupts(map_text),
        "follow-interrupted.xmi": build_follow_interrupted(map_text),
    }
    for name, scenario in scenarios.items():
        written.append(save(scenario, out / name))
    return written


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("out", type=Path, nargs="?", default=OUT, help="folder to write into")
    for path in build_all(parser.parse_args(argv).out):
        print(path)


if __name__ == "__main__":
    main()

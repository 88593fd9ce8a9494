"""Build the concrete scenarios that exercise every node kind in a player (issue 13).

    python scripts/esmini_scenarios.py OUT_DIR
    python scripts/esmini_check.py OUT_DIR/*.xmi --esmini /path/to/esmini

Together with the reference examples they cover every maneuver and condition kind, join-one
nodes and a join-one end node, conditions after conditions, and modules nested three deep with
joins inside. All positions lie on `maps/intersection.xodr` (docs/map.md for its layout: the
junction is at the origin, each arm is a straight 100 m road whose s counts away from it):

  longitudinal.xmi   east arm: Accelerate, Follow, KeepVelocity, Decelerate, Approach, Stop,
                     DriveDistance; SpeedCondition -> TimeToCollision -> InVehicleRadius
  junction.xmi       TurnRight, TurnLeft, LaneChange, Cross, FollowTrajectory, InLocationRadius,
                     TimeElapsed; a JoinOneFinished and a JoinAllFinished
  join-one-end.xmi   Overtake; the end node waits for the first of three branches
  nested.xmi         a library of its own (library/esmini-library.xmi): Outer uses Middle uses
                     Inner, with a JoinOneFinished inside Middle, used twice
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

import scemlmodel as scm
from sceml import io
from sceml.build import LibraryBuilder, ScenarioBuilder, lane, world

MAP = Path(__file__).resolve().parent.parent / "maps" / "intersection.xodr"
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


def build_library() -> scm.Library:
    """Inner in Middle in Outer, each with a role `driver` and a parameter passed down."""
    library = LibraryBuilder("esmini checks", "Modules nested three deep, with joins inside.")
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
    map_text = Path(os.path.relpath(MAP, out.resolve())).as_posix()
    library = build_library()
    written = [io.save(library, out / "library" / "esmini-library.xmi")]
    scenarios = {
        "longitudinal.xmi": build_longitudinal(map_text),
        "junction.xmi": build_junction(map_text),
        "join-one-end.xmi": build_join_one_end(map_text),
        "nested.xmi": build_nested(map_text, library),
    }
    for name, scenario in scenarios.items():
        written.append(io.save(scenario, out / name))
    return written


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("out", type=Path, help="folder to write the scenarios into")
    for path in build_all(parser.parse_args(argv).out):
        print(path)


if __name__ == "__main__":
    main()

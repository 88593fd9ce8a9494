"""Rebuild the reference examples (SPEC §9) through SceML's public Python API.

    python examples/build_examples.py [--out DIR]

Writes, into `examples/` unless told otherwise:
  library/sceml-library.xmi            CrossingManeuver (and the modules built on lane changes)
  uis1-{functional,logical,concrete}.xmi
  uis2-{functional,logical,concrete}.xmi
  overtaking-{functional,logical,concrete}.xmi   Overtaking, three modules deep

Start positions and destinations come from `maps/positions.json`, which the map script computes
on real lanes of `maps/intersection.xodr`. The committed files must equal this script's output
(tests/examples checks it).
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Callable
from pathlib import Path

import scemlmodel as scm
from sceml.model.build import LibraryBuilder, ScenarioBuilder, lane, world
from sceml.model.params import ParameterInput, discrete, normal, span, uniform
from sceml.model.saving import save

HERE = Path(__file__).resolve().parent
POSITIONS = HERE.parent / "maps" / "positions.json"
LEVELS = ("functional", "logical", "concrete")
MAP = "../maps/intersection.xodr"
DATE = "2026-01-01T00:00:00"
LIBRARY_FILE = Path("library") / "sceml-library.xmi"


def positions() -> dict:
    """The reference positions computed on the map."""
    return json.loads(POSITIONS.read_text(encoding="utf-8"))


def chooser(level: str) -> Callable[[ParameterInput, ParameterInput | None], ParameterInput | None]:
    """Pick a parameter for a level: nothing when functional, the range when logical, else the value."""

    def pick(
        concrete: ParameterInput, logical: ParameterInput | None = None
    ) -> ParameterInput | None:
        if level == "functional":
            return None
        if level == "logical" and logical is not None:
            return logical
        return concrete

    return pick


def given(**parameters: ParameterInput | None) -> dict[str, ParameterInput]:
    """Drop the parameters a level leaves unset."""
    return {key: value for key, value in parameters.items() if value is not None}


def at(point: dict, level: str, *, heading: bool = True) -> scm.WorldPosition | None:
    """A world position from positions.json, or none at the functional level."""
    if level == "functional":
        return None
    return world(point["x"], point["y"], h=point["h"] if heading else 0.0)


def on_lane(point: dict, level: str) -> scm.LanePosition | None:
    """A lane position from positions.json, or none at the functional level."""
    if level == "functional":
        return None
    return lane(point["roadId"], point["laneId"], round(point["s"], 3), round(point["offset"], 3))


def build_library() -> scm.Library:
    """The example module library."""
    library = LibraryBuilder("SceML example library", "Reusable sub-scenarios of the examples.")
    crossing = library.module(
        "CrossingManeuver",
        "A road user waits until a vehicle comes close, then crosses the road to a destination.",
    )
    crosser = crossing.role("crosser", "TwoWheeler", "Pedestrian")
    trigger = crossing.role("trigger", "FourWheeler")
    radius = crossing.parameter("triggerRadius", "m", 10.0)
    speed = crossing.parameter("crossingSpeed", "m/s", 1.5)
    dest_x = crossing.parameter("destinationX", "m")
    dest_y = crossing.parameter("destinationY", "m")
    dest_h = crossing.parameter("destinationHeading", "rad", 0.0)
    arrival = crossing.parameter("arrivalRadius", "m", 2.0)
    wait = crossing.add("InVehicleRadius", crosser, target=trigger, radius=radius)
    go = crossing.add("Accelerate", crosser, targetSpeed=speed)
    cross = crossing.add("Cross", crosser, destination=world(dest_x, dest_y, h=dest_h))
    arrived = crossing.add(
        "InLocationRadius", crosser, position=world(dest_x, dest_y), radius=arrival
    )
    crossing.chain(crossing.in_port, wait, go, cross, arrived, crossing.out_port)
    add_overtaking_modules(library)
    return library.library


def add_overtaking_modules(library: LibraryBuilder) -> None:
    """Overtaking uses PassVehicle, which uses ChangeLaneLeft and ChangeLaneRight: three deep."""
    left = library.module(
        "ChangeLaneLeft",
        "Closes in on a lead vehicle; pulls out into the lane on the left when the time to "
        "collision drops below a threshold.",
    )
    driver = left.role("driver", "FourWheeler", "Motorcycle")
    lead = left.role("lead", "FourWheeler", "TwoWheeler")
    closing = left.add(
        "TimeToCollision",
        driver,
        target=lead,
        rule="lessThan",
        time=left.parameter("timeToCollision", "s", 3.0),
    )
    pull_out = left.add(
        "LaneChange",
        driver,
        direction="left",
        distance=left.parameter("laneChangeDistance", "m", 15.0),
    )
    left.chain(left.in_port, closing, pull_out, left.out_port)

    right = library.module(
        "ChangeLaneRight",
        "Stays in the passing lane for a while, then changes back into the lane on the right.",
    )
    driver = right.role("driver", "FourWheeler", "Motorcycle")
    hold = right.add("TimeElapsed", driver, duration=right.parameter("holdTime", "s", 1.5))
    cut_in = right.add(
        "LaneChange",
        driver,
        direction="right",
        distance=right.parameter("laneChangeDistance", "m", 15.0),
    )
    right.chain(right.in_port, hold, cut_in, right.out_port)

    passing = library.module(
        "PassVehicle",
        "Pulls out behind a slower vehicle, speeds up, drives past it and changes back.",
    )
    overtaker = passing.role("overtaker", "FourWheeler", "Motorcycle")
    overtaken = passing.role("overtaken", "FourWheeler", "TwoWheeler")
    speed = passing.parameter("passingSpeed", "m/s", 13.0)
    time = passing.parameter("passingTime", "s", 1.5)
    pull_out_use = passing.use(left.definition, {"driver": overtaker, "lead": overtaken})
    speed_up = passing.add("Accelerate", overtaker, targetSpeed=speed)
    cut_in_use = passing.use(right.definition, {"driver": overtaker}, {"holdTime": time})
    passing.chain(passing.in_port, pull_out_use, speed_up, cut_in_use, passing.out_port)

    overtaking = library.module(
        "Overtaking",
        "An overtaker passes a slower vehicle on the oncoming lane; an oncoming vehicle starts "
        "towards it once the overtaker comes within a radius.",
    )
    overtaker = overtaking.role("overtaker", "FourWheeler", "Motorcycle")
    overtaken = overtaking.role("overtaken", "FourWheeler", "TwoWheeler")
    oncoming = overtaking.role("oncoming", "FourWheeler", "TwoWheeler")
    pass_use = overtaking.use(
        passing.definition,
        {"overtaker": overtaker, "overtaken": overtaken},
        {
            "passingSpeed": overtaking.parameter("passingSpeed", "m/s", 13.0),
            "passingTime": overtaking.parameter("passingTime", "s", 1.5),
        },
    )
    sighted = overtaking.add(
        "InVehicleRadius",
        oncoming,
        target=overtaker,
        radius=overtaking.parameter("oncomingTriggerRadius", "m", 40.0),
    )
    approach = overtaking.add(
        "DriveDistance",
        oncoming,
        distance=overtaking.parameter("oncomingDistance", "m", 30.0),
        speed=overtaking.parameter("oncomingSpeed", "m/s", 10.0),
    )
    overtaking.chain(overtaking.in_port, pass_use)
    overtaking.chain(overtaking.in_port, sighted, approach)
    overtaking.chain(overtaking.join_all(pass_use, approach), overtaking.out_port)


def add_ego(b: ScenarioBuilder, where: dict, level: str) -> scm.Actor:
    """The ego car of both intersection scenarios, on its start lane."""
    pick = chooser(level)
    return b.actor(
        "Car",
        "ego",
        ego=True,
        start=on_lane(where["ego_start"], level),
        speed=pick(5.0, span(3.0, 7.0, 1.0)),
        model="vehicle.tesla.model3",
    )


def add_ego_turn(
    b: ScenarioBuilder, ego: scm.Actor, turn: str, speed: float, where: dict, level: str
) -> None:
    """The ego's branch of UIS1 and UIS2: accelerate, turn, and sync 1 (it reaches its
    destination around the corner), from the root to the end node."""
    pick = chooser(level)
    spread = normal(speed, 1.0, speed - 2.0, speed + 2.0)
    accelerate = b.add("Accelerate", ego, **given(targetSpeed=pick(speed, spread), rate=pick(2.0)))
    turning = b.add(
        turn, ego, **given(destination=at(where["ego_destination"], level), tolerance=pick(3.0))
    )
    arrived = b.add(
        "InLocationRadius",
        ego,
        **given(position=at(where["ego_destination"], level), radius=pick(3.0)),
    )
    b.chain(b.root, accelerate, turning, arrived, b.end)


def build_uis1(level: str, where: dict) -> scm.Scenario:
    """UIS1: the ego turns right; a bike on a parallel lane crosses right after the intersection."""
    pick = chooser(level)
    b = ScenarioBuilder(
        "UIS1",
        map=MAP,
        level=level,
        date=DATE,
        max_duration=pick(60.0),
        description="Urban intersection: the ego turns right while a bike crosses the street.",
    )
    b.environment(time_of_day="12:00:00", cloud_state="free", precipitation="dry")
    ego = add_ego(b, where, level)
    bike = b.actor(
        "Bicycle",
        "bike",
        start=on_lane(where["bike_start"], level),
        speed=pick(0.0),
        model="vehicle.diamondback.century",
    )
    add_ego_turn(b, ego, "TurnRight", 8.0, where, level)
    ego_close = b.add(
        "InVehicleRadius", bike, target=ego, **given(radius=pick(12.0, span(8.0, 16.0, 4.0)))
    )
    bike_go = b.add(
        "Accelerate", bike, **given(targetSpeed=pick(4.0, uniform(3.0, 6.0)), rate=pick(1.5))
    )
    cross = b.add(
        "Cross",
        bike,
        **given(destination=at(where["bike_destination"], level), tolerance=pick(2.0)),
    )
    bike_arrived = b.add(
        "InLocationRadius",
        bike,
        **given(position=at(where["bike_destination"], level), radius=pick(2.0)),
    )
    b.chain(b.root, ego_close, bike_go, cross, bike_arrived, b.end)
    return b.scenario


def build_uis2(level: str, where: dict, library: scm.Library) -> scm.Scenario:
    """UIS2: the ego turns left, an oncoming car goes straight, a pedestrian crosses (a module use)."""
    pick = chooser(level)
    b = ScenarioBuilder(
        "UIS2",
        map=MAP,
        level=level,
        date=DATE,
        max_duration=pick(60.0),
        description="Urban intersection: the ego turns left, an oncoming car goes straight and a "
        "pedestrian crosses on the left.",
    )
    b.environment(time_of_day="12:00:00", cloud_state="free", precipitation="dry")
    ego = add_ego(b, where, level)
    car = b.actor(
        "Car",
        "car",
        start=on_lane(where["oncoming_start"], level),
        speed=pick(0.0),
        model="vehicle.audi.a2",
    )
    pedestrian = b.actor(
        "Pedestrian",
        "pedestrian",
        start=on_lane(where["pedestrian_start"], level),
        speed=pick(0.0),
        model="walker.pedestrian.0001",
    )
    add_ego_turn(b, ego, "TurnLeft", 7.0, where, level)
    ego_in_junction = b.add(
        "InLocationRadius",
        ego,
        **given(
            position=at(where["intersection_location"], level),
            radius=pick(4.0, span(3.0, 6.0, 1.0)),
        ),
    )
    drive = b.add(
        "DriveDistance",
        car,
        **given(distance=pick(60.0), speed=pick(10.0, discrete([8.0, 10.0, 12.0]))),
    )
    crossing = library.modules[0]
    destination = where["pedestrian_destination"]
    overrides = given(
        triggerRadius=pick(15.0, span(10.0, 20.0, 5.0)),
        crossingSpeed=pick(1.5, uniform(1.0, 2.0)),
        destinationX=pick(round(destination["x"], 3)),
        destinationY=pick(round(destination["y"], 3)),
        destinationHeading=pick(round(destination["h"], 6)),
    )
    pedestrian_part = b.use(crossing, {"crosser": pedestrian, "trigger": car}, overrides)
    b.chain(b.root, ego_in_junction, drive, b.end)
    b.chain(b.root, pedestrian_part, b.end)
    return b.scenario


def on_road(road_id: str, lane_id: int, s: float, level: str) -> scm.LanePosition | None:
    """A lane position on a straight arm of the map, or none at the functional level."""
    return None if level == "functional" else lane(road_id, lane_id, s)


def build_overtaking(level: str, arm: dict, library: scm.Library) -> scm.Scenario:
    """Overtaking on the east arm: the ego passes a slow truck using the oncoming lane."""
    pick = chooser(level)
    b = ScenarioBuilder(
        "Overtaking",
        map=MAP,
        level=level,
        date=DATE,
        max_duration=pick(30.0),
        description="Straight road: the ego overtakes a slow truck on the oncoming lane; an "
        "oncoming car starts towards it during the manoeuvre.",
    )
    b.environment(time_of_day="12:00:00", cloud_state="free", precipitation="dry")
    road, lanes = arm["roadId"], arm["driving"]
    # Outbound traffic drives along s (away from the junction); the oncoming car comes back.
    ego = b.actor(
        "Car",
        "ego",
        ego=True,
        start=on_road(road, lanes["outbound"], 2.0, level),
        speed=pick(10.0, span(9.0, 11.0, 1.0)),
        model="vehicle.tesla.model3",
    )
    truck = b.actor(
        "Truck",
        "truck",
        start=on_road(road, lanes["outbound"], 22.0, level),
        speed=pick(4.0, span(3.0, 5.0, 1.0)),
        model="vehicle.carlamotors.carlacola",
    )
    oncoming = b.actor(
        "Car",
        "oncoming",
        start=on_road(road, lanes["inbound"], 95.0, level),
        speed=pick(0.0),
        model="vehicle.audi.a2",
    )
    keep = b.add("KeepVelocity", truck, **given(duration=pick(6.0)))
    overtaking = next(m for m in library.modules if m.name == "Overtaking")
    overrides = given(
        passingSpeed=pick(13.0, uniform(12.0, 14.0)),
        oncomingTriggerRadius=pick(40.0, span(30.0, 50.0, 10.0)),
        oncomingSpeed=pick(10.0, discrete([8.0, 10.0, 12.0])),
    )
    bindings = {"overtaker": ego, "overtaken": truck, "oncoming": oncoming}
    manoeuvre = b.use(overtaking, bindings, overrides)
    b.chain(b.root, manoeuvre, b.end)
    b.chain(b.root, keep, b.end)
    return b.scenario


def build_all(out: Path) -> list[Path]:
    """Build and save every example under `out`; returns the files written."""
    where = positions()
    library = build_library()
    written = [save(library, out / LIBRARY_FILE)]
    for level in LEVELS:
        written.append(save(build_uis1(level, where["uis1"]), out / f"uis1-{level}.xmi"))
        written.append(save(build_uis2(level, where["uis2"], library), out / f"uis2-{level}.xmi"))
    east = where["map"]["arms"]["east"]
    for level in LEVELS:
        written.append(
            save(build_overtaking(level, east, library), out / f"overtaking-{level}.xmi")
        )
    return written


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=HERE, help="folder to write into")
    arguments = parser.parse_args(argv)
    for path in build_all(arguments.out):
        print(path)


if __name__ == "__main__":
    main()

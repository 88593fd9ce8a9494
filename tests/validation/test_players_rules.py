"""The Y rules: combinations whose meaning no player can keep (issue 25)."""

from __future__ import annotations

from sceml.model.build import LibraryBuilder, ScenarioBuilder, lane, relative_object, world
from sceml.validation import validate


def codes(model: object, **options: object) -> set[str]:
    return {d.code for d in validate(model, **options)}  # type: ignore[arg-type]


def scenario(speed: float = 0.0) -> ScenarioBuilder:
    b = ScenarioBuilder("T", map="town.xodr", level="concrete")
    b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0), speed=speed)
    return b


def test_a_drive_distance_at_zero_speed_never_finishes() -> None:
    b = scenario()
    ego = b.root.actors[0]
    b.chain(b.root, b.add("DriveDistance", ego, distance=20.0, speed=0.0), b.end)
    assert codes(b.scenario) == {"SCEML-Y001"}
    moving = scenario()
    ego = moving.root.actors[0]
    moving.chain(
        moving.root, moving.add("DriveDistance", ego, distance=20.0, speed=5.0), moving.end
    )
    assert codes(moving.scenario) == set()


def test_a_zero_speed_drive_distance_inside_a_module_is_found_at_its_use() -> None:
    library = LibraryBuilder("lib")
    module = library.module("Creep")
    driver = module.role("driver", "FourWheeler")
    speed = module.parameter("speed", "m/s", 5.0)
    module.chain(
        module.in_port,
        module.add("DriveDistance", driver, distance=10.0, speed=speed),
        module.out_port,
    )
    b = scenario()
    ego = b.root.actors[0]
    b.chain(b.root, b.use(module.definition, {"driver": ego}, {"speed": 0.0}), b.end)
    found = [d for d in validate(b.scenario) if d.code == "SCEML-Y001"]
    assert len(found) == 1 and "Creep_1.DriveDistance_1" in found[0].message


def test_a_turn_after_another_routed_maneuver_of_its_actor_is_warned_if_it_leaves_no_place() -> (
    None
):
    """The export routes a turn from where its actor's latest routed maneuver leaves it; a
    place relative to an entity is read at t = 0, so the route starts at the start instead."""
    b = scenario(speed=5.0)
    ego = b.root.actors[0]
    car = b.actor("Car", "car", start=lane(1, -1, 30.0), speed=0.0)
    first = b.add("TurnRight", ego, destination=relative_object(car, 5.0), tolerance=3.0)
    second = b.add("TurnLeft", ego, destination=world(-1.75, 34.0), tolerance=3.0)
    b.chain(b.root, first, second, b.end)
    diagnostics = [d for d in validate(b.scenario) if d.code == "SCEML-Y002"]
    assert [d.path for d in diagnostics] == ["TurnLeft_1"]
    # After a turn to a place on the map, the second turn's route starts there: no warning.
    first.destination = world(34.0, -1.75)
    assert "SCEML-Y002" not in codes(b.scenario)
    # Another actor's turn before it does not matter.
    c = scenario(speed=5.0)
    ego = c.root.actors[0]
    car = c.actor("Car", "car", start=lane(1, -1, 30.0), speed=5.0)
    c.chain(
        c.root,
        c.add("TurnRight", car, destination=world(34.0, -1.75), tolerance=3.0),
        c.add("TurnLeft", ego, destination=world(-1.75, 34.0), tolerance=3.0),
        c.end,
    )
    assert "SCEML-Y002" not in codes(c.scenario)


def test_for_carla_a_drive_distance_of_a_moving_actor_is_warned() -> None:
    b = scenario(speed=5.0)
    ego = b.root.actors[0]
    b.chain(b.root, b.add("DriveDistance", ego, distance=20.0, speed=5.0), b.end)
    assert codes(b.scenario, osc_profile="carla") == {"SCEML-Y003"}
    assert codes(b.scenario) == set()  # the generic export measures from the node's start
    resting = scenario(speed=0.0)
    ego = resting.root.actors[0]
    resting.chain(
        resting.root, resting.add("DriveDistance", ego, distance=20.0, speed=5.0), resting.end
    )
    assert codes(resting.scenario, osc_profile="carla") == set()

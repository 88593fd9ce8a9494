"""A maneuver that interrupts (release 1.5) says what it ends on its box; one that does not
says nothing of it."""

from __future__ import annotations

from sceml.model.build import ScenarioBuilder, lane, world
from sceml.render.labels import Scope, action_lines


def test_the_interrupts_line_names_the_axes_it_takes() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    car = b.actor("Car", "car", start=world(30.0, 0.0), speed=5.0)
    plain = b.add("KeepVelocity", ego, duration=2.0)
    brake = b.add("KeepVelocity", ego, duration=2.0, interrupts=True)
    swerve = b.add("LaneChange", ego, direction="left", interrupts=True)
    overtake = b.add("Overtake", ego, target=car, speed=12.0, interrupts=True)
    path = b.add("FollowTrajectory", ego, waypoints=[lane(1, -1, 30.0)], interrupts=True)
    assert action_lines(plain, Scope()) == ["ego", "duration: 2 s"]
    assert action_lines(brake, Scope())[-1] == "interrupts: the running longitudinal one"
    assert action_lines(swerve, Scope())[-1] == "interrupts: the running lateral one"
    assert "interrupts: the running lateral and longitudinal one" in action_lines(overtake, Scope())
    # A FollowTrajectory takes the path only (model.axes).
    assert "interrupts: the running lateral one" in action_lines(path, Scope())

"""A lane change given in time (release 1.5's duration) says so on its box, in seconds."""

from __future__ import annotations

from sceml.model.build import ScenarioBuilder, world
from sceml.render.labels import Scope, action_lines


def test_a_timed_lane_change_box_shows_its_duration() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    timed = b.add("LaneChange", ego, direction="right", duration=3.0)
    assert action_lines(timed, Scope()) == ["ego", "direction: right", "duration: 3 s"]
    by_distance = b.add("LaneChange", ego, direction="right", distance=40.0)
    assert action_lines(by_distance, Scope()) == ["ego", "direction: right", "distance: 40 m"]

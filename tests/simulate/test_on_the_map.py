"""Actors on the project's intersection map (maps/intersection.xodr, docs/map.md).

The east arm, road 2, runs from (9, 0) due east for 100 m; its lane -1 (traffic along s) has
its centre at y = -1.75, lane 1 (the other way) at y = +1.75, both 3.5 m wide.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import REPO

from sceml.model.build import ScenarioBuilder, lane, world
from sceml.simulate import END_NODE, simulate

MAP = str(REPO / "maps" / "intersection.xodr")


def builder() -> ScenarioBuilder:
    return ScenarioBuilder("map", map=MAP, level="concrete", max_duration=30.0)


def test_an_actor_follows_its_lane_centre_line() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 10.0), speed=10.0)
    b.chain(b.root, b.add("TimeElapsed", ego, duration=3.0), b.end)
    run = simulate(b.scenario, Path(MAP))
    # s = 10 is x = 19; the wait runs 0-3 s and is the StopTrigger's delay, so the end node
    # finishes at 3 s: at 10 m/s, x = 49, still on the centre line y = -1.75.
    assert run.end_time == pytest.approx(3.0)
    x, y, heading, _ = run.states[0, -1]
    assert (x, y, heading) == pytest.approx((49.0, -1.75, 0.0), abs=1e-6)


def test_a_lane_change_ends_on_the_lane_beside_after_its_distance() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 10.0), speed=10.0)
    change = b.add("LaneChange", ego, direction="left", distance=20.0)
    b.chain(b.root, change, b.end)
    run = simulate(b.scenario, Path(MAP))
    # 20 m along the road, one lane (3.5 m) to the left on half a cosine. The speed is along
    # the heading, so the car needs the curve's length at 10 m/s: the arc length of
    # y = 1.75 (1 - cos(pi x / 20)) over 20 m, 20.38 m (integrated here), about 2.04 s from
    # the start of the first step; the step that passes it ends at 2.05 s.
    x = np.linspace(0.0, 20.0, 20001)
    slope = 1.75 * np.pi / 20.0 * np.sin(np.pi * x / 20.0)
    arc = float(np.sum(np.hypot(np.diff(x), np.diff(x) * (slope[1:] + slope[:-1]) / 2)))
    assert arc == pytest.approx(20.38, abs=0.01)
    assert run.node(change.name).finished == pytest.approx(2.05)
    assert run.end_time == pytest.approx(2.1)
    x_end, y_end, heading, _ = run.states[0, -1]
    # Then on along the new lane: x = 19 + 20 + 10 * (2.1 - arc / 10) at y = 1.75.
    assert (x_end, y_end) == pytest.approx((39.0 + 10 * (2.1 - arc / 10), 1.75), abs=0.02)
    assert heading == pytest.approx(0.0, abs=1e-6)


def test_follow_closes_up_to_the_gap_and_keeps_it() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=12.0)
    lead = b.actor("Car", "lead", start=lane(2, -1, 45.0), speed=8.0)
    follow = b.add("Follow", ego, target=lead, distance=15.0)
    # The lead reaches the end of its road (x = 109) at about 6.9 s and stops there.
    b.chain(b.root, follow, b.add("TimeElapsed", ego, duration=2.5), b.end)
    run = simulate(b.scenario, Path(MAP))
    assert run.node(follow.name).finished is not None
    gap = run.states[1, -1, 0] - run.states[0, -1, 0]
    assert gap == pytest.approx(15.0, abs=0.3)
    assert run.states[0, -1, 3] == pytest.approx(8.0, abs=0.1)
    assert not run.pair("ego", "lead").collision


def test_a_right_turn_goes_through_the_junction_to_its_destination() -> None:
    b = builder()
    # South arm, road 3, lane 1 runs north towards the junction; the destination lies on the
    # east arm's lane -1 (as in UIS1).
    ego = b.actor("Car", "ego", ego=True, start=lane(3, 1, 20.0), speed=8.0)
    turn = b.add("TurnRight", ego, destination=world(34.0, -1.75), tolerance=1.0)
    b.chain(b.root, turn, b.end)
    run = simulate(b.scenario, Path(MAP))
    assert run.end_reason == END_NODE
    x, y, heading, _ = run.states[0, -1]
    assert abs(x - 34.0) <= 1.0 and y == pytest.approx(-1.75, abs=1e-3)
    assert heading == pytest.approx(0.0, abs=1e-3)  # eastwards after turning right from north
    assert not run.notes


def test_overtake_passes_in_three_phases_and_returns_ahead_of_the_target() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=10.0)
    slow = b.actor("Truck", "truck", start=lane(2, -1, 25.0), speed=5.0)
    overtake = b.add(
        "Overtake", ego, target=slow, side="left", speed=15.0, gap=10.0, laneChangeDistance=15.0
    )
    b.chain(b.root, overtake, b.end)
    run = simulate(b.scenario, Path(MAP))
    assert run.node(overtake.name).finished is not None
    ego_x, ego_y = run.states[0, -1, :2]
    assert ego_y == pytest.approx(-1.75, abs=1e-6)  # back in its lane
    assert ego_x - run.states[1, -1, 0] >= 10.0  # at least the gap ahead
    assert run.states[0, :, 1].max() == pytest.approx(1.75, abs=1e-6)  # it used the other lane
    assert not run.pair("ego", "truck").collision


def test_an_actor_stops_at_the_end_of_a_road_without_a_link_and_a_follow_does_not_stall() -> None:
    b = builder()
    # The east arm ends at x = 109 with no road on: the lead (from x = 89 at 10 m/s) stops
    # there at 2.0 s, as players stop it, and the ego following it closes up and finishes.
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=8.0)
    lead = b.actor("Car", "lead", start=lane(2, -1, 80.0), speed=10.0)
    follow = b.add("Follow", ego, target=lead, distance=15.0)
    b.chain(b.root, follow, b.end)
    b.chain(b.root, b.add("TimeElapsed", lead, duration=1.0), b.end)
    run = simulate(b.scenario, Path(MAP))
    assert run.end_reason == END_NODE
    k = int(round(2.0 / run.step))
    assert run.states[1, k, :2] == pytest.approx((109.0, -1.75))
    assert np.all(run.states[1, k:, 0] == 109.0) and np.all(run.states[1, k:, 3] == 0.0)
    assert "lead stopped at the end of its road at 2.00 s (no road on)" in run.notes
    finished = run.node(follow.name).finished
    assert finished is not None and finished > 2.0  # it was still running when the lead stopped
    gap = run.states[1, -1, 0] - run.states[0, -1, 0]
    assert gap < 15.0 + 1.5 and not run.pair("ego", "lead").collision

"""The reference examples: their timelines follow the graph (SPEC §3, §9)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import EXAMPLES

from sceml.model.loading import load_scenario
from sceml.simulate import END_NODE, Run, simulate

#: A flow costs one time step (xosc.meaning.FLOW_DELAY_STEPS): a node starts one step
#: after its predecessor finished; none out of a condition the export writes into its
#: successor's trigger (xosc.flows.inlined).
STEP = 0.05


def run_of(name: str) -> Run:
    path = EXAMPLES / name
    return simulate(load_scenario(path).root, path)


def distance(run: Run, a: str, b: str, k: int) -> float:
    pa, pb = run.states[run.actor_index(a), k], run.states[run.actor_index(b), k]
    return math.hypot(pa[0] - pb[0], pa[1] - pb[1])


def index(run: Run, t: float) -> int:
    return int(np.argmin(np.abs(run.times - t)))


def test_uis1_the_bike_waits_until_the_ego_is_within_the_radius() -> None:
    run = run_of("uis1-concrete.xmi")
    trigger = run.node("InVehicleRadius_1")
    # Ego from (1.75, -39) at 5 m/s, accelerating at 2 m/s2; bike at (4.5, -24). Within 12 m
    # once 2.75^2 + (15 - d)^2 <= 144, i.e. d >= 15 - 11.681 = 3.319 m; d = 5t + t^2 gives
    # t = 0.593 s: the sample at 0.6 s.
    assert trigger.finished == pytest.approx(0.6)
    k = index(run, trigger.finished)
    assert distance(run, "ego", "bike", k) <= 12.0 < distance(run, "ego", "bike", k - 1)
    bike = run.actor_index("bike")
    assert np.all(run.states[bike, : k + 1, 3] == 0.0)  # the bike stands until then
    assert np.allclose(run.states[bike, : k + 1, :2], (4.5, -24.0))
    # The radius is Accelerate_2's only predecessor and is written into its StartTrigger: it
    # starts in the instant the radius is reached and moves the bike from the next step on.
    assert run.node("Accelerate_2").started == pytest.approx(trigger.finished)
    # Accelerate_2: 0 -> 4 m/s at 1.5 m/s2 takes 8/3 s from the step after it starts (0.6 s
    # to 0.65 s), the next sample past 0.6 + 2.667 s.
    assert run.node("Accelerate_2").finished == pytest.approx(3.3)
    assert run.node("Cross_1").started == pytest.approx(3.3 + STEP)


def test_uis1_ends_when_both_branches_of_the_end_have_finished() -> None:
    run = run_of("uis1-concrete.xmi")
    # Accelerate_1: 5 -> 8 m/s at 2 m/s2, 1.5 s from the first step; then the turn.
    assert run.node("Accelerate_1").finished == pytest.approx(1.5)
    assert run.node("TurnRight_1").started == pytest.approx(1.5 + STEP)
    last = max(run.node("InLocationRadius_1").finished, run.node("InLocationRadius_2").finished)
    assert run.end_reason == END_NODE and run.end_time == pytest.approx(last + STEP)
    assert run.node("End").finished == pytest.approx(last + STEP)
    # The ego ends its turn on the east arm within 3 m of (34, -1.75); the bike across the road
    # within 2 m of (10, 4.5).
    ego_end = run.states[run.actor_index("ego"), index(run, run.node("TurnRight_1").finished)]
    assert math.hypot(ego_end[0] - 34.0, ego_end[1] + 1.75) <= 3.0
    bike_end = run.states[run.actor_index("bike"), -1]
    assert math.hypot(bike_end[0] - 10.0, bike_end[1] - 4.5) <= 2.0


def test_uis2_the_pedestrian_crosses_after_the_car_comes_close() -> None:
    run = run_of("uis2-concrete.xmi")
    # The car starts when the ego is within 4 m of the intersection location.
    assert run.node("DriveDistance_1").started == pytest.approx(
        run.node("InLocationRadius_2").finished + STEP
    )
    car = run.actor_index("car")
    k_car = index(run, run.node("DriveDistance_1").started) - 1  # it moves in its first step
    assert np.all(run.states[car, :k_car, 3] == 0.0)
    trigger = run.node("CrossingManeuver_1.InVehicleRadius_1")
    k = index(run, trigger.finished)
    assert trigger.finished > run.node("DriveDistance_1").started
    assert distance(run, "pedestrian", "car", k) <= 15.0 < distance(run, "pedestrian", "car", k - 1)
    cross = run.node("CrossingManeuver_1.Cross_1")
    assert cross.started == pytest.approx(
        run.node("CrossingManeuver_1.Accelerate_1").finished + STEP
    )
    walker = run.states[run.actor_index("pedestrian")]
    assert walker[0, 1] == pytest.approx(-4.5)
    assert walker[-1, 1] >= 4.5 - 2.0  # across the road, within the arrival radius
    assert np.all(np.abs(walker[:, 0] + 10.0) < 1.0)  # on the crossing at x = -10


def test_uis2_ends_by_its_end_node_when_its_three_branches_are_done() -> None:
    run = run_of("uis2-concrete.xmi")
    ends = [
        run.node("InLocationRadius_1").finished,
        run.node("DriveDistance_1").finished,
        run.node("CrossingManeuver_1.InLocationRadius_1").finished,
    ]
    assert all(t is not None for t in ends)
    last = max(ends)  # type: ignore[type-var]
    assert run.end_reason == END_NODE and run.end_time == pytest.approx(last + STEP)
    # DriveDistance: 60 m at 10 m/s (a step) takes 6 s.
    drive = run.node("DriveDistance_1")
    assert drive.finished - drive.started == pytest.approx(6.0)  # type: ignore[operator]


def test_the_overtaking_example_runs_its_nested_modules() -> None:
    run = run_of("overtaking-concrete.xmi")
    assert run.end_reason == END_NODE
    assert all(r.finished is not None for r in run.timeline)


def test_the_overtaking_example_overtakes_without_contact_and_is_back_before_the_road_ends() -> (
    None
):
    run = run_of("overtaking-concrete.xmi")
    assert not run.collided and not run.notes  # nobody touches, nobody reaches the road's end
    back = run.node("Overtaking_1.PassVehicle_1.ChangeLaneRight_1.LaneChange_1").finished
    assert back is not None
    ego, truck = run.actor_index("ego"), run.actor_index("truck")
    k = index(run, back)
    # Back on its own lane (centre y = -1.75) ahead of the truck, short of the road's end
    # (x = 109); it had used the oncoming lane (centre y = +1.75) to pass.
    assert run.states[ego, k, 1] == pytest.approx(-1.75, abs=1e-6)
    assert run.states[truck, k, 0] < run.states[ego, k, 0] < 109.0
    assert run.states[ego, :, 1].max() == pytest.approx(1.75, abs=1e-6)
    assert run.pair("ego", "oncoming").min_distance > 1.0

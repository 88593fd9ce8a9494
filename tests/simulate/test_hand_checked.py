"""Cases with an answer worked out by hand: straight lines, constant speeds, known timings.

The actors stand on no map (no map named): each moves straight along its heading, so every
expectation below follows from x = x0 + v t with boxes of 4 m x 2 m. A flow costs one time
step of 0.05 s, as in players (`xosc.meaning.FLOW_DELAY_STEPS`): the root finishes at 0, the
nodes after it start at 0.05 s, and the end node finishes one step after its last predecessor.
A flow out of a wait, a join, or a condition the export writes into its successor's trigger
(`xosc.flows.inlined`) costs none: the successor starts in the instant it finishes.
"""

from __future__ import annotations

import numpy as np
import pytest

import scemlmodel as scm
from sceml.model.build import ScenarioBuilder, world
from sceml.simulate import END_NODE, MAX_DURATION, simulate
from sceml.simulate.geometry import Boxes, time_to_collision

SIZE = {"length": 4.0, "width": 2.0}


def builder(max_duration: float = 20.0, end_policy: str = "joinAll") -> ScenarioBuilder:
    return ScenarioBuilder(
        "hand", level="concrete", max_duration=max_duration, end_policy=end_policy
    )


def car(b: ScenarioBuilder, name: str, x: float, y: float, h: float, speed: float) -> scm.Actor:
    return b.actor("Car", name, ego=name == "ego", start=world(x, y, h=h), speed=speed, **SIZE)


def wait(b: ScenarioBuilder, actor: scm.Actor, seconds: float) -> scm.ActionNode:
    return b.add("TimeElapsed", actor, duration=seconds)


def test_constant_speeds_on_a_straight_road_give_the_analytic_ttc_and_distance() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 15.0)
    car(b, "lead", 30.0, 0.0, 0.0, 10.0)
    b.chain(b.root, wait(b, ego, 2.0), b.end)
    run = simulate(b.scenario)
    # The wait runs from 0 to 2 s (a flow out of the root costs no step) and is the
    # StopTrigger's delay: the end node finishes at 2 s. Gap between the boxes:
    # 30 - 4/2 - 4/2 = 26 m at t = 0, closing at 15 - 10 = 5 m/s. At the end it is
    # 26 - 2 * 5 = 16 m, and the TTC 16 / 5 = 3.2 s: both least then.
    assert run.end_reason == END_NODE and run.end_time == pytest.approx(2.0)
    pair = run.pair("ego", "lead")
    assert pair.min_distance == pytest.approx(16.0)
    assert pair.min_distance_time == pytest.approx(2.0)
    assert pair.min_ttc == pytest.approx(3.2)
    assert pair.min_ttc_time == pytest.approx(2.0)
    assert not pair.collision and pair.pet is None  # one path: nothing crosses


def test_a_rear_end_collision_comes_when_the_gap_closes() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 15.0)
    car(b, "lead", 30.1, 0.0, 0.0, 10.0)
    b.chain(b.root, wait(b, ego, 8.0), b.end)
    run = simulate(b.scenario)
    # Gap 30.1 - 4 = 26.1 m closing at 5 m/s: the boxes touch at 5.22 s and overlap after it;
    # the first sample past it is 5.25 s.
    pair = run.pair("ego", "lead")
    assert pair.collision and pair.collision_time == pytest.approx(5.25)
    assert pair.min_distance == 0.0 and pair.min_ttc == 0.0


def crossing(b_start_y: float, b_speed: float) -> scm.Scenario:
    """A from (-30.25, 0) east at 10 m/s; B from (0, b_start_y) north at b_speed."""
    b = builder(max_duration=8.0)
    a = car(b, "a", -30.25, 0.0, 0.0, 10.0)
    car(b, "b", 0.0, b_start_y, np.pi / 2, b_speed)
    b.chain(b.root, wait(b, a, 8.0), b.end)
    return b.scenario


def test_actors_on_crossing_paths_timed_to_collide_collide_at_the_computed_time() -> None:
    run = simulate(crossing(-20.0, 20.0 / 3.0))
    # A spans x +- 2 and y +- 1; B spans x +- 1 and y +- 2. They overlap while |x_A| < 3 and
    # |y_B| < 3: x_A = -30.25 + 10 t gives 2.725 s < t < 3.325 s; y_B = -20 + 20 t / 3 gives
    # 2.55 s < t < 3.45 s. First overlap after 2.725 s: the sample at 2.75 s.
    pair = run.pair("a", "b")
    assert pair.collision and pair.collision_time == pytest.approx(2.75)
    # Both pass the crossing point (0, 0) at the same time: PET 0.
    assert pair.pet == 0.0
    assert pair.pet_point == pytest.approx((0.0, 0.0), abs=1e-9)


def test_post_encroachment_time_where_paths_cross_apart_in_time() -> None:
    run = simulate(crossing(-40.0, 20.0 / 3.0))
    # Conflict zone: half a length plus half the other's width, 2 + 1 = 3 m, either side of
    # (0, 0). A leaves it at x = 3: t = 33.25 / 10 = 3.325 s. B enters at y = -3:
    # t = 37 / (20 / 3) = 5.55 s. PET = 5.55 - 3.325 = 2.225 s.
    pair = run.pair("a", "b")
    assert not pair.collision
    assert pair.pet == pytest.approx(2.225, abs=1e-6)


def test_time_to_collision_of_crossing_boxes_from_the_separating_axes() -> None:
    # The first case at t = 0: overlap on x from 2.725 s, on y from 2.55 s: TTC 2.725 s.
    def boxes(x: float, y: float, heading: float, speed: float) -> Boxes:
        one = np.array
        return Boxes.moving(one([x]), one([y]), one([heading]), one([speed]), 4.0, 2.0)

    ttc = time_to_collision(boxes(-30.25, 0.0, 0.0, 10.0), boxes(0.0, -20.0, np.pi / 2, 20 / 3))
    assert ttc[0] == pytest.approx(2.725)
    # Moving apart: never.
    assert np.isinf(time_to_collision(boxes(0, 0, 0, 5.0), boxes(10, 0, 0, 6.0))[0])


def test_a_condition_true_before_its_activation_does_not_fire_early() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 0.0)
    delay = wait(b, ego, 2.0)
    inside = b.add("InLocationRadius", ego, position=world(0.0, 0.0), radius=5.0)
    at_once = b.add("InLocationRadius", ego, position=world(0.0, 0.0), radius=5.0)
    b.chain(b.root, delay, inside, b.end)
    b.chain(b.root, at_once, b.end)
    run = simulate(b.scenario)
    # The ego stands inside the radius from t = 0; the wait runs from 0 to 2 s and is
    # written into the first condition's trigger as its delay, so that condition is activated
    # (and holds) at 2 s, the other at 0 s; both are markers the end waits for, a step.
    assert run.node(inside.name).started == pytest.approx(2.0)
    assert run.node(inside.name).finished == pytest.approx(2.0)
    assert run.node(at_once.name).finished == pytest.approx(0.0)
    assert run.end_time == pytest.approx(2.05)


def test_a_location_condition_holds_when_the_actor_reaches_the_radius() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 10.0)
    there = b.add("InLocationRadius", ego, position=world(50.0, 0.0), radius=5.0)
    b.chain(b.root, there, b.end)
    run = simulate(b.scenario)
    # Within 5 m of x = 50 from x = 45: at 10 m/s, t = 4.5 s (checked at every step from
    # its activation at 0 s).
    assert run.node(there.name).finished == pytest.approx(4.5)


def test_speed_changes_at_the_rate_and_finishes_at_the_target() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 5.0)
    speed_up = b.add("Accelerate", ego, targetSpeed=15.0, rate=2.0)
    b.chain(b.root, speed_up, b.end)
    run = simulate(b.scenario)
    # Started at 0 s by a trigger that holds then, it acts from the next step (as a player's
    # action does), so the speed changes from t = 0: (15 - 5) / 2 = 5 s,
    # 5 * 5 + 2 * 5^2 / 2 = 50 m by t = 5 s; the end node finishes a step later,
    # 15 * 0.05 = 0.75 m further.
    assert run.node(speed_up.name).started == pytest.approx(0.0)
    assert run.node(speed_up.name).finished == pytest.approx(5.0)
    k = int(round(5.0 / run.step))
    assert run.states[0, k, 0] == pytest.approx(50.0)
    assert run.states[0, -1, 0] == pytest.approx(50.75)
    assert run.states[0, -1, 3] == pytest.approx(15.0)


def test_join_one_finishes_with_the_first_branch_and_does_not_cancel_the_other() -> None:
    b = builder()
    ego = car(b, "ego", 0.0, 0.0, 0.0, 0.0)
    short, long = wait(b, ego, 1.0), wait(b, ego, 3.0)
    b.chain(b.root, short)
    b.chain(b.root, long)
    first = b.join_one(short, long)
    after = wait(b, ego, 0.5)
    b.chain(first, after)
    both = b.join_all(after, long)
    b.chain(both, b.end)
    run = simulate(b.scenario)
    # short 0-1 s, long 0-3 s. The root, waits and joins are written into their successors'
    # triggers, so no flow here costs a step: the join-one at 1 s, after 1-1.5 s, the
    # join-all with long at 3 s, the end node then too.
    assert run.node(first.name).finished == pytest.approx(1.0)
    assert run.node(after.name).finished == pytest.approx(1.5)
    assert run.node(long.name).finished == pytest.approx(3.0)  # not cancelled
    assert run.node(both.name).finished == pytest.approx(3.0)
    assert run.end_time == pytest.approx(3.0)


def test_a_join_one_end_stops_at_the_first_branch() -> None:
    b = builder(end_policy="joinOne")
    ego = car(b, "ego", 0.0, 0.0, 0.0, 0.0)
    short, long = wait(b, ego, 1.0), wait(b, ego, 3.0)
    b.chain(b.root, short, b.end)
    b.chain(b.root, long, b.end)
    run = simulate(b.scenario)
    # short finishes at 1 s; it is a delay in the StopTrigger, so the end node then too.
    assert run.end_reason == END_NODE and run.end_time == pytest.approx(1.0)
    assert run.node(long.name).finished is None  # still running when the scenario stopped


def test_the_maximum_duration_stops_a_run_whose_end_never_comes() -> None:
    b = builder(max_duration=3.0)
    ego = car(b, "ego", 0.0, 0.0, 0.0, 1.0)
    never = b.add("InLocationRadius", ego, position=world(500.0, 500.0), radius=1.0)
    b.chain(b.root, never, b.end)
    run = simulate(b.scenario)
    assert run.end_reason == MAX_DURATION and run.end_time == pytest.approx(3.0)
    assert run.node(never.name).finished is None
    assert run.node("End").started is None


def test_a_logical_scenario_is_refused() -> None:
    from sceml.simulate import SimulationError

    b = ScenarioBuilder("hand", level="logical")
    car(b, "ego", 0.0, 0.0, 0.0, 1.0)
    b.chain(b.root, b.end)
    with pytest.raises(SimulationError, match="concrete"):
        simulate(b.scenario)

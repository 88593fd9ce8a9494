"""Follow and Approach in the preview keep the gap as the node measures and limits it (release
1.5): between the boxes, a time gap, ahead of the target, within the stated acceleration, its
jerk, and the actor's own performance, as esmini drives a LongitudinalDistanceAction.

On the intersection map's east arm (road 2, from x = 9 due east; lane -1 at y = -1.75), with
the preview's 0.05 s step. Each expectation is worked out by hand in its comment.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import REPO

import scemlmodel as scm
from sceml.model.build import ScenarioBuilder, lane
from sceml.simulate import simulate

MAP = str(REPO / "maps" / "intersection.xodr")


def builder() -> ScenarioBuilder:
    return ScenarioBuilder("gap", map=MAP, level="concrete", max_duration=30.0)


def state_at(run: object, actor: int, t: float, which: int) -> float:
    """x (0) or speed (3) of an actor at time t."""
    times = run.times  # type: ignore[attr-defined]
    at = int(np.argmin(np.abs(times - t)))
    assert times[at] == pytest.approx(t)
    return float(run.states[actor, at, which])  # type: ignore[attr-defined]


def speed_at(run: object, actor: int, t: float) -> float:
    return state_at(run, actor, t, 3)


def x_at(run: object, actor: int, t: float) -> float:
    return state_at(run, actor, t, 0)


def far_lead(b: ScenarioBuilder) -> tuple[scm.Actor, scm.Actor]:
    """An ego at 5 m/s and a lead 40 m ahead at 10 m/s: the gap (15 m wanted) grows for the
    first seconds, so gap keeping asks for more than any limit below (0.4 x 6 x 25 m alone is
    60 m/s2) and speeds up at the limit."""
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=5.0)
    lead = b.actor("Car", "lead", start=lane(2, -1, 45.0), speed=10.0)
    return ego, lead


def test_a_stated_max_acceleration_limits_the_follow() -> None:
    b = builder()
    ego, lead = far_lead(b)
    follow = b.add("Follow", ego, target=lead, distance=15.0, maxAcceleration=1.0)
    b.chain(b.root, follow, b.end)
    run = simulate(b.scenario, Path(MAP))
    # 1 m/s2 for 2 s: 5 + 2 = 7 m/s (the language's 3 m/s2 would give 11).
    assert speed_at(run, 0, 2.0) == pytest.approx(7.0, abs=1e-9)


def test_a_stated_limit_is_held_to_the_actors_own_performance() -> None:
    b = builder()
    ego, lead = far_lead(b)
    ego.maxAcceleration = scm.Value(value=2.0)
    follow = b.add("Follow", ego, target=lead, distance=15.0, maxAcceleration=15.0)
    b.chain(b.root, follow, b.end)
    run = simulate(b.scenario, Path(MAP))
    # esmini truncates DynamicConstraints to the Vehicle's Performance: 2 m/s2, 9 m/s at 2 s.
    assert speed_at(run, 0, 2.0) == pytest.approx(9.0, abs=1e-9)


def test_an_acceleration_rate_lets_the_acceleration_grow_by_it() -> None:
    b = builder()
    ego, lead = far_lead(b)
    follow = b.add(
        "Follow", ego, target=lead, distance=15.0, maxAcceleration=3.0, maxAccelerationRate=1.0
    )
    b.chain(b.root, follow, b.end)
    run = simulate(b.scenario, Path(MAP))
    # Step k (of 0.05 s) accelerates by k x 0.05 x 1 m/s3; after 20 steps the speed gained is
    # 0.05 x 0.05 x (1 + ... + 20) = 0.0025 x 210 = 0.525 m/s (a continuous ramp: 0.5).
    assert speed_at(run, 0, 1.0) == pytest.approx(5.525, abs=1e-9)


def test_freespace_keeps_the_gap_between_the_boxes() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=12.0, length=4.0)
    lead = b.actor("Car", "lead", start=lane(2, -1, 45.0), speed=8.0, length=5.0)
    follow = b.add("Follow", ego, target=lead, distance=10.0, freespace=True)
    b.chain(b.root, follow, b.add("TimeElapsed", ego, duration=2.5), b.end)
    run = simulate(b.scenario, Path(MAP))
    # 10 m between the boxes is 10 + (4 + 5) / 2 = 14.5 m between the reference points, held
    # by 6.5 s (the lead reaches the end of its road, x = 109, at 6.875 s and stops there).
    gap = x_at(run, 1, 6.5) - x_at(run, 0, 6.5)
    assert gap == pytest.approx(14.5, abs=0.1)
    assert speed_at(run, 0, 6.5) == pytest.approx(8.0, abs=0.1)


def test_a_time_gap_is_kept_at_the_targets_speed() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 5.0), speed=12.0)
    lead = b.actor("Car", "lead", start=lane(2, -1, 45.0), speed=8.0)
    follow = b.add("Follow", ego, target=lead, timeGap=1.5)
    b.chain(b.root, follow, b.add("TimeElapsed", ego, duration=5.0), b.end)
    run = simulate(b.scenario, Path(MAP))
    # 1.5 s at the lead's 8 m/s: 12 m (the distance's default, 10 m, is not used), held by
    # 6.5 s, before the lead stops at the end of its road.
    gap = x_at(run, 1, 6.5) - x_at(run, 0, 6.5)
    assert gap == pytest.approx(12.0, abs=0.1)


def test_a_leading_displacement_keeps_the_actor_ahead_of_the_target() -> None:
    b = builder()
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 45.0), speed=8.0)
    other = b.actor("Car", "other", start=lane(2, -1, 30.0), speed=8.0)
    # 15 m ahead of the other now; the node wants 10 m ahead: it slows down until then.
    keep = b.add("Approach", ego, target=other, distance=10.0, displacement="leading")
    b.chain(b.root, keep, b.end)
    run = simulate(b.scenario, Path(MAP))
    assert run.node(keep.name).finished is not None
    ahead = run.states[0, -1, 0] - run.states[1, -1, 0]
    assert ahead == pytest.approx(10.0, abs=0.5)
    assert not run.pair("ego", "other").collision

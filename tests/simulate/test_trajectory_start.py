"""A FollowTrajectory that begins at its first waypoint (release 1.5, imported trajectories)
puts the actor there when it starts, as esmini does; one that does not goes on from where the
actor is. On the intersection map's east arm (lane -1 at y = -1.75), 0.05 s steps."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import REPO

from sceml.model.build import ScenarioBuilder, world
from sceml.simulate import simulate

MAP = str(REPO / "maps" / "intersection.xodr")


def x_after_one_second(from_first: bool) -> float:
    b = ScenarioBuilder("walk", map=MAP, level="concrete", max_duration=10.0)
    car = b.actor("Car", "car", ego=True, start=world(20.0, -1.75, h=0.0), speed=10.0)
    path = b.add(
        "FollowTrajectory",
        car,
        waypoints=[world(15.0, -1.75), world(60.0, -1.75)],
        fromFirstWaypoint=from_first,
    )
    b.chain(b.root, path, b.end)
    run = simulate(b.scenario, Path(MAP))
    at = int(np.argmin(np.abs(run.times - 1.0)))
    assert run.times[at] == pytest.approx(1.0)
    return float(run.states[0, at, 0])


def test_a_path_from_its_first_waypoint_puts_the_actor_there() -> None:
    # Back to x = 15 when it starts, then 10 m in the second: x = 25.
    assert x_after_one_second(True) == pytest.approx(25.0, abs=1e-6)


def test_a_path_from_the_actor_goes_on_from_where_it_is() -> None:
    # From x = 20 through x = 15 (5 m back) towards x = 60: 10 m along it, x = 15 + 5 = 20.
    assert x_after_one_second(False) == pytest.approx(20.0, abs=1e-6)

"""A lane change given in time (release 1.5's LaneChange.duration) on the project's
intersection map: the preview drives it over what the actor covers in that time at the speed
it starts with (east arm, road 2: lane -1's centre at y = -1.75, lane 1's at y = +1.75)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import REPO

from sceml.model.build import ScenarioBuilder, lane
from sceml.simulate import simulate

MAP = str(REPO / "maps" / "intersection.xodr")


def _one_change(speed: float, **given: float) -> tuple[object, str]:
    b = ScenarioBuilder("map", map=MAP, level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=lane(2, -1, 10.0), speed=speed)
    change = b.add("LaneChange", ego, direction="left", **given)
    b.chain(b.root, change, b.end)
    return simulate(b.scenario, Path(MAP)), str(change.name)


def _arc(length: float) -> float:
    """The length of y = 1.75 (1 - cos(pi x / length)) over `length` m, integrated here."""
    x = np.linspace(0.0, length, 20001)
    slope = 1.75 * np.pi / length * np.sin(np.pi * x / length)
    return float(np.sum(np.hypot(np.diff(x), np.diff(x) * (slope[1:] + slope[:-1]) / 2)))


def test_two_seconds_at_ten_metres_a_second_are_twenty_metres() -> None:
    run, name = _one_change(10.0, duration=2.0)
    # 2 s at 10 m/s: the path is 20 m along the road; the car drives the curve's 20.38 m at
    # 10 m/s, 2.04 s, so the step that passes its end ends at 2.05 s.
    assert _arc(20.0) == pytest.approx(20.38, abs=0.01)
    assert run.node(name).finished == pytest.approx(2.05)
    x_end, y_end, heading, _ = run.states[0, -1]
    assert (x_end, y_end) == pytest.approx((39.0 + 10 * (2.1 - _arc(20.0) / 10), 1.75), abs=0.02)
    assert heading == pytest.approx(0.0, abs=1e-6)


def test_the_same_time_at_half_the_speed_is_half_the_length() -> None:
    run, name = _one_change(5.0, duration=2.0)
    # 2 s at 5 m/s: 10 m along the road; its curve is 10.72 m long, 2.14 s at 5 m/s: the
    # step that passes it ends at 2.15 s (the steeper curve takes longer than the 2 s given,
    # the preview's approximation: the shape is kept in metres).
    assert _arc(10.0) == pytest.approx(10.72, abs=0.01)
    assert run.node(name).finished == pytest.approx(2.15)
    assert run.states[0, -1, 1] == pytest.approx(1.75, abs=0.02)

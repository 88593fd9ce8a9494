"""A node with maxRuns runs again each time its activation holds anew (issue 24, repeats).

Worked out by hand as in `test_hand_checked.py`: a flow costs one step of 0.05 s, a flow out of
the root or a wait none. The repeated node is a KeepVelocity, whose run lasts its duration whatever the
speed; the export cannot repeat one (SCEML-S014), the preview runs what the language means.
"""

from __future__ import annotations

import pytest

from sceml.model.build import ScenarioBuilder, world
from sceml.simulate import END_NODE, simulate


def repeated(runs: int) -> ScenarioBuilder:
    b = ScenarioBuilder("repeats", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    wait = b.add("TimeElapsed", ego, name="Wait", duration=2.0)
    keep = b.add("KeepVelocity", ego, name="Keep", duration=1.0, maxRuns=runs)
    b.chain(b.root, wait, keep, b.end)
    return b


def test_a_node_after_a_condition_runs_again_each_time_the_condition_holds_anew() -> None:
    run = simulate(repeated(3).scenario)
    # The wait holds at 2 s and starts Keep in that instant; Keep acts from the next step
    # (a player's action does too) and finishes 1 s later, at 3.05 s. The wait is checked
    # again from 3.05 s and holds at 5.05 s: Keep to 6.10 s; again 6.10 + 2 = 8.10 s, Keep to
    # 9.15 s. The end comes a step later.
    assert run.end_reason == END_NODE and run.end_time == pytest.approx(9.20)
    keep = run.node("Keep")
    assert keep.started == pytest.approx(2.0) and keep.finished == pytest.approx(9.15)
    assert run.node("Wait").finished == pytest.approx(8.10)


def test_one_run_is_the_default() -> None:
    # As above, once: Keep to 3.05 s, the end at 3.10 s.
    run = simulate(repeated(1).scenario)
    assert run.end_time == pytest.approx(3.10)


def test_a_node_after_a_maneuver_runs_again_in_the_next_step() -> None:
    b = ScenarioBuilder("repeats", level="concrete", max_duration=30.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    first = b.add("KeepVelocity", ego, name="First", duration=1.0)
    keep = b.add("KeepVelocity", ego, name="Keep", duration=1.0, maxRuns=2)
    b.chain(b.root, first, keep, b.end)
    run = simulate(b.scenario)
    # First 0.05-1.05 s; Keep 1.10-2.10 s, again from the next step 2.15-3.15 s; end 3.20 s.
    assert run.node("Keep").started == pytest.approx(1.10)
    assert run.node("Keep").finished == pytest.approx(3.15)
    assert run.end_time == pytest.approx(3.20)

"""The preview runs no controller: a controller node finishes in the step it starts, says so on
the timeline, and leaves the actor's motion as it was (no map, 0.05 s steps)."""

from __future__ import annotations

import pytest

from sceml.model.build import ScenarioBuilder, activation, controller, override, world
from sceml.simulate import simulate


def test_a_controller_change_finishes_at_once_and_changes_no_motion() -> None:
    b = ScenarioBuilder("ctl", level="concrete", max_duration=3.0)
    ego = b.actor(
        "Car",
        "ego",
        ego=True,
        start=world(0.0, 0.0, h=0.0),
        speed=10.0,
        controller=controller("ACCController", properties={"timeGap": "1.5"}),
        activation=activation(longitudinal=True),
    )
    wait = b.add("TimeElapsed", ego, duration=1.0)
    take_over = b.add("AssignController", ego, controller=controller("InteractiveController"))
    brake = b.add("OverrideController", ego, overrides=[override("brake", 1.0)])
    off = b.add("ActivateController", ego, longitudinal=False)
    b.chain(b.root, wait, take_over, brake, off, b.end)
    run = simulate(b.scenario)
    # The wait starts with the root (a flow out of it costs no step) and ends 1 s later;
    # written into the next event's trigger, it costs no step either (xosc.flows), and the
    # assignment it starts acts from the next step, as a player's action does (1.05 s). Each
    # controller node after it starts one flow after its predecessor and finishes in that
    # same step.
    starts = [run.node(str(n.name)).started for n in (take_over, brake, off)]
    assert starts == pytest.approx([1.0, 1.1, 1.15])
    finishes = [run.node(str(n.name)).finished for n in (take_over, brake, off)]
    assert finishes == pytest.approx([1.05, 1.1, 1.15])
    assert "runs no controller" in str(run.node(str(brake.name)).note)
    # A full brake the preview does not apply: the ego keeps 10 m/s to the end.
    # The end node follows one flow later.
    assert run.end_time == pytest.approx(1.2)
    speeds = run.states[run.actor_index("ego"), :, 3]
    assert speeds == pytest.approx([10.0] * len(speeds))

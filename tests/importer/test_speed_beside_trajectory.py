"""A speed change and a trajectory in one event run together (issue 24): a FollowTrajectory is
followed at the actor's speed, so it drives the path only (`sceml.model.axes`) and a speed change
may run beside it. files/pedestrian-crossing.xosc's Walk event sets the walker's speed to 1.5 m/s
(a step) and starts its crossing path: both start when the walker is shown, in the same step,
and the walker walks the path at 1.5 m/s from that step (0.075 m per 0.05 s step, by hand)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sceml.importer import import_file
from sceml.simulate import simulate
from sceml.validation import validate

FILE = Path(__file__).parent / "files" / "pedestrian-crossing.xosc"


def test_the_speed_change_and_the_path_start_together() -> None:
    scenario = import_file(FILE).scenario
    nodes = {n.name: n for n in scenario.nodes}
    assert [f.source.name for f in nodes["Walk"].incoming] == ["ShowWalker"]
    assert [f.source.name for f in nodes["Walk_2"].incoming] == ["ShowWalker"]
    assert (nodes["Walk"].eClass.name, nodes["Walk"].shape.name) == ("Accelerate", "step")
    assert nodes["Walk_2"].eClass.name == "FollowTrajectory"
    codes = [d.code for d in validate(scenario)]
    assert "SCEML-C001" not in codes


def test_the_preview_walks_the_path_at_the_new_speed() -> None:
    run = simulate(import_file(FILE).scenario, FILE)
    walk, path = run.node("Walk"), run.node("Walk_2")
    assert walk.started == path.started
    walker = run.actor_index("walker")
    k = int(np.argmin(abs(run.times - path.started)))
    # From the first vertex (-4.5, -14) towards (4.5, -14): 1.5 m/s along +x.
    xs = run.states[walker, k : k + 3, 0]
    assert list(np.diff(xs)) == pytest.approx([0.075, 0.075])
    assert list(run.states[walker, k : k + 3, 3]) == [1.5, 1.5, 1.5]

"""A player's run is checked against a Follow's goal only where the trace can say it: a gap
between reference points behind the target. A gap between the boxes, a time gap or a gap ahead
(release 1.5) needs what the trace does not hold, so that goal is not checked."""

from __future__ import annotations

import numpy as np
import pytest

from sceml.model.build import ScenarioBuilder, world
from sceml.players.goals import goal_problems
from sceml.players.record import PlayerRun, Trace


def trace(x: float) -> Trace:
    """An actor standing at (x, 0), facing east, for 2 s at 0.05 s steps."""
    times = np.arange(0.0, 2.0001, 0.05)
    ones = np.ones_like(times)
    return Trace(times, x * ones, 0 * ones, 0 * ones, 0 * ones, np.zeros(len(times), np.int64))


@pytest.mark.parametrize(
    ("settings", "checked"),
    (
        ({}, True),
        ({"freespace": True}, False),
        ({"timeGap": 1.0}, False),
        ({"displacement": "leading"}, False),
    ),
)
def test_a_follows_gap_is_checked_where_the_trace_can_say_it(
    settings: dict[str, object], checked: bool
) -> None:
    b = ScenarioBuilder("goal", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0))
    lead = b.actor("Car", "lead", start=world(30.0, 0.0))
    follow = b.add("Follow", ego, target=lead, distance=10.0, **settings)
    run = PlayerRun("esmini", step=0.05, traces={"ego": trace(0.0), "lead": trace(30.0)})
    # 30 m apart at the finish: far above 10 m and its slack, whatever the measure.
    found = goal_problems(follow, (0.0, 0.0), 1.0, run, None)
    assert bool(found) is checked

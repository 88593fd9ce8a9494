"""An actor whose box centre lies ahead of its reference point (Actor.boxCenterX, release 1.3):
the preview's gaps and its drawings take the box where it is, not centred on the states."""

from __future__ import annotations

import numpy as np
import pytest

from sceml.maps.positions import Located
from sceml.render.mapscene import ActorMark, Place
from sceml.simulate.metrics import pair_metrics
from sceml.simulate.run import ActorInfo


def _gap(ahead: float) -> float:
    # Both heading east, standing: the follower's reference point at x = 0, the lead's at 10;
    # boxes 4 m long, so 6 m apart when centred on the reference points.
    times = np.array([0.0, 0.05])
    follower = np.array([[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]])
    lead = np.array([[10.0, 0.0, 0.0, 0.0], [10.0, 0.0, 0.0, 0.0]])
    actors = (
        ActorInfo("follower", "Car", True, 4.0, 2.0, ahead),
        ActorInfo("lead", "Car", False, 4.0, 2.0),
    )
    (pair,) = pair_metrics(times, actors, np.stack([follower, lead]))
    return pair.min_distance


def test_the_gap_is_between_the_boxes_where_they_are() -> None:
    assert _gap(0.0) == pytest.approx(6.0)
    assert _gap(1.25) == pytest.approx(4.75)  # the follower's front 1.25 m further on


def test_the_map_draws_the_box_ahead_of_the_start() -> None:
    start = Located(10.0, 0.0, 0.0)
    mark = ActorMark("ego", "Car", True, 4.0, 2.0, Place(start, (start,)), ahead=1.25)
    xs = sorted({round(float(x), 6) for x, _ in mark.corners()})
    assert xs == [9.25, 13.25]

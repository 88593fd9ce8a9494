"""The preview's articulated follower (simulate/trailers.py): a trailer stays coupled at the
hitch, lines up behind a straight tower, and in a steady turn runs inside its tower's circle.

The turn's figure is the textbook off-tracking of a single-axle trailer: a hitch on a circle of
radius R pulls an axle c behind it onto the circle of radius sqrt(R² - c²) (the axle's velocity
points at the hitch, so hitch, axle and centre form a right angle at the axle): R = 20 m,
c = 7 m give 18.735 m.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from sceml.simulate.actors import Actor
from sceml.simulate.paths import Path, heading_path
from sceml.simulate.trailers import Coupling, couple, drag

DT = 0.05


def _actor(name: str, path: Path, speed: float) -> Actor:
    return Actor(name, "Truck", False, (5.0, 2.5), path, speed)


def _circle(radius: float) -> Path:
    angles = np.linspace(-math.pi / 2, 6 * math.pi, 4000)
    return Path(np.column_stack([radius * np.cos(angles), radius * np.sin(angles)]))


def _run(tower: Actor, trailer: Actor, link: Coupling, seconds: float) -> None:
    actors = {tower.name: tower, trailer.name: trailer}
    couple(actors, [link])
    for _ in range(round(seconds / DT)):
        tower.advance_to(tower.speed, DT)
        drag(actors, [link])


def test_a_trailer_starts_in_line_at_the_hitch_and_follows_straight() -> None:
    tower = _actor("Tractor", heading_path(10.0, 5.0, math.pi / 2), 8.0)
    trailer = _actor("Semi", heading_path(0.0, 0.0, 0.0), 0.0)
    link = Coupling("Tractor", "Semi", hitch=1.0, coupler=7.0)
    couple({"Tractor": tower, "Semi": trailer}, [link])
    assert (trailer.x, trailer.y) == pytest.approx((10.0, 5.0 + 1.0 - 7.0))
    assert trailer.heading == pytest.approx(math.pi / 2) and trailer.towed
    _run(tower, trailer, link, 3.0)
    assert (trailer.x, trailer.y) == pytest.approx((10.0, tower.y - 6.0))
    assert trailer.speed == 8.0


def test_in_a_steady_turn_the_trailer_runs_inside_the_tower() -> None:
    radius, coupler = 20.0, 7.0
    tower = _actor("Tractor", _circle(radius), 5.0)
    trailer = _actor("Semi", heading_path(0.0, 0.0, 0.0), 0.0)
    link = Coupling("Tractor", "Semi", hitch=0.0, coupler=coupler)
    _run(tower, trailer, link, 40.0)  # about 1.6 turns: settled
    assert math.hypot(trailer.x, trailer.y) == pytest.approx(
        math.sqrt(radius**2 - coupler**2), abs=0.05
    )
    # Still coupled: the axle is the coupler's length from the hitch.
    assert math.hypot(tower.x - trailer.x, tower.y - trailer.y) == pytest.approx(coupler)


def test_reversing_pushes_the_trailer_back_in_line() -> None:
    tower = _actor("Car", heading_path(50.0, 0.0, 0.0), -2.0)
    trailer = _actor("Car+", heading_path(0.0, 0.0, 0.0), 0.0)
    link = Coupling("Car", "Car+", hitch=-1.2, coupler=3.25)
    _run(tower, trailer, link, 2.0)
    assert tower.x == pytest.approx(46.0)
    assert (trailer.x, trailer.y, trailer.heading) == pytest.approx((46.0 - 4.45, 0.0, 0.0))
    assert trailer.speed == -2.0


def test_connecting_another_trailer_uncouples_the_first() -> None:
    # Release 1.5's ConnectTrailer, as esmini 3.6's ConnectTrailerAction: one trailer per hitch.
    from sceml.simulate.trailers import connect, disconnect

    tower = _actor("Tractor", heading_path(10.0, 0.0, 0.0), 8.0)
    first = _actor("First", heading_path(0.0, 0.0, 0.0), 0.0)
    second = _actor("Second", heading_path(3.0, 4.0, 0.0), 0.0)
    actors = {a.name: a for a in (tower, first, second)}
    links: list[Coupling] = []
    connect(actors, links, Coupling("Tractor", "First", hitch=-1.0, coupler=2.0), rolls_on=True)
    drag(actors, links)
    assert (first.x, first.y, first.speed) == pytest.approx((7.0, 0.0, 8.0))
    connect(actors, links, Coupling("Tractor", "Second", hitch=-1.0, coupler=2.0), rolls_on=True)
    assert [link.trailer for link in links] == ["Second"] and not first.towed and second.towed
    drag(actors, links)
    # Second, 4 m beside and 6 m behind the hitch at (9, 0), turns to face it: 2 m along the
    # line from (3, 4) to (9, 0), whose length is sqrt(52).
    along = 2.0 / math.sqrt(52.0)
    assert (second.x, second.y) == pytest.approx((9.0 - 6.0 * along, 4.0 * along))
    assert first.speed == 8.0  # uncoupled on a road, it rolls on
    assert disconnect(actors, links, "Tractor", rolls_on=False) == "Second"
    assert second.speed == 0.0 and links == []
    assert disconnect(actors, links, "Tractor", rolls_on=False) is None

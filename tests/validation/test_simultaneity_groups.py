"""C001's grouping of maneuvers (`_previous_in_group`) reads each maneuver's actor through its
holder and its axes once per class; it must group exactly as reading `referenceActor` and
`maneuver_axes` of every maneuver does, for every maneuver class, unset actors included."""

from __future__ import annotations

import random

import pytest
from pyecore.ecore import EObject

import scemlmodel as scm
from sceml.model import catalog
from sceml.model.axes import maneuver_axes
from sceml.validation.simultaneity import _previous_in_group, _sorted_axes

MANEUVERS = catalog.concrete_subclasses("Maneuver")


def _plainly(order: list[EObject]) -> tuple[dict[EObject, int], dict[EObject, list[object]]]:
    """The grouping as the docstring of `_previous_in_group` states it, read the usual way."""
    bit: dict[EObject, int] = {}
    previous: dict[EObject, list[object]] = {}
    last: dict[tuple[EObject, str], EObject] = {}
    for node in order:
        if not isinstance(node, scm.Maneuver) or node.referenceActor is None:
            continue
        for category in sorted(maneuver_axes(node)):
            key = (node.referenceActor, category)
            if key in last:
                previous.setdefault(node, []).append((last[key], category))
            last[key] = node
        bit[node] = len(bit)
    return bit, previous


def test_axes_per_class_checked_by_hand() -> None:
    # From the metamodel's categories: a composite drives both axes, FollowTrajectory the path
    # only, controller and light nodes neither.
    assert _sorted_axes(scm.Overtake()) == ("lateral", "longitudinal")
    assert _sorted_axes(scm.FollowTrajectory()) == ("lateral",)
    assert _sorted_axes(scm.Accelerate()) == ("longitudinal",)
    assert _sorted_axes(scm.LightState()) == ()
    for kind in MANEUVERS:
        assert _sorted_axes(kind()) == tuple(sorted(maneuver_axes(kind()))), kind.__name__


@pytest.mark.parametrize("seed", range(40))
def test_grouping_equals_plain_reads(seed: int) -> None:
    rng = random.Random(seed)
    actors = [scm.Car(name=f"car{i}") for i in range(rng.randint(1, 3))]
    order: list[EObject] = [scm.RootNode(name="root")]
    for i in range(rng.randint(1, 60)):
        roll = rng.random()
        if roll < 0.1:
            order.append(scm.JoinAllFinished(name=f"all{i}"))
            continue
        node = rng.choice(MANEUVERS)(name=f"m{i}")
        if roll < 0.9:  # the rest keep their actor unset: not grouped
            node.referenceActor = rng.choice(actors)
        order.append(node)
    bit, previous = _previous_in_group(order)
    assert (bit, previous) == _plainly(order)

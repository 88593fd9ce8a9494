"""Interrupting maneuvers and simultaneity (release 1.5): C001 accepts two maneuvers of one actor
and category that may overlap when one of them interrupts; `overlapping` finds every maneuver
that may overlap another (the ones the import marks), equal to a pairwise search with sets on
random graphs; and an edit of the flag re-runs C001 in incremental validation."""

from __future__ import annotations

from itertools import combinations

import pytest
from pyecore.ecore import EObject
from validation.test_simultaneity_sets import _random_graph

import scemlmodel as scm
from sceml.model.axes import maneuver_axes
from sceml.model.build import ScenarioBuilder, lane
from sceml.validation import validate
from sceml.validation.edits import Change
from sceml.validation.incremental import IncrementalValidator
from sceml.validation.simultaneity import _adjacency, conflicts, overlapping


def _pairwise(nodes: list[EObject], flows: list[tuple[EObject, EObject]]) -> set[EObject]:
    """Maneuvers unordered with another of their actor and category, pair by pair, with the
    ordered-after sets of the module docstring."""
    order, sources, _ = _adjacency(nodes, flows)
    after: dict[EObject, frozenset[EObject]] = {}
    for node in order:
        inputs = [after[source] for source in sources[node]]
        if isinstance(node, scm.JoinOneFinished) and len(inputs) > 1:
            ordered = frozenset.intersection(*inputs)
        else:
            ordered = frozenset().union(*inputs)
        if isinstance(node, scm.Maneuver) and node.referenceActor is not None:
            ordered |= {node}
        after[node] = ordered
    maneuvers = [n for n in order if isinstance(n, scm.Maneuver) and n.referenceActor is not None]
    found: set[EObject] = set()
    for a, b in combinations(maneuvers, 2):
        shared = maneuver_axes(a) & maneuver_axes(b)
        unordered = a not in after[b] and b not in after[a]
        if a.referenceActor is b.referenceActor and shared and unordered:
            found |= {a, b}
    return found


@pytest.mark.parametrize("seed", range(200))
def test_overlapping_finds_what_pairs_find(seed: int) -> None:
    nodes, flows = _random_graph(seed)
    assert overlapping(nodes, flows) == _pairwise(nodes, flows)


@pytest.mark.parametrize("seed", range(200))
def test_marking_the_overlapping_ones_leaves_no_conflict(seed: int) -> None:
    nodes, flows = _random_graph(seed)
    for node in overlapping(nodes, flows):
        node.interrupts = True
    assert conflicts(nodes, flows) == []


def _speed_up_and_brake() -> tuple[scm.Scenario, scm.Maneuver]:
    b = ScenarioBuilder("Brakes", map="../../maps/intersection.xodr", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0), speed=5.0)
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    brake = b.add("Decelerate", ego, targetSpeed=2.0)
    b.chain(b.root, speed_up)
    b.chain(b.root, b.add("TimeElapsed", ego, duration=2.0), brake)
    b.chain(b.join_all(speed_up, brake), b.end)
    return b.scenario, brake


def test_an_edit_of_the_flag_re_runs_simultaneity() -> None:
    scenario, brake = _speed_up_and_brake()
    checker = IncrementalValidator(scenario)
    assert "SCEML-C001" in {d.code for d in checker.validate()}
    brake.interrupts = True
    checker.note([Change(brake, "interrupts", False, True)])
    assert "SCEML-C001" not in {d.code for d in checker.validate()}
    assert {d.code for d in checker.validate()} == {d.code for d in validate(scenario)}

"""C001's conflicts, found with one bitset per node, equal those found with plain sets on random
graphs: forks, joins of both kinds, several actors and categories (for any change to how the
bitsets are numbered or stored)."""

from __future__ import annotations

import random

import pytest
from pyecore.ecore import EObject

import scemlmodel as scm
from sceml.validation.simultaneity import Conflict, _adjacency, _previous_in_group, conflicts

KINDS = (scm.Accelerate, scm.LaneChange, scm.Overtake, scm.KeepVelocity, scm.TurnLeft)


def _with_sets(nodes: list[EObject], flows: list[tuple[EObject, EObject]]) -> list[Conflict]:
    """The rule as the module docstring states it, with frozensets of maneuvers."""
    order, sources, _ = _adjacency(nodes, flows)
    _, previous = _previous_in_group(order)
    after: dict[EObject, frozenset[EObject]] = {}
    found: list[Conflict] = []
    reported: set[tuple[EObject, EObject]] = set()  # a pair once, in its first category
    for node in order:
        inputs = [after[source] for source in sources[node]]
        if isinstance(node, scm.JoinOneFinished) and len(inputs) > 1:
            ordered = frozenset.intersection(*inputs)
        else:
            ordered = frozenset().union(*inputs)
        if isinstance(node, scm.Maneuver) and node.referenceActor is not None:
            ordered |= {node}
        for earlier, category in previous.get(node, ()):
            if earlier not in ordered and (earlier, node) not in reported:
                reported.add((earlier, node))
                found.append((earlier, node, category))
        after[node] = ordered
    return found


def _random_graph(seed: int) -> tuple[list[EObject], list[tuple[EObject, EObject]]]:
    rng = random.Random(seed)
    actors = [scm.Car(name=f"car{i}") for i in range(rng.randint(1, 3))]
    nodes: list[EObject] = [scm.RootNode(name="root")]
    flows: list[tuple[EObject, EObject]] = []
    for i in range(rng.randint(2, 40)):
        roll = rng.random()
        if roll < 0.15:
            node: EObject = scm.JoinOneFinished(name=f"one{i}")
        elif roll < 0.3:
            node = scm.JoinAllFinished(name=f"all{i}")
        else:
            node = rng.choice(KINDS)(name=f"m{i}", referenceActor=rng.choice(actors))
        joins = isinstance(node, scm.JoinOneFinished | scm.JoinAllFinished)
        for source in rng.sample(nodes, min(len(nodes), rng.randint(2, 3) if joins else 1)):
            flows.append((source, node))
        nodes.append(node)
    # Kahn's order follows the list: shuffled, the root is not always first.
    rng.shuffle(nodes)
    return nodes, flows


@pytest.mark.parametrize("seed", range(300))
def test_bitsets_find_what_sets_find(seed: int) -> None:
    nodes, flows = _random_graph(seed)
    assert conflicts(nodes, flows) == _with_sets(nodes, flows)


def test_random_graphs_have_conflicts_to_find() -> None:
    # The comparison above means something only if the graphs have conflicts and orderings.
    found = [len(_with_sets(*_random_graph(seed))) for seed in range(300)]
    assert sum(1 for count in found if count) > 100
    assert sum(1 for count in found if not count) > 20

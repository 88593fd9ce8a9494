"""The adjacency S006-S008 and the departures share (`validation/adjacency.py`) answers what the
walks over pyecore's Flow objects answered: on random graphs with forks, cycles, dangling flows
and flows that wrongly join two graphs."""

from __future__ import annotations

import random
from collections import deque

import pytest
from pyecore.ecore import EObject

import scemlmodel as scm
from sceml.model.graph import predecessors, successors, topological_order
from sceml.validation.adjacency import OwnAdjacency, left_by_kahn, reached


def _walk(graph: scm.Graph, starts: list[EObject], backwards: bool) -> set[EObject]:
    """What S006 and S007 walked before: the nodes' own flows, neighbours kept in the graph."""
    members = set(graph.nodes)
    seen = set(starts)
    queue = deque(starts)
    while queue:
        node = queue.popleft()
        for flow in node.incoming if backwards else node.outgoing:
            neighbour = flow.source if backwards else flow.target
            if neighbour is not None and neighbour in members and neighbour not in seen:
                seen.add(neighbour)
                queue.append(neighbour)
    return seen


def _random_graphs(seed: int) -> tuple[scm.Scenario, scm.ModuleDefinition]:
    rng = random.Random(seed)
    scenario = scm.Scenario()
    other = scm.ModuleDefinition(name="m")
    for graph, prefix, count in ((scenario, "s", rng.randint(1, 30)), (other, "m", 5)):
        for i in range(count):
            graph.nodes.append(scm.Accelerate(name=f"{prefix}{i}"))
    nodes, foreign = list(scenario.nodes), list(other.nodes)
    for _ in range(rng.randint(0, 45)):
        roll = rng.random()
        source: EObject | None = rng.choice(nodes)
        target: EObject | None = rng.choice(nodes)  # cycles and self-loops included
        if roll < 0.08:
            source = None
        elif roll < 0.16:
            target = None
        elif roll < 0.22:
            target = rng.choice(foreign)  # a flow into another graph (S011's case)
        elif roll < 0.28:
            source = rng.choice(foreign)
        flow = scm.Flow(source=source, target=target)
        (other if roll < 0.25 and rng.random() < 0.3 else scenario).flows.append(flow)
    return scenario, other


@pytest.mark.parametrize("seed", range(300))
def test_the_shared_adjacency_answers_as_the_flow_walks(seed: int) -> None:
    scenario, other = _random_graphs(seed)
    adjacency = OwnAdjacency(scenario)
    nodes = list(scenario.nodes)
    assert list(adjacency.nodes) == nodes
    for node in [*nodes, *other.nodes]:  # a node of another graph is read from its flows
        assert adjacency.successors(node) == successors(node)
        assert adjacency.predecessors(node) == predecessors(node)
    rng = random.Random(seed)
    for backwards in (False, True):
        starts = rng.sample(nodes, rng.randint(1, min(3, len(nodes))))
        assert reached(adjacency, starts, backwards=backwards) == _walk(scenario, starts, backwards)
    assert left_by_kahn(adjacency) == topological_order(scenario)[1]


def test_a_cycle_is_left_over_and_a_chain_is_not() -> None:
    # By hand: a -> b -> c -> b and d alone; Kahn orders a and d, not b, c.
    scenario = scm.Scenario()
    a, b, c, d = (scm.Accelerate(name=n) for n in "abcd")
    scenario.nodes.extend([a, b, c, d])
    for source, target in ((a, b), (b, c), (c, b)):
        scenario.flows.append(scm.Flow(source=source, target=target))
    adjacency = OwnAdjacency(scenario)
    assert left_by_kahn(adjacency) == {b, c}
    assert reached(adjacency, [a], backwards=False) == {a, b, c}
    assert reached(adjacency, [c], backwards=True) == {a, b, c}

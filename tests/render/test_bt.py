"""The behavior-tree view: series-parallel reduction and what non-series-parallel graphs become."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.model.build import ScenarioBuilder
from sceml.model.loading import load
from sceml.render import RenderError, diagram, to_bytes
from sceml.render.bt import Leaf, Module, Parallel, Wait, tree_of

from .svgtools import groups, parse

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def kinds(items: list) -> list[str]:
    return [item.node.eClass.name for item in items]


def test_uis1_is_parallel_all_of_two_sequences_as_in_fig_treenot() -> None:
    tree = tree_of(load(EXAMPLES / "uis1-functional.xmi").root)
    assert tree.series_parallel and tree.left_out == []
    [parallel] = tree.items
    assert isinstance(parallel, Parallel) and parallel.policy == "all"
    ego, bike = parallel.children
    assert kinds(ego) == ["Accelerate", "TurnRight", "InLocationRadius"]
    assert kinds(bike) == ["InVehicleRadius", "Accelerate", "Cross", "InLocationRadius"]


def test_uis1_svg_has_one_parallel_all_and_two_sequences() -> None:
    svg = parse(to_bytes(diagram(load(EXAMPLES / "uis1-logical.xmi").root, view="bt"), "svg"))
    assert len(groups(svg, "sceml-bt-parallel-all")) == 1
    assert len(groups(svg, "sceml-bt-sequence")) == 2
    assert groups(svg, "sceml-bt-parallel-one") == []
    leaves = {c: len(groups(svg, f"sceml-{c}")) for c in ("longitudinal", "lateral", "condition")}
    assert leaves == {"longitudinal": 2, "lateral": 2, "condition": 3}


def test_uis2_expanded_puts_the_module_body_in_its_own_frame() -> None:
    tree = tree_of(load(EXAMPLES / "uis2-functional.xmi").root, "expanded")
    [parallel] = tree.items
    assert [kinds(c) if not isinstance(c[0], Module) else "module" for c in parallel.children] == [
        ["Accelerate", "TurnLeft", "InLocationRadius"],
        ["InLocationRadius", "DriveDistance"],
        "module",
    ]
    module = parallel.children[2][0]
    assert kinds(module.body) == ["InVehicleRadius", "Accelerate", "Cross", "InLocationRadius"]


def _scenario(end_policy: str = "joinAll") -> tuple[ScenarioBuilder, list[scm.ActionNode]]:
    b = ScenarioBuilder("T", map="Town03", level="functional")
    ego = b.actor("Car", "ego", ego=True)
    b.end.policy = scm.JoinPolicy.getEEnumLiteral(end_policy)
    nodes = [b.add("KeepVelocity", ego, name=name) for name in "ABCD"]
    return b, nodes


def test_partial_merge_nests_parallels_with_the_joins_policy() -> None:
    b, (a, bb, c, _) = _scenario("joinAll")
    b.chain(b.root, a)
    b.chain(b.root, bb)
    b.chain(b.root, c, b.end)
    first = b.join_one(a, bb)
    b.chain(first, b.end)
    b.scenario.nodes.remove(_)
    tree = tree_of(b.scenario)
    assert tree.series_parallel
    [outer] = tree.items
    assert outer.policy == "all"
    inner = outer.children[0][0]
    assert isinstance(inner, Parallel) and inner.policy == "one"
    assert [[leaf.node.name for leaf in child] for child in inner.children] == [["A"], ["B"]]
    assert [leaf.node.name for leaf in outer.children[1]] == ["C"]


def test_end_join_one_becomes_parallel_one() -> None:
    b, (a, bb, _, _) = _scenario("joinOne")
    b.chain(b.root, a, b.end)
    b.chain(b.root, bb, b.end)
    [parallel] = tree_of(b.scenario).items
    assert parallel.policy == "one"


def test_a_cross_linked_graph_gets_a_wait_leaf() -> None:
    # Root -> A, Root -> B; A -> C; A and B both feed join J -> D -> End; C -> End. The join J
    # has inputs from two branches that also go elsewhere: not series-parallel.
    b, (a, bb, c, d) = _scenario()
    b.chain(b.root, a, c, b.end)
    b.chain(b.root, bb)
    join = b.join_all(a, bb)
    b.chain(join, d, b.end)
    tree = tree_of(b.scenario)
    assert not tree.series_parallel
    leaves = _flatten(tree.items)
    waits = [item for item in leaves if isinstance(item, Wait)]
    assert len(waits) == 1 and {n.name for n in waits[0].on} == {"A", "B"}
    assert sorted(item.node.name for item in leaves if isinstance(item, Leaf)) == list("ABCD")
    svg = parse(to_bytes(diagram(b.scenario, view="bt"), "svg"))
    assert len(groups(svg, "sceml-bt-wait")) == 1


def _flatten(items: list) -> list:
    flat = []
    for item in items:
        if isinstance(item, Parallel):
            for child in item.children:
                flat += _flatten(child)
        else:
            flat.append(item)
    return flat


def test_a_cycle_is_refused() -> None:
    b, (a, bb, _, _) = _scenario()
    b.chain(b.root, a, bb, a)
    b.chain(bb, b.end)
    with pytest.raises(RenderError, match="acyclic"):
        tree_of(b.scenario)

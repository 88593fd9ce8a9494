"""The canonical form used to compare behaviour must itself see real differences."""

from __future__ import annotations

from pathlib import Path

from sceml.model.build import node_named
from sceml.model.loading import load
from sceml.model.params import value

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_equal_for_the_same_file_and_blind_to_names(canonical) -> None:
    first = load(EXAMPLES / "uis1-concrete.xmi").root
    second = load(EXAMPLES / "uis1-concrete.xmi").root
    node_named(second, "Cross_1").name = "renamed"
    assert canonical(first) == canonical(second)


def test_sees_a_changed_parameter_actor_and_predecessor(canonical) -> None:
    original = canonical(load(EXAMPLES / "uis1-concrete.xmi").root)

    changed = load(EXAMPLES / "uis1-concrete.xmi").root
    node_named(changed, "Cross_1").tolerance = value(2.5)
    assert canonical(changed) != original

    changed = load(EXAMPLES / "uis1-concrete.xmi").root
    ego = node_named(changed, "Accelerate_1").referenceActor
    node_named(changed, "Accelerate_2").referenceActor = ego
    assert canonical(changed) != original

    changed = load(EXAMPLES / "uis1-concrete.xmi").root
    flow = next(iter(node_named(changed, "Accelerate_2").incoming))
    flow.source = node_named(changed, "Root")
    assert canonical(changed) != original

"""sceml.model.copying.Copier's direct copies equal the copies pyecore's setters make (SetterCopier).

Whole models, partial copies whose references leave the copy, module definitions, proxies,
references set before `copy_references`, and flattening: the copies, the `copies` mapping and the
originals (whose opposite ends a copy may change) are compared object by object.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pyecore.ecore import EObject, EProxy
from strategies import scenarios

import scemlmodel as scm
from sceml.model.copying import Copier, SetterCopier, copy_tree
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.modules.flatten import FlattenError, flatten

from .model_state import difference, model_state, paths, value

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
FILES = sorted(
    [*EXAMPLES.rglob("*.xmi"), *(REPO / "tests" / "validation" / "corpus").rglob("*.xmi")]
)

Copying = Callable[[Copier, EObject], list[EObject]]


def whole(copier: Copier, root: EObject) -> list[EObject]:
    """The model and everything in it."""
    duplicate = copier.copy(root)
    copier.copy_references()
    return [duplicate]


def some_nodes_and_flows(copier: Copier, root: EObject) -> list[EObject]:
    """Every other node, and every other flow: references leave the copy (flows to nodes not
    copied, actors of the root node), so opposite ends of originals change."""
    graph = root if isinstance(root, scm.Scenario) else root.modules[0]
    nodes = copier.copy_all(list(graph.nodes)[::2])
    flows = copier.copy_all(list(graph.flows)[1::2])
    copier.copy_references()
    return [*nodes, *flows]


def definitions(copier: Copier, root: EObject) -> list[EObject]:
    """What flattening copies of a library: each definition's nodes and flows."""
    copied: list[EObject] = []
    for definition in getattr(root, "modules", []):
        copied += copier.copy_all(definition.nodes)
        copied += copier.copy_all(definition.flows)
    copier.copy_references()
    return copied


def compare(path: Path, copying: Copying) -> None:
    """Copy the model of `path` both ways; copies, mappings and originals must be the same."""
    states = []
    for make in (SetterCopier, Copier):
        document = load(path)
        copier = make()
        copies = copying(copier, document.root)
        roots = {"original": document.root, **{f"copy{i}": c for i, c in enumerate(copies)}}
        names = paths(roots)
        states.append(
            {
                # Reading a feature makes pyecore create its (empty) holder; the setter copier
                # reads every feature of the originals, the direct one only those it copies.
                "objects": model_state(roots, read_holders=False),
                "copies": [value(o, names) for o in copier.copies.values()],
                "originals": [value(o, names) for o in copier.copies],
            }
        )
    assert difference(*states) is None


@pytest.mark.parametrize("copying", [whole, some_nodes_and_flows, definitions])
@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_copies_are_the_same_both_ways(path: Path, copying: Copying) -> None:
    compare(path, copying)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.sampled_from(["functional", "logical", "concrete"]).flatmap(
        lambda level: scenarios(level, max_nodes=10)
    ),
    st.sampled_from([whole, some_nodes_and_flows]),
)
def test_random_scenarios_copy_the_same_both_ways(scenario: scm.Scenario, copying: Copying) -> None:
    states = []
    for make in (SetterCopier, Copier):
        copier = make()
        copies = copying(copier, scenario)
        state = model_state({f"copy{i}": c for i, c in enumerate(copies)})
        states.append(state)
        for duplicate in copies:  # leave the drawn scenario as it was for the other copier
            if isinstance(duplicate, scm.Flow):
                duplicate.source = duplicate.target = None
    assert difference(*states) is None


def test_proxies_resolved_or_not_and_references_set_before() -> None:
    def copied(make: type[Copier], resolve: bool) -> dict[str, Any]:
        document = load(EXAMPLES / "uis2-concrete.xmi")
        use = next(n for n in document.root.nodes if isinstance(n, scm.ModuleUse))
        if resolve:
            use.definition.force_resolve()
        copier = make()
        duplicate = copier.copy(document.root)
        # Set before copy_references: the setter must undo it, as pyecore's does.
        duplicate.flows[0].source = duplicate.nodes[1]
        copier.copy_references()
        copier.copy_references()  # twice: the second pass replaces what the first set
        definition = copier.copy(use.definition)  # a proxy copied itself
        copier.copy_references()
        assert (type(use.definition) is EProxy) is True
        return model_state({"copy": duplicate, "definition": definition})

    for resolve in (False, True):
        assert difference(copied(SetterCopier, resolve), copied(Copier, resolve)) is None


def test_flattening_gives_the_same_model_both_ways(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    for path in [p for p in FILES if p.parent == EXAMPLES]:
        results = []
        for direct in (False, True):
            monkeypatch.setattr(Copier, "direct", direct)
            try:
                flat: Any = flatten(load(path).root)
            except FlattenError as error:
                results.append(str(error))
                continue
            results.append(model_state({"flat": flat}))
            results.append(save(flat, tmp_path / f"{direct}.xmi", origin=path).read_bytes())
        assert difference(results[: len(results) // 2], results[len(results) // 2 :]) is None


def test_copy_tree_of_a_detached_value() -> None:
    value_ = scm.Range(min=1.0, max=2.0)
    holder = scm.ParameterOverride(parameter="speed", value=value_)
    copied = copy_tree(holder.value)
    assert copied is not value_ and copied.eContainer() is None
    assert (copied.min, copied.max, copied.step) == (1.0, 2.0, None)
    assert scm.Range.step not in copied._isset


def test_every_sceml_class_is_copied_directly() -> None:
    # Otherwise the comparisons above would compare pyecore with itself.
    from sceml.model.copying import _shape

    classes = [c for c in scm.eClassifiers.values() if isinstance(c, type)]
    assert all(_shape(cls).direct for cls in classes if not cls.eClass.abstract)

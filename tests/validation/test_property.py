"""Random edits to the valid examples never make validation raise or fail internally."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scemlmodel as scm
from sceml.model.loading import load
from sceml.validation import INTERNAL_ERROR, validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
FILES = [
    "uis1-concrete.xmi",
    "uis2-concrete.xmi",
    "uis2-logical.xmi",
    "uis2-functional.xmi",
    "library/sceml-library.xmi",
]
EDITS = (
    "drop_flow",
    "drop_node",
    "drop_parameter",
    "retarget_flow",
    "reverse_flow",
    "add_flow",
    "change_level",
    "reassign_actor",
    "set_number",
    "drop_binding",
)

edits = st.lists(
    st.tuples(st.sampled_from(EDITS), st.integers(0, 10_000), st.integers(0, 10_000)),
    max_size=6,
)
numbers = st.one_of(st.floats(-1e6, 1e6), st.just(0.0))


def pick(items: list, index: int) -> object | None:
    return items[index % len(items)] if items else None


def graphs(root: object) -> list[scm.Graph]:
    return list(root.modules) if isinstance(root, scm.Library) else [root]  # type: ignore[attr-defined]


def apply(root: object, edit: str, a: int, b: int, number: float) -> None:
    graph = pick(graphs(root), a)
    if graph is None:
        return
    nodes, flows = list(graph.nodes), list(graph.flows)
    contents = list(root.eAllContents())  # type: ignore[attr-defined]
    flow, node, other = pick(flows, a), pick(nodes, a), pick(nodes, b)
    if edit == "drop_flow" and flow is not None:
        graph.flows.remove(flow)
    elif edit == "drop_node" and node is not None:
        graph.nodes.remove(node)  # flows keep pointing at it: a broken model on purpose
    elif edit == "drop_parameter":
        value = pick([o for o in contents if isinstance(o, scm.ParameterValue)], a)
        if value is not None and value.eContainer() is not None:
            value.eContainer().eSet(value.eContainmentFeature(), None)
    elif edit == "retarget_flow" and flow is not None:
        flow.target = other
    elif edit == "reverse_flow" and flow is not None:
        flow.source, flow.target = flow.target, flow.source
    elif edit == "add_flow" and node is not None:
        graph.flows.append(scm.Flow(source=node, target=other))
    elif edit == "change_level":
        for holder in (o for o in contents if isinstance(o, scm.RootNode)):
            holder.level = list(scm.AbstractionLevel.eLiterals)[b % 3]
    elif edit == "reassign_actor":
        actor = pick([o for o in contents if isinstance(o, scm.Participant)], b)
        target = pick([o for o in contents if isinstance(o, scm.ActionNode)], a)
        if target is not None:
            target.eSet("targetActor" if b % 2 else "referenceActor", actor if a % 3 else None)
    elif edit == "set_number":
        value = pick([o for o in contents if isinstance(o, scm.Value | scm.Range)], a)
        if isinstance(value, scm.Value):
            value.value = number
        elif value is not None:
            value.min = number
    elif edit == "drop_binding":
        use = pick([o for o in contents if isinstance(o, scm.ModuleUse)], a)
        if use is not None and len(use.bindings):
            use.bindings.remove(use.bindings[b % len(use.bindings)])


@settings(
    max_examples=80,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(file=st.sampled_from(FILES), changes=edits, number=numbers)
def test_random_edits_never_crash_the_validator(
    file: str, changes: list[tuple[str, int, int]], number: float
) -> None:
    document = load(EXAMPLES / file)
    for edit, a, b in changes:
        apply(document.root, edit, a, b, number)
    found = validate(document.root, document=document)
    internal = [str(d) for d in found if d.code == INTERNAL_ERROR]
    assert internal == []

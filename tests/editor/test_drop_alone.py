"""A node dropped alone (issue 27): the incremental run patches the expansion it kept and runs
the scenario's rules, not every shape rule, and still equals a fresh full validation; every case
the shortcut must not take (a name the expansion chose, a node in a module definition, a use, a
reference out of the scenario, an undone drop) gives the full run's result too."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest
from editor.test_incremental import EXAMPLES, copied_examples, keyed
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scemlmodel as scm
from sceml.editor import EditorSession
from sceml.model.graph import root_node
from sceml.validation import context as context_module
from sceml.validation import validate
from sceml.validation.edits import Change, Impact, placed_alone
from sceml.validation.incremental import IncrementalValidator

Expansions = Callable[[], int]


@pytest.fixture
def expansions(monkeypatch: pytest.MonkeyPatch) -> Iterator[Expansions]:
    """How many times validation has expanded module uses since the test started."""
    calls = [0]
    real = context_module.expansion

    def counted(scenario: scm.Scenario) -> Any:
        calls[0] += 1
        return real(scenario)

    monkeypatch.setattr(context_module, "expansion", counted)
    yield lambda: calls[0]


def validator_of(session: EditorSession) -> tuple[IncrementalValidator, scm.Scenario]:
    """A validator of the session's model, past its first (full) run."""
    document = session.document
    assert document is not None
    validator = IncrementalValidator(document.root, document=document)
    validator.validate()
    return validator, document.root


def same_as_full(validator: IncrementalValidator) -> list[tuple[object, ...]]:
    """The incremental run's diagnostics, checked against a fresh full validation."""
    return expanding(validator, lambda: 0)[0]


def expanding(
    validator: IncrementalValidator, expansions: Expansions
) -> tuple[list[tuple[object, ...]], int]:
    """`same_as_full`, and how many times the incremental run expanded module uses."""
    before = expansions()
    found = keyed(validator.validate())
    expanded = expansions() - before
    assert found == keyed(validate(validator.model, document=validator.document))
    return found, expanded


def drop(validator: IncrementalValidator, graph: scm.Graph, node: scm.GraphElement) -> None:
    graph.nodes.append(node)
    validator.note([Change(graph, "nodes", None, node)])


def crosser(scenario: scm.Scenario) -> scm.Participant:
    """The actor UIS2's CrossingManeuver_1 binds to its crosser, who accelerates inside it."""
    use = next(node for node in scenario.nodes if isinstance(node, scm.ModuleUse))
    return next(b.actor for b in use.bindings if b.role == "crosser")


def ego(scenario: scm.Scenario) -> scm.Actor:
    root = root_node(scenario)
    assert root is not None
    return next(actor for actor in root.actors if actor.name == "ego")


def test_a_drop_in_the_editor_reuses_the_expansion(
    uis2: EditorSession, expansions: Expansions
) -> None:
    uis2.apply([{"op": "add_node", "kind": "Stop", "actor": "ego"}])  # expands once: kept
    before = expansions()
    uis2.apply([{"op": "add_node", "kind": "Decelerate", "actor": "ego"}])
    stats = uis2.validator.stats
    assert expansions() == before, "the kept expansion was patched, not made again"
    assert not stats.full and not stats.through_modules_run
    assert stats.checks_run < 40, stats  # the new node's rules and the scenario's
    found = keyed(uis2.diagnostics())
    assert found == keyed(validate(uis2.document.root, document=uis2.document))
    # Two maneuvers of ego with no flow ordering them: C001 reads the patched expansion.
    assert any(
        code == "SCEML-C001" and "'Decelerate_1'" in message for code, _, message, *_ in found
    )


def test_a_dropped_node_is_placed_where_the_full_expansion_puts_it(
    uis2: EditorSession, expansions: Expansions
) -> None:
    validator, scenario = validator_of(uis2)
    # Inserted before the use: the expansion lists it before the use's copies.
    node = scm.Accelerate(name="Early", referenceActor=crosser(scenario))
    scenario.nodes.insert(2, node)
    validator.note([Change(scenario, "nodes", None, node)])
    assert expanding(validator, expansions)[1] == 0
    assert not validator.stats.full


@pytest.mark.parametrize(
    "name", ["CrossingManeuver_1.Accelerate_1", "CrossingManeuver_1.Cross_1", "CrossingManeuver_1"]
)
def test_a_node_named_like_an_expanded_name_makes_the_expansion_again(
    uis2: EditorSession, expansions: Expansions, name: str
) -> None:
    validator, scenario = validator_of(uis2)
    # An Accelerate of the crosser with no flow runs beside the copied one: C001 names both.
    drop(validator, scenario, scm.Accelerate(name=name, referenceActor=crosser(scenario)))
    found, expanded = expanding(validator, expansions)
    assert expanded == 1
    if name.endswith("Accelerate_1"):  # the copy takes the next free name; C001 names it
        assert any(f"{name}~2" in str(message) for _, _, message, *_ in found), found


def test_an_unnamed_use_is_renamed_around_a_dropped_node(
    uis2: EditorSession, expansions: Expansions
) -> None:
    validator, scenario = validator_of(uis2)
    use = next(node for node in scenario.nodes if isinstance(node, scm.ModuleUse))
    use.name = None
    validator.forget()
    same_as_full(validator)
    # The unnamed use expanded as CrossingManeuver_1; a node of that name moves it to _2.
    alongside = crosser(scenario)
    drop(validator, scenario, scm.Accelerate(name="CrossingManeuver_1", referenceActor=alongside))
    found = same_as_full(validator)
    assert any("CrossingManeuver_2.Accelerate_1" in str(m) for _, _, m, *_ in found), found
    # A name the expansion did not choose changes nothing in it: patched.
    drop(validator, scenario, scm.Accelerate(name="CrossingManeuver_3", referenceActor=alongside))
    assert expanding(validator, expansions)[1] == 0


def test_a_node_dropped_into_a_module_definition_is_no_shortcut(
    uis2: EditorSession, expansions: Expansions
) -> None:
    validator, scenario = validator_of(uis2)
    use = next(node for node in scenario.nodes if isinstance(node, scm.ModuleUse))
    definition = use.definition
    role = definition.roles[0]
    drop(validator, definition, scm.Accelerate(name="Inner", referenceActor=role))
    found, expanded = expanding(validator, expansions)
    assert expanded == 1
    assert any("CrossingManeuver_1.Inner" in str(message) for _, _, message, *_ in found), found


def test_a_dropped_use_makes_the_expansion_again(
    uis2: EditorSession, expansions: Expansions
) -> None:
    uis2.apply([{"op": "add_node", "kind": "Stop", "actor": "ego"}])
    before = expansions()
    uis2.apply(
        [
            {
                "op": "add_module_use",
                "library": "library/sceml-library.xmi",
                "module": "CrossingManeuver",
                "bindings": {"crosser": "pedestrian", "trigger": "ego"},
            }
        ]
    )
    assert expansions() == before + 1
    assert uis2.validator.stats.through_modules_run
    assert keyed(uis2.diagnostics()) == keyed(validate(uis2.document.root, document=uis2.document))


def test_a_node_referring_out_of_the_scenario_is_no_shortcut(uis2: EditorSession) -> None:
    validator, scenario = validator_of(uis2)
    use = next(node for node in scenario.nodes if isinstance(node, scm.ModuleUse))
    role = use.definition.roles[0]  # a role of a library's module: expanding fails on it
    node = scm.Stop(name="Stray", referenceActor=role)
    assert placed_alone(Change(scenario, "nodes", None, node)) is None  # not in the scenario yet
    drop(validator, scenario, node)
    assert placed_alone(Change(scenario, "nodes", None, node)) is None
    found = same_as_full(validator)
    assert any(code == "SCEML-M017" for code, *_ in found), found


def test_an_undone_drop_and_a_drop_noted_twice(uis2: EditorSession) -> None:
    validator, scenario = validator_of(uis2)
    node = scm.Stop(name="Twice", referenceActor=ego(scenario))
    change = Change(scenario, "nodes", None, node)
    drop(validator, scenario, node)
    same_as_full(validator)
    # Undone: the same record, the node gone; then redone and undone again before a run.
    scenario.nodes.remove(node)
    validator.note([change])
    assert Impact([change]).alone == {}
    same_as_full(validator)
    scenario.nodes.append(node)
    validator.note([change, change])
    same_as_full(validator)
    assert [n for n in scenario.nodes if n is node] == [node]


def test_a_dropped_node_with_a_taken_name_and_a_join(uis2: EditorSession) -> None:
    validator, scenario = validator_of(uis2)
    drop(validator, scenario, scm.Stop(name="Accelerate_1", referenceActor=ego(scenario)))
    found = same_as_full(validator)
    assert any(code == "SCEML-S013" for code, *_ in found), found
    drop(validator, scenario, scm.JoinAllFinished(name="Join_9"))
    found = same_as_full(validator)
    assert any("'Join_9'" in str(message) for _, _, message, *_ in found), found


def test_a_drop_into_a_scenario_without_uses(uis1: EditorSession) -> None:
    validator, scenario = validator_of(uis1)
    drop(validator, scenario, scm.Stop(name="Alone", referenceActor=ego(scenario)))
    same_as_full(validator)
    drop(validator, scenario, scm.Cross(name="Alone2", referenceActor=ego(scenario)))
    same_as_full(validator)


def test_a_drop_undone_and_redone_elsewhere_takes_its_new_place(uis2: EditorSession) -> None:
    """A node whose insertion is undone and then made again at the end of the list: the kept
    expansion must list it where it is now, or C001 names the pair the other way round
    (hypothesis found it: two Accelerates of ego, both dropped at the second place)."""
    validator, scenario = validator_of(uis2)
    first = scm.Accelerate(name="CrossingManeuver_1", referenceActor=ego(scenario))
    second = scm.Accelerate(name="CrossingManeuver_2", referenceActor=ego(scenario))
    for node in (first, second):
        scenario.nodes.insert(1, node)
        validator.note([Change(scenario, "nodes", None, node)])
    same_as_full(validator)
    scenario.nodes.remove(second)
    validator.note([Change(scenario, "nodes", None, second)])
    scenario.nodes.append(second)
    validator.note([Change(scenario, "nodes", None, second)])
    found = same_as_full(validator)
    assert any(code == "SCEML-C001" for code, *_ in found), found


# --- random drops, adversarial names and places -------------------------------------------------

DROP_KINDS = ["Accelerate", "Stop", "Cross", "TimeElapsed", "JoinAllFinished"]
NAMES = [
    "CrossingManeuver_1",
    "CrossingManeuver_2",
    "CrossingManeuver_1.Accelerate_1",
    "CrossingManeuver_1.Cross_1",
    "CrossingManeuver_1.Accelerate_1~2",
    "Accelerate_1",
    "Fresh",
    None,
]


def random_step(data: st.DataObject, scenario: scm.Scenario, undo: list[Change]) -> list[Change]:
    """Drop a node (anywhere, named anything, into the scenario or the used module), undo the
    last drop, or redo it; the changes as the editor would note them."""
    use = next(node for node in scenario.nodes if isinstance(node, scm.ModuleUse))
    move = data.draw(st.sampled_from(["drop", "drop", "drop", "undo", "redo"]))
    if move in ("undo", "redo") and undo:
        change = undo[-1]
        graph, node = change.owner, change.new
        if node in graph.nodes:
            graph.nodes.remove(node)
        else:
            graph.nodes.append(node)
        return [change]
    into_module = data.draw(st.integers(0, 5)) == 0
    graph = use.definition if into_module else scenario
    kind = data.draw(st.sampled_from(DROP_KINDS))
    node = getattr(scm, kind)(name=data.draw(st.sampled_from(NAMES)))
    if isinstance(node, scm.ActionNode) and kind != "TimeElapsed":
        performers = (
            list(use.definition.roles) if into_module else [ego(scenario), crosser(scenario)]
        )
        if data.draw(st.integers(0, 7)) == 0:  # a role of the module, from the scenario
            performers = list(use.definition.roles)
        node.referenceActor = data.draw(st.sampled_from(performers))
    graph.nodes.insert(data.draw(st.integers(0, len(graph.nodes))), node)
    change = Change(graph, "nodes", None, node)
    undo.append(change)
    return [change]


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.data(), unnamed=st.booleans(), steps=st.integers(1, 10))
def test_random_drops_equal_a_full_run(data: st.DataObject, unnamed: bool, steps: int) -> None:
    with copied_examples() as folder:
        session = EditorSession()
        session.open(folder / "uis2-concrete.xmi")
        validator, scenario = validator_of(session)
        if unnamed:
            next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse)).name = None
            validator.forget()
            same_as_full(validator)
        undo: list[Change] = []
        for _ in range(steps):
            validator.note(random_step(data, scenario, undo))
            if data.draw(st.booleans()):  # sometimes several edits before one run
                same_as_full(validator)
        same_as_full(validator)

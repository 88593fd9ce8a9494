"""Property tests with the editor's own operations (sceml.editor): what a diff lists and a merge joins.

- A random edit sequence applied in the editor: the diff of the file before and the file after
  lists exactly the changes the editor's views show (modulo changes that cancel out), as
  (action, path) pairs worked out from the two views, not from the diff's own reading.
- Two edit sequences on disjoint parts of one base merge to what applying both in one session
  gives.
- Two sequences that set one parameter to different values are reported as a conflict there.
"""

from __future__ import annotations

import re
import shutil
import tempfile
from collections import Counter
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import scemlmodel as scm
from sceml.diff import Change, compare_files
from sceml.diff.merge import merge
from sceml.editor import EditorSession, OperationError
from sceml.model.compare import differences
from sceml.model.loading import load_scenario
from sceml.model.saving import save

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
MAPS = EXAMPLES.parent / "maps"
BASE = "uis1-logical.xmi"

NUMBER = st.integers(0, 40).map(float)
PARAMETER = st.one_of(
    st.none(),
    st.builds(lambda v: {"type": "value", "value": v}, NUMBER),
    st.builds(lambda a: {"type": "range", "min": a, "max": a + 5, "step": None}, NUMBER),
    st.builds(lambda a: {"type": "uniform", "min": a, "max": a + 2}, NUMBER),
)
#: A destination or location: a world position (x, y, maybe a heading) or a lane position.
PLACE = st.one_of(
    st.builds(
        lambda x, y, h: {"type": "world", "x": x, "y": y, "z": None, "h": h},
        PARAMETER.filter(lambda v: v is not None),
        PARAMETER.filter(lambda v: v is not None),
        PARAMETER,
    ),
    st.builds(
        lambda road, s: {"type": "lane", "roadId": road, "laneId": 1, "s": s, "offset": None},
        st.sampled_from(["1", "2", "3"]),
        PARAMETER.filter(lambda v: v is not None),
    ),
)
POSITION = st.builds(lambda x, y: {"x": x, "y": y}, NUMBER, NUMBER)
SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@contextmanager
def copied_examples() -> Iterator[Path]:
    """A private copy of examples/ with the map beside it, for one hypothesis example."""
    with tempfile.TemporaryDirectory() as folder:
        shutil.copytree(EXAMPLES, Path(folder) / "examples", ignore=shutil.ignore_patterns("*.py"))
        shutil.copytree(MAPS, Path(folder) / "maps", ignore=shutil.ignore_patterns("*.py"))
        yield Path(folder) / "examples"


def top_nodes(view: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {n["id"]: n for n in view["nodes"] if n["parent"] is None}


def parameters(entry: dict[str, Any]) -> dict[str, Any]:
    return {f["name"]: f["value"] for f in entry["fields"] if f["type"] == "parameter"}


def values(entry: dict[str, Any]) -> dict[str, Any]:
    """The fields a test edits: parameters and positions."""
    return {
        f["name"]: f["value"] for f in entry["fields"] if f["type"] in ("parameter", "position")
    }


def field_of(change: Change) -> tuple[str, str]:
    """(action, path) with a changed leaf cut to the field it is in: a position is one field of
    the editor's panel but several leaves of the diff (`destination.x`, `destination.y`)."""
    if change.action != "changed":
        return change.action, change.path
    inside = change.path[len(change.element) + 1 :]
    field = re.split(r"[.\[]", inside)[0]
    return "changed", f"{change.element}.{field}"


# What the views say changed --------------------------------------------------------------------


def expected_changes(before: dict[str, Any], after: dict[str, Any]) -> Counter[tuple[str, str]]:
    """(action, path) of every change, read off the editor's views before and after."""
    found: Counter[tuple[str, str]] = Counter()
    old, new = top_nodes(before), top_nodes(after)
    for node_id, entry in old.items():
        if node_id not in new:
            found["removed", entry["name"]] += 1
    for node_id, entry in new.items():
        if node_id not in old:
            found["added", entry["name"]] += 1
            continue
        was = old[node_id]
        if was["name"] != entry["name"]:
            found["renamed", entry["name"]] += 1
        held, holds = values(was), values(entry)
        for field in held.keys() | holds.keys():
            if held.get(field) != holds.get(field):
                found["changed", f"{entry['name']}.{field}"] += 1
        if was["position"] != entry["position"]:
            found["moved", entry["name"]] += 1
    old_actors = {a["id"]: a for a in before["actors"]}
    for entry in after["actors"]:
        was = old_actors[entry["id"]]
        held, holds = parameters(was), parameters(entry)
        for field in held.keys() | holds.keys():
            if held.get(field) != holds.get(field):
                found["changed", f"{entry['name']}.{field}"] += 1
    found.update(_flow_changes(before, after, old, new))
    return found


def _flow_changes(
    before: dict[str, Any], after: dict[str, Any], old: dict[str, Any], new: dict[str, Any]
) -> Counter[tuple[str, str]]:
    def name(node_id: str) -> str:
        return str((new.get(node_id) or old[node_id])["name"])

    def pairs(view: dict[str, Any], nodes: dict[str, Any]) -> Counter[tuple[str, str]]:
        return Counter(
            (e["source"], e["target"])
            for e in view["edges"]
            if e["source"] in nodes and e["target"] in nodes
        )

    was, now = pairs(before, old), pairs(after, new)
    found: Counter[tuple[str, str]] = Counter()
    for (source, target), count in (was - now).items():
        found["removed", f"{name(source)} -> {name(target)}"] += count
    for (source, target), count in (now - was).items():
        found["added", f"{name(source)} -> {name(target)}"] += count
    return found


# Random edits ----------------------------------------------------------------------------------


class Editing:
    """Draws operations over what the view shows now; keeps renamed nodes recognisable.

    A rename is recognised by the node's kind, actor, parameters and neighbours; a node renamed
    and then stripped of most of them is, rightly, a removal and an addition. So a renamed node,
    and its neighbours, get no other edit than a move in the same sequence, and a node whose
    values were edited is not renamed.
    """

    ADDED_KINDS = ("Stop", "TimeElapsed", "LaneChange")  # none of them is in UIS1

    def __init__(self, data: st.DataObject, session: EditorSession, view: dict[str, Any]):
        self.data, self.session, self.view = data, session, view
        self.frozen: set[str] = set()
        self.edited: set[str] = set()
        self.renames = 0

    def step(self) -> None:
        op = self.data.draw(st.one_of(self.choices()))
        try:
            self.view = self.session.apply([op])
        except OperationError:
            return
        if op["op"] in ("set_parameter", "set_position"):
            self.edited.add(op["node"])
        if op["op"] == "set" and op["field"] == "name":
            node = op["node"]
            self.frozen.add(node)
            for edge in self.view["edges"]:
                if node in (edge["source"], edge["target"]):
                    self.frozen.update((edge["source"], edge["target"]))

    def choices(self) -> list[st.SearchStrategy[dict[str, Any]]]:
        nodes = top_nodes(self.view)
        free = [i for i, n in nodes.items() if i not in self.frozen]
        actions = [i for i in free if parameters(nodes[i]) and nodes[i]["kind"] != "RootNode"]
        names = [a["name"] for a in self.view["actors"]]
        actors = [a["id"] for a in self.view["actors"]]
        edges = [
            e["id"] for e in self.view["edges"] if not {e["source"], e["target"]} & self.frozen
        ]
        found = [
            st.builds(
                lambda n, p: {"op": "move", "positions": {n: p}},
                st.sampled_from(list(nodes)),
                POSITION,
            ),
            st.builds(
                lambda k, a: {"op": "add_node", "kind": k, "actor": a},
                st.sampled_from(self.ADDED_KINDS),
                st.sampled_from(names),
            ),
            st.builds(
                lambda a, v: {
                    "op": "set_actor_parameter",
                    "actor": a,
                    "field": "initialSpeed",
                    "value": v,
                },
                st.sampled_from(actors),
                PARAMETER,
            ),
        ]
        if free:
            found.append(
                st.builds(
                    lambda s, t: {"op": "connect", "source": s, "target": t},
                    st.sampled_from(free),
                    st.sampled_from(free),
                )
            )
            found.append(st.builds(lambda n: {"op": "delete", "nodes": [n]}, st.sampled_from(free)))
        if edges:
            found.append(
                st.builds(lambda e: {"op": "delete", "edges": [e]}, st.sampled_from(edges))
            )
        placed = [i for i in free if any(f["type"] == "position" for f in nodes[i]["fields"])]
        if placed:
            found.append(self.position_op(nodes, placed))
        if actions:
            found.append(self.parameter_op(nodes, actions))
            renamable = [i for i in actions if i not in self.edited]
            if renamable:
                found.append(self.rename_op(renamable))
        return found

    def parameter_op(
        self, nodes: dict[str, Any], actions: list[str]
    ) -> st.SearchStrategy[dict[str, Any]]:
        @st.composite
        def draw(draw_: st.DrawFn) -> dict[str, Any]:
            node = draw_(st.sampled_from(actions))
            field = draw_(st.sampled_from(sorted(parameters(nodes[node]))))
            value = draw_(PARAMETER)
            return {"op": "set_parameter", "node": node, "field": field, "value": value}

        return draw()

    def position_op(
        self, nodes: dict[str, Any], placed: list[str]
    ) -> st.SearchStrategy[dict[str, Any]]:
        @st.composite
        def draw(draw_: st.DrawFn) -> dict[str, Any]:
            node = draw_(st.sampled_from(placed))
            fields = [f["name"] for f in nodes[node]["fields"] if f["type"] == "position"]
            value = draw_(st.one_of(st.none(), PLACE))
            return {"op": "set_position", "node": node, "field": fields[0], "value": value}

        return draw()

    def rename_op(self, actions: list[str]) -> st.SearchStrategy[dict[str, Any]]:
        self.renames += 1
        name = f"Renamed_{self.renames}"
        return st.builds(
            lambda n: {"op": "set", "node": n, "field": "name", "value": name},
            st.sampled_from(actions),
        )


@pytest.mark.parametrize("example", [BASE, "uis2-logical.xmi"])  # UIS2: with a module use
@SETTINGS
@given(data=st.data(), length=st.integers(1, 10))
def test_the_diff_lists_exactly_the_edits(example: str, data: st.DataObject, length: int) -> None:
    with copied_examples() as folder:
        base = folder / example
        session = EditorSession()
        before = session.open(base)
        editing = Editing(data, session, before)
        for _ in range(length):
            editing.step()
        edited = folder / "edited.xmi"
        after = session.save(edited)
        changes = compare_files(base, edited).changes
        whole = [(c.action, c.path) for c in changes if c.action != "changed"]
        assert len(whole) == len(set(whole))  # each element and flow once
        assert {field_of(c) for c in changes} == set(expected_changes(before, after))


# Merges ----------------------------------------------------------------------------------------

#: One side's edits, by node and actor names, so that the same edits apply in another session.
Plan = list[tuple[Any, ...]]


def plan(data: st.DataObject, nodes: list[str], actor: str, kind: str) -> Plan:
    """Edits of the nodes `nodes` and the actor `actor` only; added nodes are of `kind`."""
    steps: Plan = []
    for _ in range(data.draw(st.integers(1, 6))):
        what = data.draw(
            st.sampled_from(["parameter", "position", "move", "delete", "add", "actor"])
        )
        node = data.draw(st.sampled_from(nodes))
        if what == "parameter":
            steps.append(("parameter", node, data.draw(PARAMETER)))
        elif what == "position":
            steps.append(("position", node, data.draw(PLACE)))
        elif what == "move":
            steps.append(("move", node, data.draw(POSITION)))
        elif what == "delete":
            steps.append(("delete", node))
        elif what == "add":
            steps.append(("add", kind, node))
        else:
            steps.append(("actor", actor, data.draw(PARAMETER)))
    return steps


def apply_plan(session: EditorSession, steps: Plan) -> None:
    """Apply a plan by names; an edit the editor refuses (a node already deleted) is skipped."""
    for step in steps:
        view = session.view()
        ids = {n["name"]: i for i, n in top_nodes(view).items()}
        actors = {a["name"]: a["id"] for a in view["actors"]}
        what = step[0]
        if what != "actor" and step[-1 if what == "add" else 1] not in ids:
            continue
        if what == "parameter":
            node = ids[step[1]]
            field = sorted(parameters(top_nodes(view)[node]))[0]
            session.apply([{"op": "set_parameter", "node": node, "field": field, "value": step[2]}])
        elif what == "position":
            node = top_nodes(view)[ids[step[1]]]
            fields = [f["name"] for f in node["fields"] if f["type"] == "position"]
            if fields:
                op = {"op": "set_position", "node": ids[step[1]], "field": fields[0]}
                session.apply([{**op, "value": step[2]}])
        elif what == "move":
            session.apply([{"op": "move", "positions": {ids[step[1]]: step[2]}}])
        elif what == "delete":
            session.apply([{"op": "delete", "nodes": [ids[step[1]]]}])
        elif what == "add":
            made = session.apply([{"op": "add_node", "kind": step[1]}])["created"][0]
            session.apply([{"op": "connect", "source": ids[step[2]], "target": made}])
        else:
            op = {"op": "set_actor_parameter", "actor": actors[step[1]], "field": "initialSpeed"}
            session.apply([{**op, "value": step[2]}])


def edited_copy(base: Path, name: str, *plans: Plan) -> Path:
    session = EditorSession()
    session.open(base)
    for steps in plans:
        apply_plan(session, steps)
    target = base.with_name(name)
    session.save(target)
    return target


def loaded(path: Path) -> scm.Scenario:
    root = load_scenario(path).root
    assert isinstance(root, scm.Scenario)
    return root


def flows_in_order(scenario: scm.Scenario) -> scm.Scenario:
    """The same scenario with its flows sorted by end names (a merge appends theirs' last)."""
    flows = sorted(scenario.flows, key=lambda f: (str(f.source.name), str(f.target.name)))
    scenario.flows.clear()
    scenario.flows.extend(flows)
    return scenario


def split(data: st.DataObject, base: Path) -> tuple[list[str], list[str]]:
    session = EditorSession()
    nodes = [n["name"] for n in top_nodes(session.open(base)).values() if parameters(n)]
    nodes = [n for n in nodes if n != "Root"]
    ours = data.draw(
        st.lists(st.sampled_from(nodes), min_size=1, max_size=len(nodes) - 1, unique=True)
    )
    return ours, [n for n in nodes if n not in ours]


@SETTINGS
@given(data=st.data())
def test_independent_edits_merge_to_both_applied(data: st.DataObject) -> None:
    with copied_examples() as folder:
        base = folder / BASE
        mine, others = split(data, base)
        ours_plan = plan(data, mine, "ego", "Stop")
        theirs_plan = plan(data, others, "bike", "TimeElapsed")
        ours = edited_copy(base, "ours.xmi", ours_plan)
        theirs = edited_copy(base, "theirs.xmi", theirs_plan)
        both = edited_copy(base, "both.xmi", ours_plan, theirs_plan)
        # Random edits may break rules on either side; here only the joining is under test.
        result = merge(loaded(base), loaded(ours), loaded(theirs), validate=False)
        assert result.conflicts == []
        merged = save(result.scenario, base.with_name("merged.xmi"))
        assert differences(flows_in_order(loaded(merged)), flows_in_order(loaded(both))) == []


@SETTINGS
# Above every value UIS1 holds, so each side's value is a change.
@given(
    data=st.data(),
    values=st.lists(st.integers(100, 140).map(float), min_size=2, max_size=2, unique=True),
)
def test_two_values_for_one_parameter_are_a_conflict(
    data: st.DataObject, values: list[float]
) -> None:
    with copied_examples() as folder:
        base = folder / BASE
        mine, others = split(data, base)
        target = data.draw(st.sampled_from(mine))
        ours_plan = [("parameter", target, {"type": "value", "value": values[0]})]
        ours_plan += [
            s for s in plan(data, mine, "ego", "Stop") if s[0] not in ("delete", "parameter")
        ]
        theirs_plan = [("parameter", target, {"type": "value", "value": values[1]})]
        theirs_plan += plan(data, others, "bike", "TimeElapsed")
        ours = edited_copy(base, "ours.xmi", ours_plan)
        theirs = edited_copy(base, "theirs.xmi", theirs_plan)
        result = merge(loaded(base), loaded(ours), loaded(theirs), validate=False)
        assert not result.ok
        assert [c.reason for c in result.conflicts if c.path.startswith(f"{target}.")] == [
            "changed differently"
        ]

"""Random edit sequences: undo-all gives back the bytes before, redo-all the bytes after."""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path
from typing import Any

from editor.helpers import saved_bytes
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sceml.editor import EditorSession, OperationError
from sceml.editor.view import NodeCache

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
KINDS = ["Accelerate", "Stop", "LaneChange", "TimeElapsed", "JoinAllFinished", "Cross"]
SPEED = st.one_of(
    st.none(),
    st.builds(lambda v: {"type": "value", "value": v}, st.floats(0, 40)),
    st.builds(lambda a: {"type": "range", "min": a, "max": a + 5, "step": None}, st.floats(0, 30)),
)


def draw_op(data: st.DataObject, view: dict) -> dict[str, Any]:
    """One operation over the nodes, edges and actors the view shows now."""
    nodes = [n["id"] for n in view["nodes"] if n["parent"] is None]
    actions = [n["id"] for n in view["nodes"] if n["kind"] in KINDS and n["parent"] is None]
    actors = [a["id"] for a in view["actors"]]
    names = [a["name"] for a in view["actors"]]
    choices: list[st.SearchStrategy[dict[str, Any]]] = [
        st.builds(
            lambda k, a: {"op": "add_node", "kind": k, "actor": a},
            st.sampled_from(KINDS),
            st.sampled_from([None, *names]),
        ),
        st.builds(
            lambda s, t: {"op": "connect", "source": s, "target": t},
            st.sampled_from(nodes),
            st.sampled_from(nodes),
        ),
        st.builds(lambda n: {"op": "delete", "nodes": [n]}, st.sampled_from(nodes)),
        st.builds(
            lambda n, x: {"op": "move", "positions": {n: {"x": x, "y": 1.0}}},
            st.sampled_from(nodes),
            st.floats(-500, 500),
        ),
        st.builds(
            lambda k: {"op": "add_actor", "kind": k},
            st.sampled_from(["Car", "Bicycle", "Pedestrian"]),
        ),
    ]
    if view["edges"]:
        edges = [e["id"] for e in view["edges"] if "/" not in e["id"]]
        choices.append(st.builds(lambda e: {"op": "delete", "edges": [e]}, st.sampled_from(edges)))
    if actors:
        choices.append(
            st.builds(lambda a: {"op": "remove_actor", "actor": a}, st.sampled_from(actors))
        )
        choices.append(
            st.builds(
                lambda a, k: {"op": "set_actor", "actor": a, "field": "kind", "value": k},
                st.sampled_from(actors),
                st.sampled_from(["Van", "Motorcycle", "Pedestrian"]),
            )
        )
    if actions:
        choices.append(
            st.builds(
                lambda n, v: {"op": "set_parameter", "node": n, "field": "targetSpeed", "value": v},
                st.sampled_from(actions),
                SPEED,
            )
        )
    return data.draw(st.one_of(choices))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), requests=st.integers(1, 8))
def test_undo_all_and_redo_all_give_the_same_bytes(data: st.DataObject, requests: int) -> None:
    with tempfile.TemporaryDirectory() as folder:
        shutil.copytree(EXAMPLES, Path(folder) / "examples", ignore=shutil.ignore_patterns("*.py"))
        session = EditorSession()
        view = session.open(Path(folder) / "examples" / "uis2-concrete.xmi")
        before = saved_bytes(session)
        steps = 0
        for _ in range(requests):
            ops = [draw_op(data, view) for _ in range(data.draw(st.integers(1, 3)))]
            try:
                view = session.apply(ops)
                steps += 1
            except OperationError:
                view = session.view()  # refused as a whole: nothing stays applied
        after = saved_bytes(session)
        for _ in range(steps):
            session.undo()
        assert saved_bytes(session) == before
        assert not session.view()["dirty"]
        for _ in range(steps):
            session.redo()
        assert saved_bytes(session) == after


def fresh_view(session: EditorSession) -> dict[str, Any]:
    """The view listed from scratch, every node and actor anew (what the cache must equal)."""
    kept = session._cache
    session._cache = NodeCache()
    try:
        return session.view()
    finally:
        session._cache = kept


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), requests=st.integers(1, 8))
def test_the_view_after_any_edit_equals_one_listed_from_scratch(
    data: st.DataObject, requests: int
) -> None:
    with tempfile.TemporaryDirectory() as folder:
        shutil.copytree(EXAMPLES, Path(folder) / "examples", ignore=shutil.ignore_patterns("*.py"))
        session = EditorSession()
        view = session.open(Path(folder) / "examples" / "uis2-concrete.xmi")
        for _ in range(requests):
            move = data.draw(st.sampled_from(["ops", "ops", "rename actor", "undo", "redo"]))
            try:
                if move == "undo":
                    view = session.undo()
                elif move == "redo":
                    view = session.redo()
                elif move == "rename actor" and view["actors"]:
                    actor = data.draw(st.sampled_from(view["actors"]))["id"]
                    rename = {"op": "set_actor", "actor": actor, "field": "name", "value": "x9"}
                    view = session.apply([rename])
                else:
                    view = session.apply([draw_op(data, view)])
            except OperationError:
                view = session.view()
            fresh = fresh_view(session)
            assert view["nodes"] == fresh["nodes"]
            assert view["actors"] == fresh["actors"]

"""The command stack: one request is one step, a failing request leaves nothing, dirty tracking."""

from __future__ import annotations

import pytest
from editor.helpers import node_id, saved_bytes

from sceml.editor import EditorSession, OperationError
from sceml.editor.changes import Recorder
from sceml.editor.commands import CommandStack


def test_one_request_is_one_undo_step_with_its_label(uis1: EditorSession) -> None:
    view = uis1.apply(
        [{"op": "add_node", "kind": "Stop"}, {"op": "add_node", "kind": "Stop"}], "Two stops"
    )
    assert view["undo"] == "Two stops" and len(view["created"]) == 2
    undone = uis1.undo()
    assert not any(n["kind"] == "Stop" for n in undone["nodes"])
    assert undone["undo"] is None and undone["redo"] == "Two stops"


def test_default_labels_name_what_was_done(uis1: EditorSession) -> None:
    assert uis1.apply([{"op": "add_node", "kind": "Stop"}])["undo"] == "Add Stop"
    assert uis1.apply([{"op": "add_actor", "kind": "Car"}])["undo"] == "Add actor"


def test_a_failing_op_rolls_back_the_ones_before_it(uis1: EditorSession) -> None:
    before = saved_bytes(uis1)
    version = uis1.view()["version"]
    turn = node_id(uis1.view(), "TurnRight_1")
    with pytest.raises(OperationError):
        uis1.apply(
            [
                {"op": "add_node", "kind": "Stop"},
                {"op": "delete", "nodes": [turn]},
                {"op": "connect", "source": "n999", "target": turn},
            ]
        )
    assert saved_bytes(uis1) == before
    view = uis1.view()
    assert view["undo"] is None and not view["dirty"] and view["version"] == version


def test_a_new_edit_clears_redo(uis1: EditorSession) -> None:
    uis1.apply([{"op": "add_node", "kind": "Stop"}])
    uis1.undo()
    assert uis1.apply([{"op": "add_actor", "kind": "Van"}])["redo"] is None


def test_dirty_is_relative_to_the_save_point(uis1: EditorSession) -> None:
    assert not uis1.view()["dirty"]
    assert uis1.apply([{"op": "add_node", "kind": "Stop"}])["dirty"]
    assert not uis1.undo()["dirty"]
    assert uis1.redo()["dirty"]
    assert not uis1.save()["dirty"]
    assert uis1.undo()["dirty"]  # the saved file has the Stop
    assert not uis1.redo()["dirty"]
    uis1.undo()
    assert uis1.apply([{"op": "add_actor", "kind": "Van"}])["dirty"]


def test_undo_and_redo_with_nothing_to_do_change_nothing(uis1: EditorSession) -> None:
    version = uis1.view()["version"]
    assert uis1.undo()["version"] == version
    assert uis1.redo()["version"] == version


def test_every_change_bumps_the_version(uis1: EditorSession) -> None:
    first = uis1.view()["version"]
    second = uis1.apply([{"op": "add_node", "kind": "Stop"}])["version"]
    third = uis1.undo()["version"]
    fourth = uis1.save()["version"]
    assert first < second < third < fourth


def test_stack_without_a_session() -> None:
    stack = CommandStack()
    touched: list[str] = []

    def edit(recorder: Recorder) -> str:
        touched.append("ran")
        return "result"

    assert stack.run("Nothing", edit) == "result"
    assert stack.undo_label is None, "a step that changed nothing is not recorded"
    assert not stack.dirty and touched == ["ran"]

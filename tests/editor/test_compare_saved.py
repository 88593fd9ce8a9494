"""The editor compares the open scenario with its saved file in `sceml diff`'s terms (issue 29)."""

from __future__ import annotations

import pytest
from editor.helpers import node_id

from sceml.editor import EditorSession
from sceml.editor.errors import OperationError


def test_marks_and_lines_follow_the_edits_until_saved(uis2: EditorSession) -> None:
    view = uis2.compare(True)
    assert view["comparison"] == {
        "against": "uis2-concrete.xmi",
        "saved": True,
        "changes": [],
        "removed": [],
    }
    assert not any("mark" in node for node in view["nodes"])
    accelerate = node_id(view, "Accelerate_1")
    view = uis2.apply(
        [
            {
                "op": "set_parameter",
                "node": accelerate,
                "field": "targetSpeed",
                "value": {"type": "value", "value": 9},
            }
        ]
    )
    marks = {node["name"]: node.get("mark") for node in view["nodes"] if node.get("mark")}
    assert marks == {"Accelerate_1": "changed"}
    assert view["comparison"]["changes"] == ["~ Accelerate_1.targetSpeed: 7 -> 9 m/s"]
    view = uis2.apply([{"op": "delete", "nodes": [node_id(view, "DriveDistance_1")]}])
    assert "DriveDistance_1" in view["comparison"]["removed"]
    view = uis2.save()
    assert view["comparison"]["changes"] == [] and view["comparison"]["removed"] == []
    view = uis2.compare(False)
    assert "comparison" not in view


def test_a_module_definition_is_not_compared(uis2: EditorSession) -> None:
    view = uis2.view()
    uis2.open_definition(node_id(view, "CrossingManeuver_1"))
    with pytest.raises(OperationError, match="works on scenarios"):
        uis2.compare(True)

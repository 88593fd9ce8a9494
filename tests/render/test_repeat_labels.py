"""A node that runs more than once says so on its box, and the editor edits the count."""

from __future__ import annotations

import pytest

import scemlmodel as scm
from sceml.editor.errors import OperationError
from sceml.editor.fields import feature_field
from sceml.editor.node_ops import attribute_value
from sceml.model.build import ScenarioBuilder, world
from sceml.render.labels import Scope, action_lines


def test_max_runs_is_a_line_only_above_one() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    once = b.add("KeepVelocity", ego, duration=2.0)
    thrice = b.add("KeepVelocity", ego, duration=2.0, maxRuns=3)
    assert action_lines(once, Scope()) == ["ego", "duration: 2 s"]
    assert action_lines(thrice, Scope()) == ["ego", "duration: 2 s", "maxRuns: 3"]
    opaque = scm.OpaqueAction(
        name="Kept", xml="<Action><PrivateAction/></Action>", sourceLine=7, sourceVersion="1.1"
    )
    opaque.maxRuns = 2
    assert action_lines(opaque, Scope())[-1] == "maxRuns: 2"


def test_the_editor_offers_and_sets_max_runs() -> None:
    node = scm.KeepVelocity(name="Keep")
    feature = node.eClass.findEStructuralFeature("maxRuns")
    assert feature_field(node, feature) == {
        "name": "maxRuns",
        "label": "Max runs",
        "type": "text",
        "value": 1,
    }
    assert attribute_value(feature, "4") == 4
    with pytest.raises(OperationError, match="whole number"):
        attribute_value(feature, "often")

"""The `${...}` evaluator reads OpenSCENARIO's expression grammar and never runs Python."""

from __future__ import annotations

import pytest

import scemlmodel as scm
from sceml.validation import validate
from sceml.xosc.expressions import ExpressionError, evaluate, text_of

VALUES = {"a": "2", "b": "3.5", "name": "car"}


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("1 + 2 * 3", 7.0),
        ("(1 + 2) * 3", 9.0),
        ("-$a + $b", 1.5),
        ("$b / $a", 1.75),
        ("7 % 4", 3.0),
        ("max($a, $b) - min(1, 0.5)", 3.0),
        ("pow($a, 3) + sqrt(16) + abs(-1) + sign(-3)", 12.0),
        ("round(2.5) + floor(1.9) + ceil(1.1)", 6.0),
        ("$a == 2 and not ($b < 1 or false)", 1.0),
        ("1e2 / 4", 25.0),
    ],
)
def test_expressions(text: str, value: float) -> None:
    assert evaluate(text, VALUES) == pytest.approx(value)


@pytest.mark.parametrize(
    "text",
    ["__import__('os')", "$missing + 1", "$name * 2", "1 / 0", "(1 + 2", "1 +", "open"],
)
def test_what_cannot_be_read_is_refused(text: str) -> None:
    with pytest.raises(ExpressionError):
        evaluate(text, VALUES)


def test_whole_numbers_are_written_without_a_fraction() -> None:
    assert (text_of(30.0), text_of(2.5)) == ("30", "2.5")


def test_a_broken_opaque_node_is_a_validation_error() -> None:
    from sceml.model.build import ScenarioBuilder, world

    builder = ScenarioBuilder("x", map="Town01", level="concrete")
    ego = builder.actor("Car", "ego", ego=True, start=world(0, 0))
    kept = scm.OpaqueAction(name="kept", xml="<Event/>", sourceLine=3, sourceVersion="1.3")
    kept.referenceActor = ego
    builder.scenario.nodes.append(kept)
    builder.chain(builder.root, kept, builder.end)
    codes = {d.code for d in validate(builder.scenario)}
    assert "SCEML-E006" in codes
    kept.xml = '<Action name="a"><PrivateAction><VisibilityAction graphics="true" traffic="true" sensors="true"/></PrivateAction></Action>'
    assert "SCEML-E006" not in {d.code for d in validate(builder.scenario)}

"""Facts about parameters live in the metamodel's annotations and are read through the catalog."""

from __future__ import annotations

import pytest

from sceml.model import catalog
from sceml.model.build import ScenarioBuilder, lane
from sceml.validation import validate

KINDS = [c.__name__ for c in (*catalog.action_node_kinds(), *catalog.actor_kinds())]


def test_signs_and_limits_come_from_the_annotations() -> None:
    assert catalog.sign("Overtake", "gap") == catalog.POSITIVE
    assert catalog.sign("Car", "length") == catalog.POSITIVE
    assert catalog.sign("LanePosition", "s") == catalog.NON_NEGATIVE
    assert catalog.sign("LanePosition", "offset") is None
    assert catalog.sign("ParameterOverride", "value") is None
    assert catalog.limited("Stop", "max_deceleration") == ("rate",)
    assert catalog.limited("Accelerate", "max_acceleration") == ("rate",)
    assert catalog.limited("Bus", "max_speed") == ("initialSpeed",)
    assert "Actor" in catalog.limited_kinds()


#: Speeds that may be negative, driving backwards (release 1.4): a target, the speed a
#: condition compares, the initial speed; OpenSCENARIO's SpeedAction and SpeedCondition are signed.
SIGNED_SPEEDS = {
    ("Accelerate", "targetSpeed"),
    ("Decelerate", "targetSpeed"),
    ("SpeedCondition", "speed"),
    *((kind, "initialSpeed") for kind in (c.__name__ for c in catalog.actor_kinds())),
}


@pytest.mark.parametrize("kind", KINDS)
def test_every_speed_has_its_sign_and_is_bounded_by_max_speed(kind: str) -> None:
    for spec in catalog.parameters(kind):
        if spec.unit == "m/s":
            sign = catalog.SIGNED if (kind, spec.name) in SIGNED_SPEEDS else catalog.NON_NEGATIVE
            assert (spec.sign, spec.limit) == (sign, "max_speed"), spec


@pytest.mark.parametrize("feature", ["rate", "gap"])
def test_zero_is_refused_where_the_annotation_says_positive(feature: str) -> None:
    # levels/checks.py once let rate and gap be zero while the validator refused them.
    b = ScenarioBuilder("T", map="town.xodr", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0))
    other = b.actor("Car", "other", start=lane(1, -1, 40.0))
    if feature == "gap":
        node = b.add("Overtake", ego, target=other, gap=0.0)
    else:
        node = b.add("Accelerate", ego, targetSpeed=5.0, rate=0.0)
    b.chain(b.root, node, b.end)
    assert "SCEML-P007" in {d.code for d in validate(b.scenario)}

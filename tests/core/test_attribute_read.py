"""sceml.model.traversal.single_value reads what pyecore's descriptor reads, without making holders."""

from __future__ import annotations

import pytest
from pyecore.ecore import EObject

import scemlmodel as scm
from sceml.model.traversal import features, single_value

CONCRETE = sorted(
    (c for c in scm.eClassifiers.values() if isinstance(c, type) and not c.eClass.abstract),
    key=lambda cls: cls.__name__,
)


def _single_features(cls: type[EObject]) -> list[str]:
    return [f.name for f in features(cls.eClass) if not f.many]


@pytest.mark.parametrize("cls", CONCRETE, ids=lambda cls: cls.__name__)
def test_an_unset_feature_reads_its_default_and_stays_unset(cls: type[EObject]) -> None:
    for name in _single_features(cls):
        untouched, read = cls(), cls()
        assert single_value(untouched, name) == getattr(read, name), name
        assert name not in untouched.__dict__, name
        assert not untouched._isset


def test_a_set_attribute_reads_its_value() -> None:
    node = scm.Accelerate(name="A", maxRuns=3)
    assert single_value(node, "maxRuns") == 3
    assert single_value(node, "name") == "A"
    node.maxRuns = 0
    assert single_value(node, "maxRuns") == 0
    # A feature read once (pyecore made its holder with the default) reads the same.
    other = scm.KeepVelocity()
    assert other.maxRuns == 1
    assert single_value(other, "maxRuns") == 1


def test_the_default_is_the_metamodels() -> None:
    # Checked by hand against metamodel/scemlmodel.ecore: ActionNode.maxRuns defaults to 1,
    # EndNode.policy to joinAll.
    assert single_value(scm.Decelerate(), "maxRuns") == 1
    assert single_value(scm.EndNode(), "policy") is scm.JoinPolicy.joinAll


def test_a_set_reference_reads_its_target() -> None:
    actor = scm.Car(name="ego")
    node = scm.Follow(name="F", referenceActor=actor)
    assert single_value(node, "referenceActor") is actor
    assert single_value(node, "targetActor") is None
    assert "targetActor" not in node.__dict__


def test_a_many_valued_feature_is_refused() -> None:
    with pytest.raises(TypeError, match="waypoints"):
        single_value(scm.FollowTrajectory(), "waypoints")

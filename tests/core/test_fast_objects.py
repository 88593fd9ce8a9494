"""sceml.model.fastobjects leaves exactly the state pyecore's own constructors and setters leave."""

from __future__ import annotations

from typing import Any

import pytest
from pyecore.ecore import EObject, EProxy

import scemlmodel as scm
from sceml.model import fastobjects
from sceml.model.fastobjects import add_child, new, set_reference, set_value, slot

from .model_state import difference, model_state

CONCRETE = sorted(
    (c for c in scm.eClassifiers.values() if isinstance(c, type) and not c.eClass.abstract),
    key=lambda cls: cls.__name__,
)


@pytest.mark.parametrize("cls", CONCRETE, ids=lambda cls: cls.__name__)
def test_new_object_has_the_state_of_the_constructor(cls: type[EObject]) -> None:
    made, built = cls(), new(cls)
    assert type(built) is cls
    assert list(built.__dict__) == list(made.__dict__)
    for name, value in made.__dict__.items():
        if name == "dyn_inst":
            assert built.__dict__[name] is built
        else:
            assert built.__dict__[name] == value
            assert type(built.__dict__[name]) is type(value)
    assert built in EObject._instances


def _pair(build: Any) -> None:
    """Build the same objects twice, through pyecore (`fast=False`) and directly; compare."""
    slow, fast = build(False), build(True)
    assert difference(model_state({"r": slow}), model_state({"r": fast})) is None


def test_attributes_and_none_values() -> None:
    def build(fast: bool) -> EObject:
        node = new(scm.RootNode) if fast else scm.RootNode()
        values = [("name", "Root"), ("level", scm.AbstractionLevel.concrete), ("author", None)]
        for name, value in values:
            feature = scm.RootNode.eClass.findEStructuralFeature(name)
            if fast:
                set_value(node, slot(feature), value)
            else:
                node.eSet(feature, value)
        return node

    _pair(build)


def test_containments_single_and_many() -> None:
    def build(fast: bool) -> EObject:
        root = scm.RootNode()
        actors = [scm.Car(name="a"), scm.Pedestrian(name="b")]
        duration = scm.Value(value=3.0)
        if fast:
            for actor in actors:
                add_child(root, slot(scm.RootNode.actors), actor)
            add_child(root, slot(scm.RootNode.maxDuration), duration)
            set_value(root, slot(scm.RootNode.environment), None)
        else:
            root.actors.extend(actors)
            root.maxDuration = duration
            root.environment = None
        return root

    _pair(build)


def test_references_with_and_without_an_opposite_and_to_a_proxy() -> None:
    def build(fast: bool) -> EObject:
        scenario = scm.Scenario()
        start, end = scm.RootNode(name="Root"), scm.EndNode(name="End")
        use = scm.ModuleUse(name="Use")
        actor = scm.Car(name="ego")
        start.actors.append(actor)
        scenario.nodes.extend([start, end, use])
        flows = [scm.Flow(), scm.Flow()]
        scenario.flows.extend(flows)
        step = scm.Accelerate(name="Go")
        scenario.nodes.append(step)
        proxy = EProxy(path="library.xmi#Module", resource=None)
        links = [
            (flows[0], scm.Flow.source, start),
            (flows[0], scm.Flow.target, use),
            (flows[1], scm.Flow.source, use),
            (flows[1], scm.Flow.target, end),
            (step, scm.ActionNode.referenceActor, actor),
            (use, scm.ModuleUse.definition, proxy),
        ]
        for holder, feature, target in links:
            if fast:
                set_reference(holder, slot(feature), target)
            else:
                holder.eSet(feature, target)
        return scenario

    _pair(build)


def test_the_supported_shapes_are_those_of_sceml() -> None:
    assert fastobjects.reference_supported(scm.Flow.source)
    assert fastobjects.reference_supported(scm.ModuleUse.definition)
    assert not fastobjects.reference_supported(scm.GraphElement.outgoing)  # many, transient
    assert fastobjects.child_supported(scm.Graph.nodes)
    assert not fastobjects.child_supported(scm.Flow.source)
    assert fastobjects.attribute_supported(scm.Value.value)
    assert not fastobjects.attribute_supported(scm.Graph.nodes)

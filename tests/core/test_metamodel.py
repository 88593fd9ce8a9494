"""The .ecore avoids every known pyecore/EMF trap and says what the rest of SceML relies on."""

from __future__ import annotations

from pathlib import Path

import pytest
from pyecore.ecore import EAttribute, EClass, EEnum, EReference
from pyecore.resources import URI, ResourceSet

from sceml.model import catalog

ECORE = Path(__file__).resolve().parents[2] / "metamodel" / "scemlmodel.ecore"


@pytest.fixture(scope="module")
def package():
    return ResourceSet().get_resource(URI(str(ECORE))).contents[0]


def classes(package) -> list[EClass]:
    return [c for c in package.eClassifiers if isinstance(c, EClass)]


def test_package_has_prefix_and_is_not_called_sceml(package) -> None:
    # Without nsPrefix pyecore writes xsi:type="None:..."; "sceml" would shadow src/sceml.
    assert package.nsPrefix == "scemlmodel"
    assert package.name != "sceml"
    assert package.nsURI.startswith("https://")


def test_enum_literals_equal_their_names(package) -> None:
    # pyecore writes a literal's name, EMF its literal: they must agree.
    for enum in (c for c in package.eClassifiers if isinstance(c, EEnum)):
        for literal in enum.eLiterals:
            assert literal.literal == literal.name, f"{enum.name}.{literal.name}"


def test_every_opposite_is_declared_on_both_ends(package) -> None:
    opposites = 0
    for eclass in classes(package):
        for reference in eclass.eReferences:
            if reference.eOpposite is not None:
                opposites += 1
                assert reference.eOpposite.eOpposite is reference, f"{eclass.name}.{reference.name}"
    assert opposites == 4  # Flow.source/target <-> GraphElement.outgoing/incoming


def test_no_many_valued_attributes(package) -> None:
    # pyecore writes an empty many-valued attribute as "EOrderedSet()", which nothing reads back.
    for eclass in classes(package):
        for attribute in eclass.eAttributes:
            assert not attribute.many, f"{eclass.name}.{attribute.name}"


def test_no_edate_attributes(package) -> None:
    for eclass in classes(package):
        for attribute in eclass.eAttributes:
            assert attribute.eType.name != "EDate", f"{eclass.name}.{attribute.name}"


def test_defaults_use_default_value_literal(package) -> None:
    import scemlmodel as scm

    with_default = 0
    for eclass in classes(package):
        for attribute in eclass.eAttributes:
            if attribute.defaultValueLiteral is None:
                continue
            with_default += 1
            generated = getattr(scm, eclass.name)
            literal = generated.eClass.findEStructuralFeature(attribute.name).get_default_value()
            text = literal.name if hasattr(literal, "name") else str(literal).lower()
            assert text == attribute.defaultValueLiteral, f"{eclass.name}.{attribute.name}"
    assert with_default >= 8


def test_spec_concepts_exist(package) -> None:
    names = {c.name for c in package.eClassifiers}
    expected = {
        "Scenario",
        "RootNode",
        "EndNode",
        "GraphElement",
        "ModuleElement",
        "ActionNode",
        "Maneuver",
        "Condition",
        "JoiningPolicy",
        "JoinAllFinished",
        "JoinOneFinished",
        "Accelerate",
        "Decelerate",
        "Stop",
        "KeepVelocity",
        "DriveDistance",
        "Follow",
        "Approach",
        "LaneChange",
        "TurnLeft",
        "TurnRight",
        "Cross",
        "FollowTrajectory",
        "Overtake",
        "InLocationRadius",
        "InVehicleRadius",
        "TimeElapsed",
        "SpeedCondition",
        "TimeToCollision",
        "Actor",
        "Pedestrian",
        "TwoWheeler",
        "Bicycle",
        "Motorcycle",
        "FourWheeler",
        "Car",
        "Van",
        "Truck",
        "Bus",
        "WorldPosition",
        "LanePosition",
        "Environment",
        "Value",
        "Range",
        "UniformDistribution",
        "NormalDistribution",
        "DiscreteDistribution",
        "ModuleDefinition",
        "ModuleUse",
        "InPort",
        "OutPort",
        "ActorRole",
        "RoleBinding",
        "ParameterOverride",
        "Library",
        "AbstractionLevel",
    }
    assert expected <= names


def test_every_action_kind_has_category_complexity_and_typed_parameters() -> None:
    # OpaqueAction (what `sceml import` keeps verbatim) is no paper kind: category "opaque".
    kinds = [k for k in catalog.action_node_kinds() if k.__name__ != "OpaqueAction"]
    assert len(kinds) == 36
    assert catalog.category("OpaqueAction") == "opaque"
    for kind in kinds:
        assert catalog.category(kind) in catalog.CATEGORIES, kind
        assert catalog.complexity(kind) in (1, 2, 3), kind
        for spec in catalog.parameters(kind):
            assert spec.unit, f"{kind.__name__}.{spec.name} has no unit"


def test_global_kinds_are_performed_by_no_actor() -> None:
    performed_by_none = {
        k.__name__ for k in catalog.action_node_kinds() if not catalog.performed_by_actor(k)
    }
    assert performed_by_none == {
        "ParameterCondition",
        "VariableCondition",
        "SetParameter",
        "SetVariable",
        "TrafficSignalState",
        "TrafficSignalCondition",
    }
    assert catalog.category("SetParameter") == "global"
    assert catalog.category("ParameterCondition") == "condition"


def test_categories_follow_the_paper() -> None:
    assert catalog.category("Accelerate") == "longitudinal"
    assert catalog.category("LaneChange") == "lateral"
    assert catalog.category("TurnRight") == "lateral"
    assert catalog.category("Overtake") == "composite"
    assert catalog.category("InVehicleRadius") == "condition"
    assert catalog.category("ActivateController") == "controller"
    assert catalog.category("OverrideController") == "controller"
    assert catalog.category("ConnectTrailer") == "coupling"
    assert catalog.category("DisconnectTrailer") == "coupling"
    assert catalog.category("JoinAllFinished") is None


def test_target_actor_kinds() -> None:
    needing = {k.__name__ for k in catalog.action_node_kinds() if catalog.needs_target(k)}
    assert needing == {
        "Follow",
        "Approach",
        "MatchSpeed",
        "Overtake",
        "InVehicleRadius",
        "TimeToCollision",
        "TimeHeadway",
        "ConnectTrailer",
    }


def test_language_defaults_and_required_parameters() -> None:
    assert catalog.parameter("Accelerate", "rate").default == 2.0
    assert catalog.parameter("Accelerate", "targetSpeed").required
    assert not catalog.parameter("InVehicleRadius", "radius").required
    assert catalog.parameter("Car", "length").per_actor_default
    assert catalog.actor_dimensions("Car") == {"length": 4.5, "width": 1.8, "height": 1.5}
    assert catalog.actor_dimensions("Pedestrian")["height"] == 1.8


def test_references_between_files_are_single_valued(package) -> None:
    # EMF writes a many-valued reference that mixes same-file and other-file targets as
    # href="#/1", which pyecore cannot resolve; only ModuleUse.definition crosses files.
    use = next(c for c in classes(package) if c.name == "ModuleUse")
    definition = use.findEStructuralFeature("definition")
    assert isinstance(definition, EReference) and not definition.many
    assert isinstance(
        next(c for c in classes(package) if c.name == "ModuleDefinition").findEStructuralFeature(
            "name"
        ),
        EAttribute,
    )

"""The catalog reads the .ecore with lxml; pyecore's own reading of the same file is the yardstick.

Every answer the catalog gives is compared, for every class, with what the metamodel says when
pyecore builds it from the file: ancestors in pyecore's order, parameters (which features, in
which order, with which annotation details), and the inherited node and actor annotations.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from pyecore.ecore import EClass, EReference
from pyecore.resources import URI, ResourceSet

from sceml.model import catalog

ECORE = Path(__file__).resolve().parents[2] / "metamodel" / "scemlmodel.ecore"


@pytest.fixture(scope="module")
def classes() -> dict[str, EClass]:
    package = ResourceSet().get_resource(URI(str(ECORE))).contents[0]
    return {c.name: c for c in package.eClassifiers if isinstance(c, EClass)}


def _details(element: object, source: str) -> dict[str, str]:
    for annotation in getattr(element, "eAnnotations", ()):
        if annotation.source == source:
            return dict(annotation.details.items())
    return {}


def test_every_class_is_read_in_file_order(classes: dict[str, EClass]) -> None:
    assert list(catalog._ecore_classes()) == list(classes)


def test_ancestors_come_in_pyecores_order(classes: dict[str, EClass]) -> None:
    for name, eclass in classes.items():
        assert catalog._all_supertypes(name) == tuple(s.name for s in eclass.eAllSuperTypes())
        for other in classes:
            expected = other == name or other in {s.name for s in eclass.eAllSuperTypes()}
            assert catalog.is_kind_of(name, other) is expected


def test_parameters_are_the_annotated_parameter_values(classes: dict[str, EClass]) -> None:
    for name, eclass in classes.items():
        expected = []
        for feature in eclass.eAllStructuralFeatures():
            if isinstance(feature, EReference) and feature.eType.name == "ParameterValue":
                details = _details(feature, catalog.PARAMETER_ANNOTATION)
                expected.append((feature.name, details.get("unit", ""), details.get("sign")))
        got = [(spec.name, spec.unit, spec.sign) for spec in catalog.parameters(name)]
        assert got == expected, name


def test_inherited_annotations_let_the_most_specific_class_win(
    classes: dict[str, EClass],
) -> None:
    for name, eclass in classes.items():
        for source in (catalog.NODE_ANNOTATION, catalog.ACTOR_ANNOTATION):
            merged: dict[str, str] = {}
            for ancestor in reversed([eclass, *eclass.eAllSuperTypes()]):
                merged.update(_details(ancestor, source))
            assert catalog._inherited_annotation(name, source) == merged


def test_limited_kinds_and_concrete_kinds(classes: dict[str, EClass]) -> None:
    limited = tuple(
        name
        for name, eclass in classes.items()
        if any(
            "limit" in _details(feature, catalog.PARAMETER_ANNOTATION)
            for feature in eclass.eStructuralFeatures
        )
    )
    assert catalog.limited_kinds() == limited
    assert "Accelerate" in limited  # its target speed is bounded by max_speed
    concrete = {
        name
        for name, eclass in classes.items()
        if not eclass.abstract and "Actor" in {s.name for s in eclass.eAllSuperTypes()}
    }
    assert {kind.__name__ for kind in catalog.actor_kinds()} == concrete

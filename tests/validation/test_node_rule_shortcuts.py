"""The per-node rules' shortcuts (tables kept per metaclass, reads without pyecore's descriptor,
early returns) give what the straightforward computation gives."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st
from pyecore.ecore import EClass, EObject

import scemlmodel as scm
from sceml.model import catalog
from sceml.model.params import describe
from sceml.validation import actors, parameters, plausibility
from sceml.validation.parameters import parameter_path, values_physically_meaningful

# The metamodel's classes, as the generated package exposes them.
CLASSES = [
    c
    for c in scm.eClass.eClassifiers
    if isinstance(c, EClass) and getattr(getattr(scm, c.name, None), "eClass", None) is c
]
NODE_KINDS = [c for c in CLASSES if not c.abstract and scm.ActionNode.eClass in c.eAllSuperTypes()]


@pytest.mark.parametrize("eclass", CLASSES, ids=lambda c: c.name)
def test_sign_and_required_tables_say_what_the_catalog_says(eclass: EClass) -> None:
    for feature in eclass.eAllStructuralFeatures():
        assert parameters._sign(eclass, feature) == catalog.sign(eclass.name, feature.name)
    required = [spec.name for spec in catalog.parameters(eclass.name) if spec.required]
    assert list(parameters._required_parameters(eclass)) == required


def test_the_tables_hold_signs_of_both_kinds() -> None:
    # What the cases below lean on: Environment has a positive and a non-negative parameter.
    environment = scm.Environment.eClass
    assert catalog.sign("Environment", "fogVisualRange") == catalog.POSITIVE
    assert catalog.sign("Environment", "precipitationIntensity") == catalog.NON_NEGATIVE
    assert parameters._sign(environment, environment.findEStructuralFeature("fogVisualRange")) == (
        catalog.POSITIVE
    )


@pytest.mark.parametrize("eclass", NODE_KINDS, ids=lambda c: c.name)
def test_actor_table_says_what_the_catalog_says(eclass: EClass) -> None:
    name = eclass.name
    assert actors._kind(eclass) == (
        catalog.performed_by_actor(name),
        catalog.needs_target(name),
        catalog.allows_target(name),
    )


def straightforward_p007(value: EObject) -> list[str]:
    """SCEML-P007 as it read before the shortcuts: every number, the sign looked up each time."""
    feature, owner = value.eContainmentFeature(), value.eContainer()
    sign = catalog.sign(owner.eClass.name, feature.name)
    if isinstance(value, scm.Value):
        candidates = [value.value]
    elif isinstance(value, scm.Range):
        candidates = [value.min, value.max]
    else:
        candidates = [option.value for option in value.options]
    stated = [float(number) for number in candidates if number is not None]
    unit = catalog.parameter(owner.eClass.name, feature.name).unit
    if not all(math.isfinite(number) for number in stated):
        return [f"{parameter_path(value)} is {describe(value)}: not a finite number"]
    if sign == catalog.POSITIVE and any(number <= 0 for number in stated):
        return [f"{parameter_path(value)} is {describe(value, unit)}; it must be above 0"]
    if sign == catalog.NON_NEGATIVE and any(number < 0 for number in stated):
        return [f"{parameter_path(value)} is {describe(value, unit)}; it must be >= 0"]
    return []


maybe_numbers = st.one_of(st.none(), st.floats(), st.sampled_from([0.0, -0.0, 1.0, -1.0]))


def stated_values(draw: st.DrawFn) -> EObject:
    shape = draw(st.sampled_from(["value", "range", "discrete"]))
    if shape == "value":
        return scm.Value(value=draw(maybe_numbers))
    if shape == "range":
        return scm.Range(min=draw(maybe_numbers), max=draw(maybe_numbers))
    options = [
        scm.WeightedValue(value=draw(maybe_numbers), weight=1.0)
        for _ in range(draw(st.integers(0, 4)))
    ]
    return scm.DiscreteDistribution(options=options)


@given(
    st.composite(stated_values)(),
    st.sampled_from(
        [
            ("Environment", "fogVisualRange"),  # positive
            ("Environment", "precipitationIntensity"),  # non-negative
            ("WorldPosition", "x"),  # any sign
        ]
    ),
)
def test_p007_finds_what_the_straightforward_rule_finds(
    value: EObject, where: tuple[str, str]
) -> None:
    kind, feature = where
    owner = getattr(scm, kind)()
    owner.eSet(feature, value)
    found = [message for _, message in values_physically_meaningful(value, None)]  # type: ignore[arg-type]
    assert found == straightforward_p007(value)


@pytest.mark.parametrize("eclass", CLASSES, ids=lambda c: c.name)
def test_limited_table_says_what_the_catalog_says(eclass: EClass) -> None:
    for key in plausibility.LIMIT_UNITS:
        assert plausibility._limited(eclass, key) == catalog.limited(eclass.name, key)


@given(maybe_numbers)
def test_highest_of_a_single_value_is_the_size_the_descriptor_reads(number: float | None) -> None:
    value = scm.Value(value=number)  # None leaves it unset: its default is read
    found = plausibility.highest(value)
    stated = value.value  # read after, through pyecore's descriptor
    if stated is None:
        assert found is None
    elif math.isnan(stated):
        assert found is not None and math.isnan(found)
    else:
        assert found == abs(stated)

"""Properties of random valid scenarios (tests/strategies.py): they validate clean at every level,
and concrete ones export to OpenSCENARIO that the official XSD of each version accepts."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from strategies import scenarios

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.export import export
from sceml.validation import validate
from sceml.xosc import schema

PROPERTY = settings(max_examples=50, deadline=None)


def errors(scenario: scm.Scenario, **options: object) -> list[str]:
    return [str(d) for d in validate(scenario, **options) if d.severity >= Severity.ERROR]


@pytest.mark.parametrize("level", ["functional", "logical", "concrete"])
def test_random_valid_scenarios_validate_clean(level: str) -> None:
    @PROPERTY
    @given(scenario=scenarios(level))
    def check(scenario: scm.Scenario) -> None:
        assert errors(scenario) == []

    check()


@PROPERTY
@given(scenario=scenarios("concrete"))
def test_concrete_scenarios_export_to_xsd_valid_openscenario(scenario: scm.Scenario) -> None:
    for version in schema.SUPPORTED_VERSIONS:
        # What `sceml validate --osc-version` promises is what export must then deliver.
        assert errors(scenario, osc_version=version) == []
        tree = export(scenario, version=version)  # validates internally, raises if invalid
        assert schema.declared_version(tree) == version
        assert schema.validate_tree(tree, version) == []

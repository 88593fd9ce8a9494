"""Parameterized .xosc plus ParameterValueDistribution: XSD 1.1-1.3, ASAM QC 1.2/1.3."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from lxml import etree

from sceml.levels.paths import LevelError
from sceml.levels.pvd import distribution_kind, export_distribution
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario
from sceml.model.saving import save
from sceml.xosc import schema
from sceml.xosc.qualitychecker import run_quality_checker

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _declared_and_used(xosc: Path) -> tuple[set[str], set[str]]:
    root = etree.parse(str(xosc)).getroot()
    declared = set(root.xpath("/OpenSCENARIO/ParameterDeclarations/ParameterDeclaration/@name"))
    used = set(re.findall(r'"\$([A-Za-z0-9_]+)"', xosc.read_text()))
    return declared, used


@pytest.mark.parametrize("version", ["1.1", "1.2", "1.3"])
@pytest.mark.parametrize("mode", ["auto", "stochastic"])
def test_uis2_distribution_passes_xsd_and_qc(tmp_path: Path, version: str, mode: str) -> None:
    files = export_distribution(
        EXAMPLES / "uis2-logical.xmi", tmp_path, version=version, mode=mode, runs=20, seed=3
    )
    assert files.kind == "stochastic"  # UIS2 has a normal and a uniform distribution
    for path in (files.scenario, files.distribution):
        assert schema.validate_file(path) == []
        if version != "1.1":
            report = run_quality_checker(path)
            assert report.ok, [str(i) for i in report.issues]
    declared, used = _declared_and_used(files.scenario)
    sampled = {
        "ego_initialSpeed",
        "Accelerate_1_targetSpeed",
        "InLocationRadius_2_radius",
        "DriveDistance_1_speed",
        "CrossingManeuver_1_triggerRadius",
        "CrossingManeuver_1_crossingSpeed",
    }
    # Every sampled parameter is declared and used; 1.0/1.1 also declare the marker parameter.
    assert sampled <= used <= declared
    assert declared - sampled <= {"SceML_marker"}
    pvd = etree.parse(str(files.distribution)).getroot()
    assert pvd.xpath("//ScenarioFile/@filepath") == ["uis2.xosc"]
    stochastic = pvd.find("ParameterValueDistribution/Stochastic")
    assert stochastic.get("numberOfTestRuns") == "20" and float(stochastic.get("randomSeed")) == 3
    normal = pvd.xpath(
        "//StochasticDistribution[@parameterName='Accelerate_1_targetSpeed']/NormalDistribution"
    )[0]
    assert (normal.get("expectedValue"), normal.get("variance")) == ("7.0", "1.0")
    assert normal.find("Range").attrib == {"lowerLimit": "5.0", "upperLimit": "9.0"}


@pytest.mark.parametrize("version", ["1.1", "1.2", "1.3"])
def test_deterministic_distribution_of_a_grid_only_scenario(tmp_path: Path, version: str) -> None:
    # UIS1 with its two distributions fixed leaves two ranges with steps: a deterministic sweep.
    logical = load_scenario(EXAMPLES / "uis1-logical.xmi")
    nodes = {n.name: n for n in logical.root.nodes}
    nodes["Accelerate_1"].targetSpeed = _value(8)
    nodes["Accelerate_2"].targetSpeed = _value(4)
    source = EXAMPLES / "uis1-logical.xmi"
    grid_only = tmp_path / "uis1-logical.xmi"
    save(logical.root, grid_only)
    _copy_map(source, grid_only)
    files = export_distribution(grid_only, tmp_path / "out", version=version)
    assert files.kind == "deterministic"
    for path in (files.scenario, files.distribution):
        assert schema.validate_file(path) == []
        if version != "1.1":
            assert run_quality_checker(path).ok
    pvd = etree.parse(str(files.distribution)).getroot()
    ranges = pvd.xpath("//DeterministicSingleParameterDistribution/DistributionRange")
    assert [r.getparent().get("parameterName") for r in ranges] == [
        "ego_initialSpeed",
        "InVehicleRadius_1_radius",
    ]
    assert ranges[1].get("stepWidth") == "4.0"
    assert ranges[1].find("Range").attrib == {"lowerLimit": "8.0", "upperLimit": "16.0"}


def test_deterministic_mode_refuses_distributions() -> None:
    space = parameter_space(load_scenario(EXAMPLES / "uis2-logical.xmi").root)
    with pytest.raises(LevelError, match="Accelerate_1.targetSpeed"):
        distribution_kind(space, "deterministic")


def _value(number: float):  # type: ignore[no-untyped-def]
    from sceml.model.params import value

    return value(number)


def _copy_map(source: Path, target: Path) -> None:
    """The map path is relative: make it resolve from the temporary folder too."""
    scenario = load_scenario(target)
    scenario.root.nodes[0].map = str((target.parent / scenario.root.nodes[0].map).resolve())
    save(scenario.root, target)

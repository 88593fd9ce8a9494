"""The parameterised-export hook (issue 6): chosen values become `$name` with a declaration."""

from __future__ import annotations

from pathlib import Path

from sceml.export import ParameterDeclarationSpec, export
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_hooked_values_become_parameter_references() -> None:
    scenario = load_scenario(EXAMPLES / "uis2-concrete.xmi").root
    hook = {
        ("Root/ego", "initialSpeed"): ParameterDeclarationSpec("EgoSpeed", "6.0"),
        ("CrossingManeuver_1.InVehicleRadius_1", "radius"): ParameterDeclarationSpec(
            "Radius", "15.0"
        ),
    }
    for version in ("1.0", "1.3"):
        root = export(scenario, version=version, parameters=hook).getroot()
        declared = {
            p.get("name"): (p.get("parameterType"), p.get("value"))
            for p in root.find("ParameterDeclarations")
        }
        assert declared["EgoSpeed"] == ("double", "6.0") and declared["Radius"] == (
            "double",
            "15.0",
        )
        init = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']")
        assert init.find(".//AbsoluteTargetSpeed").get("value") == "$EgoSpeed"
        radius = root.find(".//RelativeDistanceCondition")
        assert radius.get("value") == "$Radius"

"""Release 1.4's kinds from files/lights-and-stops.xosc (OpenSCENARIO 1.3, written by hand):
LightStateAction (Init and story) imports as LightState, StandStillCondition as StandStill,
AccelerationCondition as AccelerationCondition with its direction; they export back as written
(XSD-valid) and import again to the same scenario. What stays opaque (a light with a colour)
says what it is."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import ExportError, export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
LIGHTS = FILES / "lights-and-stops.xosc"
#: The elements compared between the original and the re-export, with their attributes.
COMPARED = ("LightStateAction", "VehicleLight", "LightState", "StandStillCondition")


def elements(path: Path, tag: str) -> list[dict[str, str]]:
    """Each `tag` element's attributes, numbers as numbers; `$Still` read as its value."""
    found = []
    for element in etree.parse(str(path)).iter(tag):
        attributes = {}
        for key, value in element.attrib.items():
            text = {"$Still": "1"}.get(value, value)
            try:
                attributes[key] = repr(float(text))
            except ValueError:
                attributes[key] = text
        found.append(attributes)
    return sorted(found, key=repr)


def test_lights_and_motion_conditions_import_as_their_kinds() -> None:
    imported = import_file(LIGHTS)
    assert imported.report.counts()["opaque"] == 0
    nodes = {str(n.name): n for n in imported.scenario.nodes}
    low_beam = next(
        n for n in nodes.values() if isinstance(n, scm.LightState) and n.name.startswith("Init")
    )
    assert (low_beam.lightType.name, low_beam.mode.name, low_beam.luminousIntensity.value) == (
        "lowBeam",
        "on",
        1500.0,
    )
    # An Init light acts from the start: right after the root.
    assert [f.source for f in low_beam.incoming] == [graph.root_node(imported.scenario)]
    brake = nodes["BrakeLightsOn"]
    assert (brake.lightType.name, brake.transitionTime.value, brake.flashingOnDuration) == (
        "brakeLights",
        0.2,
        None,
    )
    hazard = nodes["HazardLights"]
    assert (
        hazard.mode.name,
        hazard.flashingOnDuration.value,
        hazard.flashingOffDuration.value,
    ) == (
        "flashing",
        0.4,
        0.4,
    )
    assert hazard.luminousIntensity is None  # unset: the player's default
    decelerates = nodes["LeadDecelerates"]
    assert isinstance(decelerates, scm.AccelerationCondition)
    assert (decelerates.rule.name, decelerates.acceleration.value, decelerates.direction.name) == (
        "lessThan",
        -3.0,
        "longitudinal",
    )
    still = nodes["LeadStandsStill"]
    assert isinstance(still, scm.StandStill) and still.duration.value == 1.0
    assert [f.source for f in hazard.incoming] == [still]


def test_lights_and_motion_conditions_export_as_they_were_read(tmp_path: Path, same) -> None:
    first = import_file(LIGHTS)
    exported = tmp_path / "lights.xosc"
    export_to_file(first.scenario, exported, version="1.3", source_path=LIGHTS)
    assert schema.validate_file(exported, "1.3") == []
    for tag in COMPARED:
        original = elements(LIGHTS, tag)
        if tag == "LightStateAction":  # an absent transitionTime is written as its 0
            original = [{"transitionTime": "0.0", **a} for a in original]
        assert elements(exported, tag) == original, tag
    # The acceleration's value and direction as written; its strict rule as read.
    assert elements(exported, "AccelerationCondition") == [
        {"value": "-3.0", "rule": "lessThan", "direction": "longitudinal"}
    ]
    again = import_file(exported, allow=[FILES])
    for scenario in (first.scenario, again.scenario):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first.scenario, again.scenario)


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2"))
def test_lights_are_refused_before_1_3(version: str, tmp_path: Path) -> None:
    # 1.2 has the action, but its schema wants a user-defined light beside every vehicle light.
    with pytest.raises(ExportError) as refused:
        export_to_file(import_file(LIGHTS).scenario, tmp_path / "l.xosc", version=version)
    assert "LightState needs OpenSCENARIO 1.3" in str(refused.value.diagnostics)
    assert not (tmp_path / "l.xosc").exists()


def test_a_coloured_light_stays_opaque_and_says_what_it_is(tmp_path: Path) -> None:
    text = LIGHTS.read_text(encoding="utf-8").replace(
        '<LightState mode="on" luminousIntensity="300"/>',
        '<LightState mode="on" luminousIntensity="300"><Color colorType="red">'
        '<ColorRgb red="1" green="0" blue="0"/></Color></LightState>',
    )
    coloured = tmp_path / "coloured.xosc"
    coloured.write_text(text, encoding="utf-8")
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    shutil.copy(FILES / "highway.xodr", tmp_path)
    imported = import_file(coloured)
    assert imported.report.counts()["opaque"] == 1
    (line,) = [e.message for e in imported.report.section("opaque")]
    assert "Action LightStateAction transitionTime=0.2" in line
    assert "a light colour has no SceML form" in line


RELATIVE = FILES / "relative-speeds.xosc"


def test_relative_speeds_import_as_match_speed() -> None:
    imported = import_file(RELATIVE)
    assert imported.report.counts()["opaque"] == 0
    follower = next(a for a in graph.actors(imported.scenario) if a.name == "Follower")
    assert follower.initialSpeed.value == 18.0  # the step at the start: 0.9 of the lead's 20
    slow, keep = sorted(
        (n for n in imported.scenario.nodes if isinstance(n, scm.MatchSpeed)),
        key=lambda n: str(n.name),
    )
    assert (keep.name, keep.relation.name, keep.speedFactor.value, keep.continuous) == (
        "Init_Follower",
        "factor",
        0.9,
        True,
    )
    assert keep.rate is None and keep.targetActor.name == "Lead"
    assert (slow.relation.name, slow.speedDelta.value, slow.rate.value, slow.continuous) == (
        "delta",
        -5.0,
        2.0,
        False,
    )


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_relative_speeds_export_as_they_were_read(version: str, tmp_path: Path) -> None:
    first = import_file(RELATIVE)
    exported = tmp_path / "relative.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=RELATIVE)
    assert schema.validate_file(exported, version) == []
    assert elements(exported, "RelativeTargetSpeed") == elements(RELATIVE, "RelativeTargetSpeed")
    again = import_file(exported, allow=[FILES])
    # The same MatchSpeed nodes. (The slow-down's wait of 3 s, written as a delay on
    # `SimulationTime >= 0` beside the Init node's finish, comes back as a wait after the
    # root joined with it: the same run in esmini, by its logs, but not the same graph.)
    assert _speeds(again.scenario) == _speeds(first.scenario)


def _speeds(scenario: scm.Scenario) -> list[tuple[object, ...]]:
    """Each MatchSpeed: its actors, relation, values and whether it is continuous."""
    return sorted(
        (
            n.referenceActor.name,
            n.targetActor.name,
            n.relation.name,
            None if n.speedDelta is None else n.speedDelta.value,
            None if n.speedFactor is None else n.speedFactor.value,
            None if n.rate is None else n.rate.value,
            n.continuous,
        )
        for n in scenario.nodes
        if isinstance(n, scm.MatchSpeed)
    )

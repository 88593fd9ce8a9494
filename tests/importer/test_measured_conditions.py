"""Conditions that measure a distance keep how they measure through import and export: a
hand-written file imports to the SceML kind (not opaque), exports back at every version that can
say it (XSD-valid, the same attributes as the original) and imports again to the same scenario;
1.0, which cannot say a longitudinal distance, is refused with the node named."""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import ExportError, export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
TTC = FILES / "ttc-measured.xosc"
HEADWAY = FILES / "headway-measured.xosc"
DISTANCE = FILES / "relative-distance-measured.xosc"
MEASURE = ("value", "freespace", "rule", "relativeDistanceType", "coordinateSystem")


def _attributes(path: Path, tag: str) -> list[dict[str, str]]:
    """The measuring attributes of every `tag` element, as written (defaults filled in the way
    OpenSCENARIO reads an absent one)."""
    defaults = {"relativeDistanceType": "euclidianDistance", "coordinateSystem": "entity"}
    found = []
    for element in etree.parse(str(path)).iter(tag):
        found.append({key: element.get(key, defaults.get(key, "")) for key in MEASURE})
    return found


def test_a_measured_time_to_collision_is_mapped_not_opaque() -> None:
    imported = import_file(TTC)
    assert imported.report.counts()["opaque"] == 0
    (ttc,) = [n for n in imported.scenario.nodes if n.eClass.name == "TimeToCollision"]
    assert ttc.freespace is False
    assert ttc.relativeDistanceType.name == "longitudinal"
    assert ttc.coordinateSystem.name == "entity"
    assert ttc.targetActor.name == "Target"
    assert ttc.time.value == 2.5


#: Each hand-written file, its condition element, the measure it was written with and the value
#: its export writes (a parameter's value: the export resolves them).
WRITTEN = {
    "ttc": (
        TTC,
        "TimeToCollisionCondition",
        {
            "value": "$HeadwayTime",
            "freespace": "false",
            "rule": "lessThan",
            "relativeDistanceType": "longitudinal",
            "coordinateSystem": "entity",
        },
        "2.5",
    ),
    "headway": (
        HEADWAY,
        "TimeHeadwayCondition",
        {
            "value": "1.2",
            "freespace": "true",
            "rule": "lessThan",
            "relativeDistanceType": "longitudinal",
            "coordinateSystem": "lane",
        },
        "1.2",
    ),
    "distance": (
        DISTANCE,
        "RelativeDistanceCondition",
        {
            "value": "$Gap",
            "freespace": "true",
            "rule": "lessThan",
            "relativeDistanceType": "longitudinal",
            "coordinateSystem": "entity",
        },
        "12.0",
    ),
}


@pytest.mark.parametrize("version", ("1.1", "1.2", "1.3"))
@pytest.mark.parametrize("which", sorted(WRITTEN))
def test_a_measuring_condition_exports_as_it_was_read(
    which: str, version: str, tmp_path: Path, same
) -> None:
    source, tag, measure, value = WRITTEN[which]
    assert _attributes(source, tag) == [measure]
    first = import_file(source)
    assert first.report.counts()["opaque"] == 0
    exported = tmp_path / "measured.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=source)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    written = _attributes(exported, tag)
    assert written == [{**measure, "value": value}]
    again = import_file(exported, allow=[FILES]).scenario
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_a_measured_time_headway_is_mapped_with_its_target() -> None:
    (headway,) = [n for n in import_file(HEADWAY).scenario.nodes if n.eClass.name == "TimeHeadway"]
    assert (headway.referenceActor.name, headway.targetActor.name) == ("Target", "Ego")
    assert headway.freespace is True
    assert headway.relativeDistanceType.name == "longitudinal"
    assert headway.coordinateSystem.name == "lane"
    assert (headway.rule.name, headway.time.value) == ("lessThan", 1.2)


def test_openscenario_1_0_cannot_say_a_longitudinal_time_to_collision(tmp_path: Path) -> None:
    with pytest.raises(ExportError) as refused:
        export_to_file(import_file(TTC).scenario, tmp_path / "ttc.xosc", version="1.0")
    assert "relativeDistanceType longitudinal needs OpenSCENARIO 1.1" in str(refused.value)
    assert "CutInStartCondition" in str(refused.value)
    assert not (tmp_path / "ttc.xosc").exists()


def test_a_time_to_collision_along_the_route_stays_opaque_and_says_why(tmp_path: Path) -> None:
    text = TTC.read_text().replace('coordinateSystem="entity"', 'alongRoute="true"')
    along = tmp_path / "along.xosc"
    along.write_text(text)
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    imported = import_file(along)
    assert imported.report.counts()["opaque"] == 1
    assert any("alongRoute" in entry.message for entry in imported.report.section("opaque"))


TRAVELED = FILES / "traveled-distance.xosc"


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_a_traveled_distance_is_mapped_and_exported_as_it_was_read(
    version: str, tmp_path: Path, same
) -> None:
    first = import_file(TRAVELED)
    assert first.report.counts()["opaque"] == 0
    (traveled,) = [n for n in first.scenario.nodes if n.eClass.name == "TraveledDistance"]
    assert (traveled.referenceActor.name, traveled.distance.value) == ("Ego", 60.0)
    exported = tmp_path / "traveled.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=TRAVELED)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    (written,) = etree.parse(str(exported)).iter("TraveledDistanceCondition")
    assert float(written.get("value")) == 60.0
    entity = written.getparent().getparent().find("TriggeringEntities/EntityRef")
    assert entity.get("entityRef") == "Ego"
    again = import_file(exported, allow=[FILES]).scenario
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def _distance_node(scenario: Any) -> Any:
    """The scenario's one InVehicleRadius."""
    (node,) = [n for n in scenario.nodes if n.eClass.name == "InVehicleRadius"]
    return node


def test_a_measured_relative_distance_is_an_in_vehicle_radius_with_its_measure() -> None:
    imported = import_file(DISTANCE)
    assert imported.report.counts()["opaque"] == 0
    # Nothing about the distance is guessed any more (it was read as a radius before 1.3).
    guessed = [e.message for e in imported.report.section("guessed")]
    assert not [m for m in guessed if "distance" in m or "freespace" in m]
    node = _distance_node(imported.scenario)
    assert (node.referenceActor.name, node.targetActor.name) == ("Ego", "Target")
    assert node.freespace is True
    assert node.relativeDistanceType.name == "longitudinal"
    assert node.coordinateSystem.name == "entity"
    assert (node.rule.name, node.radius.value) == ("lessThan", 12.0)


def test_openscenario_1_0_says_a_longitudinal_freespace_distance(tmp_path: Path) -> None:
    # 1.0's RelativeDistanceCondition has relativeDistanceType longitudinal and freespace
    # already (only coordinateSystem is 1.1's): the 1.0 export writes them without it.
    exported = tmp_path / "distance.xosc"
    export_to_file(import_file(DISTANCE).scenario, exported, version="1.0")
    assert schema.validate_tree(schema.parse_file(exported)) == []
    (written,) = etree.parse(str(exported)).iter("RelativeDistanceCondition")
    assert dict(written.attrib) == {
        "entityRef": "Target",
        "relativeDistanceType": "longitudinal",
        "value": "12.0",
        "freespace": "true",
        "rule": "lessThan",
    }


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = DISTANCE.read_text()
    assert old in text
    variant = tmp_path / "variant.xosc"
    variant.write_text(text.replace(old, new))
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    return variant


def test_openscenario_1_0_cannot_say_a_distance_in_lane_coordinates(tmp_path: Path) -> None:
    variant = _variant(tmp_path, 'coordinateSystem="entity"', 'coordinateSystem="lane"')
    scenario = import_file(variant).scenario
    assert _distance_node(scenario).coordinateSystem.name == "lane"
    with pytest.raises(ExportError) as refused:
        export_to_file(scenario, tmp_path / "out.xosc", version="1.0")
    assert "coordinateSystem lane needs OpenSCENARIO 1.1" in str(refused.value)
    assert "CutInStartCondition" in str(refused.value)
    assert not (tmp_path / "out.xosc").exists()


def test_a_distance_beyond_the_radius_keeps_its_rule(tmp_path: Path) -> None:
    variant = _variant(
        tmp_path, 'rule="lessThan" coordinateSystem', 'rule="greaterThan" coordinateSystem'
    )
    variant.write_text(
        variant.read_text().replace('conditionEdge="rising"', 'conditionEdge="none"')
    )
    scenario = import_file(variant).scenario
    assert _distance_node(scenario).rule.name == "greaterThan"
    exported = tmp_path / "out.xosc"
    export_to_file(scenario, exported, version="1.3", source_path=variant)
    (written,) = etree.parse(str(exported)).iter("RelativeDistanceCondition")
    assert written.get("rule") == "greaterThan"


def test_a_distance_growing_past_its_value_on_a_rising_edge_keeps_its_edge(tmp_path: Path) -> None:
    # greaterThan on a rising edge waits for the gap to grow past the value; "holds" would fire
    # at once where the gap starts beyond it, so the node keeps the edge (release 1.3).
    variant = _variant(
        tmp_path, 'rule="lessThan" coordinateSystem', 'rule="greaterThan" coordinateSystem'
    )
    assert 'name="CutInStartCondition" delay="0" conditionEdge="rising"' in variant.read_text()
    imported = import_file(variant)
    assert imported.report.counts()["opaque"] == 0
    (radius,) = [n for n in imported.scenario.nodes if isinstance(n, scm.InVehicleRadius)]
    assert radius.rule == scm.ComparisonRule.greaterThan
    assert radius.edge == scm.ConditionEdge.rising

"""A LongitudinalDistanceAction keeps its measure and limits through import and export (release
1.5): the hand-written file imports to Follow and Approach (not opaque) with its freespace,
displacement, time gap and DynamicConstraints, exports back at every version that can say
them (XSD-valid, the same attributes as the original) and imports again to the same scenario;
the versions that cannot say a jerk or a side are refused with the node named."""

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
KEEPING = FILES / "distance-keeping.xosc"

#: Each action's attributes and constraints as the file writes them, parameters resolved.
WRITTEN = [
    (
        {
            "entityRef": "Lead",
            "distance": "12.0",
            "freespace": "true",
            "continuous": "true",
            "displacement": "trailingReferencedEntity",
        },
        {
            "maxAcceleration": "4.0",
            "maxDeceleration": "7.0",
            "maxSpeed": "35.0",
            "maxAccelerationRate": "2.0",
            "maxDecelerationRate": "5.0",
        },
    ),
    (
        {
            "entityRef": "Ego",
            "timeGap": "1.5",
            "freespace": "false",
            "continuous": "false",
            "displacement": "leadingReferencedEntity",
        },
        {"maxAcceleration": "3.0", "maxDeceleration": "6.0", "maxSpeed": "30.0"},
    ),
]


def _actions(path: Path) -> list[tuple[dict[str, str], dict[str, str]]]:
    """Each LongitudinalDistanceAction's attributes and its DynamicConstraints', numbers
    written as floats and an absent displacement as players read it in 1.1+ (behind)."""
    found = []
    for action in etree.parse(str(path)).iter("LongitudinalDistanceAction"):
        attributes = {"displacement": "trailingReferencedEntity", **action.attrib}
        for key in ("distance", "timeGap"):
            if key in attributes:
                attributes[key] = repr(float(attributes[key].replace("$Gap", "12")))
        limits = action.find("DynamicConstraints")
        numbers = {key: repr(float(value)) for key, value in limits.attrib.items()}
        found.append((attributes, numbers))
    return found


def _node(scenario: scm.Scenario, kind: str) -> scm.DistanceKeeping:
    (node,) = [n for n in scenario.nodes if n.eClass.name == kind]
    return node


def test_a_distance_keeping_is_read_with_its_measure_and_limits() -> None:
    imported = import_file(KEEPING)
    assert imported.report.counts()["opaque"] == 0
    follow = _node(imported.scenario, "Follow")
    assert (follow.referenceActor.name, follow.targetActor.name) == ("Ego", "Lead")
    assert (follow.distance.value, follow.timeGap) == (12.0, None)
    assert follow.freespace is True
    assert follow.displacement.name == "trailing"
    limits = ("maxAcceleration", "maxDeceleration", "maxSpeed")
    jerks = ("maxAccelerationRate", "maxDecelerationRate")
    assert [follow.eGet(k).value for k in (*limits, *jerks)] == [4.0, 7.0, 35.0, 2.0, 5.0]
    approach = _node(imported.scenario, "Approach")
    assert (approach.referenceActor.name, approach.targetActor.name) == ("Lead", "Ego")
    assert approach.timeGap.value == 1.5
    assert approach.freespace is False
    assert approach.displacement.name == "leading"
    assert [approach.eGet(k).value for k in limits] == [3.0, 6.0, 30.0]
    assert [approach.eGet(k) for k in jerks] == [None, None]


def test_the_file_says_what_the_test_expects() -> None:
    assert _actions(KEEPING) == WRITTEN


@pytest.mark.parametrize("version", ("1.2", "1.3"))
def test_a_distance_keeping_exports_as_it_was_read(version: str, tmp_path: Path, same) -> None:
    first = import_file(KEEPING)
    exported = tmp_path / "keeping.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=KEEPING)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    assert _actions(exported) == WRITTEN
    again = import_file(exported, allow=[FILES]).scenario
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_openscenario_1_1_has_no_jerk_limits(tmp_path: Path) -> None:
    with pytest.raises(ExportError) as refused:
        export_to_file(import_file(KEEPING).scenario, tmp_path / "k.xosc", version="1.1")
    assert "maxAccelerationRate needs OpenSCENARIO 1.2" in str(refused.value)
    assert "EgoFollows" in str(refused.value)
    assert not (tmp_path / "k.xosc").exists()


def test_openscenario_1_1_says_the_side_and_1_0_cannot(tmp_path: Path) -> None:
    scenario = import_file(KEEPING).scenario
    follow = _node(scenario, "Follow")
    follow.maxAccelerationRate = follow.maxDecelerationRate = None
    exported = tmp_path / "k11.xosc"
    export_to_file(scenario, exported, version="1.1", source_path=KEEPING)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    written = [
        a.get("displacement") for a in etree.parse(str(exported)).iter("LongitudinalDistanceAction")
    ]
    # Behind the target is what players take an absent displacement for: not written.
    assert written == [None, "leadingReferencedEntity"]
    with pytest.raises(ExportError) as refused:
        export_to_file(scenario, tmp_path / "k10.xosc", version="1.0")
    assert "a gap kept on the leading side needs OpenSCENARIO 1.1" in str(refused.value)
    assert "LeadGetsAhead" in str(refused.value)


def test_a_negative_distance_in_1_0_is_a_gap_ahead(tmp_path: Path) -> None:
    text = KEEPING.read_text().replace('revMinor="2"', 'revMinor="0"')
    # What 1.0's schema has not: displacement, jerks, override, greaterOrEqual.
    for said, in_1_0 in (
        ('distance="$Gap"', 'distance="-8"'),
        (' displacement="trailingReferencedEntity"', ""),
        (' displacement="leadingReferencedEntity"', ""),
        (' maxAccelerationRate="2" maxDecelerationRate="5"', ""),
        ('priority="override"', 'priority="overwrite"'),
        ('rule="greaterOrEqual"', 'rule="greaterThan"'),
    ):
        text = text.replace(said, in_1_0)
    old = tmp_path / "old.xosc"
    old.write_text(text)
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    follow = _node(import_file(old).scenario, "Follow")
    assert (follow.distance.value, follow.displacement.name) == (8.0, "leading")


def test_a_distance_keeping_without_limits_writes_the_actors_own(tmp_path: Path) -> None:
    # Unset, the limits are what the export wrote before release 1.5: the actor's performance
    # within the gap-keeping limits (the catalog's car_white: 10 m/s2 taken down to 3, 10 m/s2
    # to 6, and its 69 m/s).
    scenario = import_file(KEEPING).scenario
    follow = _node(scenario, "Follow")
    for key in ("maxAcceleration", "maxDeceleration", "maxSpeed", "maxAccelerationRate"):
        follow.eSet(key, None)
    follow.maxDecelerationRate = None
    exported = tmp_path / "plain.xosc"
    export_to_file(scenario, exported, version="1.3", source_path=KEEPING)
    (limits, _) = [
        a.find("DynamicConstraints").attrib
        for a in etree.parse(str(exported)).iter("LongitudinalDistanceAction")
    ]
    assert dict(limits) == {"maxAcceleration": "3.0", "maxDeceleration": "6.0", "maxSpeed": "69.0"}


def test_a_gap_in_another_frame_is_reported_as_not_kept(tmp_path: Path) -> None:
    text = KEEPING.read_text().replace(
        'timeGap="1.5" freespace="false"', 'timeGap="1.5" freespace="false" coordinateSystem="lane"'
    )
    framed = tmp_path / "framed.xosc"
    framed.write_text(text)
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    imported = import_file(framed)
    kept = [e.message for e in imported.report.section("not represented")]
    assert [m for m in kept if "lane frame" in m] == [
        "LeadGetsAhead: the gap measured in the lane frame is measured along the actor's heading"
    ]
    assert imported.report.counts()["opaque"] == 0

"""Lane changes keep their target through import and export: into another actor's lane with an
offset and a shape, into an absolute lane, by two lanes; the hand-written file imports with
nothing opaque, exports back XSD-valid at every version with the same LaneChangeAction, and
imports again to the same scenario."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from lxml import etree

from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
LANE_CHANGES = FILES / "lane-changes.xosc"


def _changes(path: Path) -> list[dict[str, str]]:
    """Each LaneChangeAction's offset, shape, distance and target, numbers as floats' text."""
    found = []
    for change in etree.parse(str(path)).iter("LaneChangeAction"):
        dynamics = change.find("LaneChangeActionDynamics")
        target = change.find("LaneChangeTarget/*")
        found.append(
            {
                "offset": str(float(change.get("targetLaneOffset", "0"))),
                "shape": dynamics.get("dynamicsShape"),
                "distance": str(float(dynamics.get("value"))),
                "target": target.tag,
                "entity": str(target.get("entityRef")),
                "value": target.get("value"),
            }
        )
    return found


def test_the_lane_changes_are_mapped_with_their_targets() -> None:
    imported = import_file(LANE_CHANGES)
    assert imported.report.counts()["opaque"] == 0
    cut_in, onward = sorted(
        (n for n in imported.scenario.nodes if n.eClass.name == "LaneChange"),
        key=lambda n: str(n.name),
    )
    assert (cut_in.targetActor.name, cut_in.lanes, cut_in.targetLane) == ("Ego", 0, None)
    assert (cut_in.shape.name, cut_in.targetOffset.value, cut_in.distance.value) == (
        "cubic",
        0.5,
        40.0,
    )
    assert (onward.targetLane, onward.shape.name, onward.targetActor) == (-3, "linear", None)


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_the_lane_changes_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    first = import_file(LANE_CHANGES)
    exported = tmp_path / "lane-changes.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=LANE_CHANGES)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    assert (
        _changes(exported)
        == _changes(LANE_CHANGES)
        == [
            {
                "offset": "0.5",
                "shape": "cubic",
                "distance": "40.0",
                "target": "RelativeTargetLane",
                "entity": "Ego",
                "value": "0",
            },
            {
                "offset": "0.0",
                "shape": "linear",
                "distance": "30.0",
                "target": "AbsoluteTargetLane",
                "entity": "None",
                "value": "-3",
            },
        ]
    )
    again = import_file(exported, allow=[FILES]).scenario
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_a_change_by_two_lanes_keeps_its_count(tmp_path: Path) -> None:
    text = LANE_CHANGES.read_text().replace(
        '<RelativeTargetLane entityRef="Ego" value="0"/>',
        '<RelativeTargetLane entityRef="Target" value="-2"/>',
    )
    two = tmp_path / "two.xosc"
    two.write_text(text)
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    (change,) = [n for n in import_file(two).scenario.nodes if n.name == "CutInEvent"]
    assert (change.direction.name, change.lanes, change.targetActor) == ("right", 2, None)
    exported = tmp_path / "out.xosc"
    export_to_file(import_file(two).scenario, exported, version="1.3", source_path=two)
    assert _changes(exported)[0]["entity"] == "Target"
    assert _changes(exported)[0]["value"] == "-2"

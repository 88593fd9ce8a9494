"""Lane changes given in time (release 1.5's LaneChange.duration): the hand-written file
imports with each change's seconds kept, nothing opaque and nothing guessed, exports back
XSD-valid at every version with the same `dynamicsDimension="time"` and value, and imports
again to the same scenario; the carla profile, whose parser reads a distance only, refuses it."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import ExportError, export, export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.model.build import ScenarioBuilder, lane
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
TIMED = FILES / "lane-change-time.xosc"


def _dynamics(path: Path) -> list[tuple[str | None, str | None, float]]:
    """Each LaneChangeAction's shape, dimension and value, in file order."""
    return [
        (d.get("dynamicsShape"), d.get("dynamicsDimension"), float(d.get("value", "nan")))
        for d in etree.parse(str(path)).iter("LaneChangeActionDynamics")
    ]


def _changes(imported_nodes: list[object]) -> dict[str, object]:
    return {n.name: n for n in imported_nodes if type(n).__name__ == "LaneChange"}  # type: ignore[attr-defined]


def test_a_change_given_in_time_keeps_its_seconds() -> None:
    imported = import_file(TIMED)
    assert imported.report.counts()["opaque"] == 0
    # The only guess is which actor is the ego (by its name): no metres at a guessed speed.
    assert [e.message for e in imported.report.section("guessed")] == ["ego: 'Ego', by its name"]
    changes = _changes(list(imported.scenario.nodes))
    cut_in, onward = changes["CutInEvent"], changes["OnwardEvent"]
    assert (cut_in.distance, cut_in.duration.value, cut_in.shape.name) == (None, 3.0, "sinusoidal")
    assert (onward.distance, onward.duration.value, onward.shape.name) == (None, 2.5, "linear")


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_a_change_given_in_time_exports_as_time(version: str, tmp_path: Path, same) -> None:
    first = import_file(TIMED)
    exported = tmp_path / "lane-change-time.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=TIMED)
    assert schema.validate_tree(schema.parse_file(exported)) == []
    assert (
        _dynamics(exported)
        == _dynamics(TIMED)
        == [("sinusoidal", "time", 3.0), ("linear", "time", 2.5)]
    )
    again = import_file(exported, allow=[FILES]).scenario
    # The export writes the default environment where the file had none: not this test's matter.
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_a_change_given_by_distance_still_exports_as_distance(tmp_path: Path) -> None:
    imported = import_file(TIMED)
    change = _changes(list(imported.scenario.nodes))["CutInEvent"]
    change.duration = None  # unset: the language's default distance, 30 m
    exported = tmp_path / "distance.xosc"
    export_to_file(imported.scenario, exported, version="1.1", source_path=TIMED)
    assert _dynamics(exported)[0] == ("sinusoidal", "distance", 30.0)


def test_the_carla_profile_refuses_a_change_given_in_time() -> None:
    b = ScenarioBuilder("Timed", map="map.xodr", level="concrete", date="2026-01-01T00:00:00")
    ego = b.actor("Car", "ego", ego=True, start=lane("3", 1, 30.0), speed=5.0)
    change = b.add("LaneChange", ego, duration=3.0)
    b.chain(b.root, change, b.end)
    with pytest.raises(ExportError) as caught:
        export(b.scenario, version="1.0", profile="carla", town="Town03")
    (refusal,) = caught.value.diagnostics
    assert (refusal.code, refusal.path) == ("SCEML-E008", "LaneChange_1")
    assert "carla profile: a lane change given in time" in refusal.message
    change.duration, change.distance = None, scm.Value(value=40.0)
    carla = export(b.scenario, version="1.0", profile="carla", town="Town03")
    dynamics = carla.find(".//LaneChangeActionDynamics")
    assert (dynamics.get("dynamicsDimension"), float(dynamics.get("value"))) == ("distance", 40.0)

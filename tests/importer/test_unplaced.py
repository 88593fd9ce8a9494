"""Entities the file gives no start, read as esmini reads them (issue 24).

A SUMO controller's template entity (`cut-in_sumo`, `sumo-test`) is never placed by esmini:
before, it was an actor without a start (SCEML-E002, exit 1); now it is no actor, and the
report says what is not represented. An actor whose trajectory starts at t = 0 with no Init
position (`parking_demo`'s Man1) starts where esmini puts it, the trajectory's first point.
An Init trajectory followed in time (`bicycle_fall_over`) stays opaque: FollowTrajectory has no
timing, and followed at the actor's speed it rode 30 m on.
"""

from __future__ import annotations

from pathlib import Path

from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model.loading import load
from sceml.validation import validate

FILES = Path(__file__).resolve().parent / "files"


def _actors(scenario: scm.Scenario) -> dict[str, scm.Actor]:
    (root,) = [n for n in scenario.nodes if isinstance(n, scm.RootNode)]
    return {str(a.name): a for a in root.actors}


def _export(tmp_path: Path, name: str) -> etree._Element:
    model = tmp_path / f"{name}.xmi"
    import_to_file(FILES / f"{name}.xosc", model)
    exported = tmp_path / f"{name}.xosc"
    export_to_file(load(model).root, exported, version="1.1", source_path=model)
    return etree.parse(str(exported)).getroot()


def test_a_sumo_template_entity_is_no_actor_and_the_report_says_so() -> None:
    imported = import_file(FILES / "sumo-template.xosc")
    assert set(_actors(imported.scenario)) == {"Ego"}
    (entry,) = imported.report.section("not represented")
    assert entry.line == 23
    assert "'SumoTraffic'" in entry.message and "SUMO" in entry.message
    codes = {d.code for d in validate(imported.scenario) if d.severity.name == "ERROR"}
    assert codes == set()


def test_a_sumo_template_the_storyboard_uses_stays_an_actor(tmp_path: Path) -> None:
    text = (FILES / "sumo-template.xosc").read_text()
    used = text.replace(
        '<Actors selectTriggeringEntities="false"><EntityRef entityRef="Ego"/>',
        '<Actors selectTriggeringEntities="false"><EntityRef entityRef="SumoTraffic"/>',
    )
    assert used != text
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    (tmp_path / "sumo-template.xosc").write_text(used)
    imported = import_file(tmp_path / "sumo-template.xosc")
    assert set(_actors(imported.scenario)) == {"Ego", "SumoTraffic"}
    assert imported.report.section("not represented") == []


def test_a_controller_named_sumo_controller_without_the_property_is_sumos(
    tmp_path: Path,
) -> None:
    # esmini takes the controller's name as its type when esminiController is missing.
    text = (FILES / "sumo-template.xosc").read_text()
    named = text.replace('<Property name="esminiController" value="SumoController"/>', "").replace(
        '<Controller name="SumoTraffic">', '<Controller name="SumoController">'
    )
    assert "esminiController" not in named and 'name="SumoController"' in named
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    (tmp_path / "sumo-template.xosc").write_text(named)
    assert set(_actors(import_file(tmp_path / "sumo-template.xosc").scenario)) == {"Ego"}


def test_a_sumo_template_is_not_exported(tmp_path: Path) -> None:
    root = _export(tmp_path, "sumo-template")
    assert [o.get("name") for o in root.iter("ScenarioObject")] == ["Ego"]


def test_an_actor_without_start_starts_where_its_first_trajectory_begins() -> None:
    imported = import_file(FILES / "trajectory-start.xosc")
    walker = _actors(imported.scenario)["Walker"]
    start = walker.startPosition
    assert isinstance(start, scm.RoadPosition)
    assert (start.roadId, start.s.value, start.t.value) == ("1", 20.0, -10.0)
    (walk,) = [n for n in imported.scenario.nodes if isinstance(n, scm.FollowTrajectory)]
    # The start left the trajectory: it is driven from where the walker stands.
    assert [(p.s.value, p.t.value) for p in walk.waypoints] == [(30.0, -10.0), (30.0, -4.0)]
    assert [type(flow.source) for flow in walk.incoming] == [scm.RootNode]
    assert "SCEML-E002" not in {d.code for d in validate(imported.scenario)}
    assert any("first point of Walk" in e.message for e in imported.report.section("mapped"))


def test_the_derived_start_exports_as_the_trajectory_the_file_had(tmp_path: Path) -> None:
    root = _export(tmp_path, "trajectory-start")
    (start,) = root.iterfind(".//Private[@entityRef='Walker']//TeleportAction//RoadPosition")
    assert (start.get("s"), start.get("t")) == ("20.0", "-10.0")
    (polyline,) = root.iter("Polyline")
    vertices = [v.find("Position/*") for v in polyline.iterfind("Vertex")]
    assert [v.tag for v in vertices] == ["RelativeObjectPosition", "RoadPosition", "RoadPosition"]
    assert vertices[0].get("entityRef") == "Walker"
    assert [(v.get("s"), v.get("t")) for v in vertices[1:]] == [("30.0", "-10.0"), ("30.0", "-4.0")]


def test_the_derived_start_comes_back_the_same(tmp_path: Path) -> None:
    _export(tmp_path, "trajectory-start")
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    again = import_file(tmp_path / "trajectory-start.xosc").scenario
    start = _actors(again)["Walker"].startPosition
    assert (start.roadId, start.s.value, start.t.value) == ("1", 20.0, -10.0)
    (walk,) = [n for n in again.nodes if isinstance(n, scm.FollowTrajectory)]
    assert [(p.s.value, p.t.value) for p in walk.waypoints] == [(30.0, -10.0), (30.0, -4.0)]


def test_an_actor_with_no_start_and_no_trajectory_keeps_no_start() -> None:
    imported = import_file(FILES / "no-start.xosc")
    assert _actors(imported.scenario)["Parked"].startPosition is None


def test_a_timed_trajectory_stays_opaque_and_gives_the_start(tmp_path: Path) -> None:
    imported = import_file(FILES / "timed-trajectory.xosc")
    cyclist = _actors(imported.scenario)["Cyclist"]
    assert isinstance(cyclist.startPosition, scm.LanePosition)
    assert cyclist.startPosition.s.value == 100.0
    assert [n for n in imported.scenario.nodes if isinstance(n, scm.FollowTrajectory)] == []
    (opaque,) = [n for n in imported.scenario.nodes if isinstance(n, scm.OpaqueAction)]
    assert "<Timing" in opaque.xml
    root = _export(tmp_path, "timed-trajectory")
    (timing,) = root.iter("Timing")
    assert (timing.get("domainAbsoluteRelative"), timing.get("scale")) == ("relative", "1")
    times = [v.get("time") for v in next(root.iter("Polyline")).iterfind("Vertex")]
    assert times == ["0", "2", "2.5", "3.5", "4"]

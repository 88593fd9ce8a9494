"""An OpenSCENARIO trajectory begins at its first vertex (release 1.5's
FollowTrajectory.fromFirstWaypoint): players put the actor there when the action starts, so the
import keeps that vertex as where the path begins and the export writes the polyline as the
file had it, with no vertex at the actor added before it (`pedestrian_traj_synch`: the ego's
path from where it was, 0.5 m past the first vertex by then, drove 0.5 m apart in esmini).
SceML's own exports, which begin at the actor itself, come back as they were."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model.build import ScenarioBuilder, world
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
WALK = FILES / "trajectory-follow-mode.xosc"


def vertices(path: Path) -> list[tuple[str, ...]]:
    """Each Polyline vertex's position: its kind and its coordinates as numbers."""
    found = []
    for vertex in etree.parse(str(path)).iter("Vertex"):
        (position,) = vertex.find("Position")
        keys = [k for k in ("x", "y", "entityRef", "dx", "dy") if position.get(k) is not None]
        found.append(
            (
                str(position.tag),
                *(
                    position.get(k) if k == "entityRef" else repr(float(position.get(k)))
                    for k in keys
                ),
            )
        )
    return found


def test_a_trajectory_that_begins_elsewhere_keeps_its_first_vertex() -> None:
    (walk,) = [n for n in import_file(WALK).scenario.nodes if n.eClass.name == "FollowTrajectory"]
    assert walk.fromFirstWaypoint is True
    assert [(p.x.value, p.y.value) for p in walk.waypoints] == [(-4.5, -14.0), (4.5, -14.0)]


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.3"))
def test_it_exports_the_polyline_as_the_file_had_it(version: str, tmp_path: Path, same) -> None:
    assert vertices(WALK) == [
        ("WorldPosition", "-4.5", "-14.0"),
        ("WorldPosition", "4.5", "-14.0"),
    ]
    first = import_file(WALK)
    exported = tmp_path / "walk.xosc"
    export_to_file(first.scenario, exported, version=version, source_path=WALK)
    assert schema.validate_file(exported, version) == []
    assert vertices(exported) == vertices(WALK)
    again = import_file(exported, allow=[FILES]).scenario
    (walk,) = [n for n in again.nodes if n.eClass.name == "FollowTrajectory"]
    assert walk.fromFirstWaypoint is True


def test_a_sceml_trajectory_still_begins_at_the_actor(tmp_path: Path) -> None:
    b = ScenarioBuilder("walk", map=str(FILES / "highway.xodr"), level="concrete")
    ped = b.actor("Pedestrian", "ped", ego=True, start=world(0.0, 0.0, h=0.0), speed=1.5)
    walk = b.add("FollowTrajectory", ped, waypoints=[world(5.0, 0.0), world(5.0, 5.0)])
    b.chain(b.root, walk, b.end)
    exported = tmp_path / "own.xosc"
    export_to_file(b.scenario, exported, version="1.3")
    assert vertices(exported) == [
        ("RelativeObjectPosition", "ped", "0.0", "0.0"),
        ("WorldPosition", "5.0", "0.0"),
        ("WorldPosition", "5.0", "5.0"),
    ]
    (again,) = [
        n for n in import_file(exported).scenario.nodes if n.eClass.name == "FollowTrajectory"
    ]
    assert again.fromFirstWaypoint is False
    assert len(again.waypoints) == 2

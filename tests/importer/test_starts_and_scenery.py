"""Starts that esmini takes from an Init trajectory, and places with no roads (issue 24).

esmini puts an actor that has no TeleportAction at the first point of its Init trajectory
(bicycle_fall_over, follow_trajectory_by_front_axle, lane-change_trajectory_wp: before, the
import left such an actor without a start, SCEML-E002, and nothing exported). A scenario whose
RoadNetwork is only a SceneGraphFile (esmini's parking lot) has no roads; the scene graph is its
map and every position a world position (before: SCEML-E001, "needs a map").
"""

from __future__ import annotations

from pathlib import Path

from importer.test_reading_as_esmini import actor, scenario

import scemlmodel as scm
from sceml.export import export
from sceml.importer import import_file
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.validation import validate

VERTEX = '<Vertex time="{t}"><Position><WorldPosition x="{x}" y="{y}" h="0"/></Position></Vertex>'


def _trajectory(shape: str) -> str:
    return (
        '<Private entityRef="Ego"><PrivateAction><LongitudinalAction><SpeedAction>'
        '<SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/>'
        '<SpeedActionTarget><AbsoluteTargetSpeed value="5"/></SpeedActionTarget></SpeedAction>'
        "</LongitudinalAction></PrivateAction><PrivateAction><RoutingAction>"
        '<FollowTrajectoryAction><Trajectory closed="false" name="T"><Shape>'
        f"{shape}</Shape></Trajectory><TimeReference><None/></TimeReference>"
        '<TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction>'
        "</RoutingAction></PrivateAction></Private>"
    )


def test_an_init_trajectory_gives_the_start_and_a_follow_trajectory(tmp_path: Path) -> None:
    points = [(100.0, -5.25), (150.0, -5.25), (200.0, -1.75)]
    polyline = "".join(VERTEX.format(t=i, x=x, y=y) for i, (x, y) in enumerate(points))
    imported = import_file(scenario(tmp_path, init=_trajectory(f"<Polyline>{polyline}</Polyline>")))
    ego = actor(imported.scenario, "Ego")
    assert isinstance(ego.startPosition, scm.WorldPosition)
    assert (ego.startPosition.x.value, ego.startPosition.y.value) == points[0]
    assert ego.initialSpeed.value == 5.0
    (follow,) = [n for n in imported.scenario.nodes if isinstance(n, scm.FollowTrajectory)]
    # The first point is the start itself; the node drives through the others, from the root.
    assert [(p.x.value, p.y.value) for p in follow.waypoints] == points[1:]
    assert [type(flow.source) for flow in follow.incoming] == [scm.RootNode]
    assert "SCEML-E002" not in {d.code for d in validate(imported.scenario)}


def test_a_nurbs_init_trajectory_starts_at_its_first_control_point(tmp_path: Path) -> None:
    controls = "".join(
        f'<ControlPoint weight="1"><Position><WorldPosition x="{x}" y="-5.25"/></Position>'
        "</ControlPoint>"
        for x in (120, 130, 140)
    )
    knots = "".join(f'<Knot value="{k}"/>' for k in (0, 0, 0, 1, 1, 1))
    nurbs = f'<Nurbs order="3">{controls}{knots}</Nurbs>'
    imported = import_file(scenario(tmp_path, init=_trajectory(nurbs)))
    start = actor(imported.scenario, "Ego").startPosition
    assert (start.x.value, start.y.value) == (120.0, -5.25)
    # SceML has no NURBS: the trajectory itself stays as it was read, run from the start.
    (kept,) = [n for n in imported.scenario.nodes if isinstance(n, scm.OpaqueAction)]
    assert "<Nurbs" in kept.xml and [type(f.source) for f in kept.incoming] == [scm.RootNode]


def test_a_scene_graph_without_roads_is_the_map_and_exports_back(tmp_path: Path) -> None:
    path = scenario(
        tmp_path,
        init='<Private entityRef="Ego"><PrivateAction><TeleportAction><Position>'
        '<WorldPosition x="10" y="20" h="0"/></Position></TeleportAction></PrivateAction>'
        "</Private>",
    )
    (tmp_path / "models").mkdir()
    (tmp_path / "models" / "lot.osgb").write_bytes(b"\x00scenery")
    text = path.read_text().replace(
        '<LogicFile filepath="highway.xodr"/>', '<SceneGraphFile filepath="models/lot.osgb"/>'
    )
    path.write_text(text)
    imported = import_file(path)
    root = next(n for n in imported.scenario.nodes if isinstance(n, scm.RootNode))
    assert root.map == "models/lot.osgb"
    save(imported.scenario, tmp_path / "lot.xmi")
    (tmp_path / ".sceml-root").touch()
    document = load(tmp_path / "lot.xmi")
    found = {d.code: d.message for d in validate(document.root, document=document)}
    assert set(found) == {"SCEML-R002"}
    assert "scene graph with no roads" in found["SCEML-R002"]
    written = export(
        document.root, source_path=tmp_path / "lot.xmi", output_path=tmp_path / "x.xosc"
    )
    network = written.getroot().find("RoadNetwork")
    assert [(e.tag, e.get("filepath")) for e in network] == [("SceneGraphFile", "models/lot.osgb")]

"""Release 1.5's settings on the boxes and in the editor: a Follow's or Approach's box says how
it measures and what limits it states, and only that (a Follow with the defaults stays the box it
was); a trajectory's box says when it begins at its first waypoint."""

from __future__ import annotations

import scemlmodel as scm
from sceml.editor.fields import node_fields
from sceml.model.build import ScenarioBuilder, world
from sceml.render.labels import Scope, action_lines


def follow(**settings: object) -> scm.Follow:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    node: scm.Follow = b.add("Follow", ego, target=lead, name="follow", **settings)
    return node


def test_a_follow_with_the_defaults_keeps_its_box() -> None:
    assert action_lines(follow(distance=12.0), Scope()) == ["ego, target lead", "distance: 12 m"]


def test_a_follow_shows_its_measure_side_and_limits() -> None:
    node = follow(
        distance=12.0, freespace=True, displacement="leading", maxAcceleration=4.0, maxSpeed=30.0
    )
    lines = action_lines(node, Scope())
    assert lines[1] == "measured: bounding boxes"
    assert "displacement: leading" in lines
    assert "maxAcceleration: 4 m/s²" in lines
    assert any(line.startswith("maxSpeed: 30 m/s") for line in lines)
    assert not any(line.startswith(("freespace", "maxDeceleration")) for line in lines)


def test_a_time_gap_replaces_the_distance_on_the_box() -> None:
    lines = action_lines(follow(timeGap=1.5), Scope())
    assert lines == ["ego, target lead", "timeGap: 1.5 s"]


def test_the_editor_offers_the_measure_and_limits_as_fields() -> None:
    fields = {f["name"]: f for f in node_fields(follow(distance=12.0))}
    assert fields["freespace"]["type"] == "bool" and fields["freespace"]["value"] is False
    assert fields["displacement"]["options"] == ["trailing", "leading", "any"]
    assert fields["displacement"]["value"] == "trailing"
    for name in ("maxAcceleration", "maxDeceleration", "maxSpeed", "timeGap"):
        assert name in fields
    assert fields["maxAccelerationRate"]["unit"] == "m/s3"


def test_a_trajectory_box_says_when_it_begins_at_its_first_waypoint() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ped = b.actor("Pedestrian", "ped", ego=True, start=world(0.0, 0.0), speed=1.5)
    points = [world(5.0, 0.0), world(5.0, 5.0)]
    own = b.add("FollowTrajectory", ped, waypoints=points)
    imported = b.add("FollowTrajectory", ped, waypoints=points, fromFirstWaypoint=True)
    assert not any("fromFirstWaypoint" in line for line in action_lines(own, Scope()))
    assert "fromFirstWaypoint: True" in action_lines(imported, Scope())
    fields = {f["name"]: f for f in node_fields(imported)}
    assert fields["fromFirstWaypoint"]["type"] == "bool"

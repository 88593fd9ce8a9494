"""A measuring condition's box says how it measures when that is not the default, in one line."""

from __future__ import annotations

import pytest

import scemlmodel as scm
from sceml.editor.errors import OperationError
from sceml.editor.node_ops import attribute_value
from sceml.model.build import ScenarioBuilder, world
from sceml.render.labels import Scope, action_lines


def ttc_lines(**measure: object) -> list[str]:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    return action_lines(b.add("TimeToCollision", ego, target=lead, time=2.0, **measure), Scope())


def test_the_default_measure_adds_no_line() -> None:
    assert ttc_lines() == ["ego, target lead", "rule: lessThan", "time: 2 s"]


def test_a_measure_apart_from_the_default_is_one_line() -> None:
    lines = ttc_lines(freespace=False, relativeDistanceType="longitudinal", coordinateSystem="lane")
    assert lines[1] == "measured: reference points, longitudinal, lane coordinates"
    assert not any(line.startswith(("freespace", "relativeDistanceType")) for line in lines)


def test_the_editor_offers_the_measure_as_fields() -> None:
    from sceml.editor.fields import node_fields
    from sceml.model.build import node_named

    b = ScenarioBuilder("fields", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    b.add("TimeToCollision", ego, target=lead, name="ttc", relativeDistanceType="lateral")
    fields = {f["name"]: f for f in node_fields(node_named(b.scenario, "ttc"))}
    assert fields["freespace"] == {
        "name": "freespace",
        "label": "Freespace",
        "type": "bool",
        "value": True,
    }
    assert fields["relativeDistanceType"]["options"] == ["euclidean", "longitudinal", "lateral"]
    assert fields["relativeDistanceType"]["value"] == "lateral"
    assert fields["coordinateSystem"]["options"] == ["entity", "lane", "road", "trajectory"]
    assert fields["coordinateSystem"]["value"] == "entity"


def test_the_palette_offers_traveled_distance_among_the_conditions() -> None:
    from sceml.editor.palette import node_groups

    conditions = next(g for g in node_groups() if "TimeToCollision" in str(g))
    assert "TraveledDistance" in str(conditions)


def test_a_time_headway_box_shows_its_measure() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    node = b.add("TimeHeadway", ego, target=lead, time=1.5, coordinateSystem="road")
    assert action_lines(node, Scope()) == [
        "ego, target lead",
        "measured: road coordinates",
        "rule: lessThan",
        "time: 1.5 s",
    ]


def test_a_traveled_distance_box_shows_its_distance() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    node = b.add("TraveledDistance", ego, distance=60.0)
    assert action_lines(node, Scope()) == ["ego", "distance: 60 m"]


def test_a_lane_change_box_shows_its_target_lane_offset_and_shape() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    plain = b.add("LaneChange", ego, direction="right")
    assert action_lines(plain, Scope()) == ["ego", "direction: right"]
    into = b.add("LaneChange", ego, target=lead, lanes=0, shape="cubic", targetOffset=0.5)
    assert action_lines(into, Scope()) == [
        "ego, target lead",
        "direction: left",
        "lanes: 0",
        "shape: cubic",
        "targetOffset: 0.5 m",
    ]
    absolute = b.add("LaneChange", ego, targetLane=-3, distance=40.0)
    assert action_lines(absolute, Scope()) == ["ego", "targetLane: -3", "distance: 40 m"]


def test_the_editor_sets_a_lane_change_target_lane_from_its_text_field() -> None:
    feature = scm.LaneChange.eClass.findEStructuralFeature
    assert attribute_value(feature("targetLane"), "-3") == -3
    assert attribute_value(feature("targetLane"), "") is None
    assert attribute_value(feature("lanes"), 2) == 2
    for wrong in ("two", True, 1.5):
        with pytest.raises(OperationError, match="whole number"):
            attribute_value(feature("lanes"), wrong)


def radius_lines(**measure: object) -> list[str]:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    return action_lines(b.add("InVehicleRadius", ego, target=lead, radius=12.0, **measure), Scope())


def test_an_in_vehicle_radius_box_stays_as_it_was_with_its_defaults() -> None:
    # Between the reference points and "within" are what InVehicleRadius always meant.
    assert radius_lines() == ["ego, target lead", "radius: 12 m"]


def test_an_in_vehicle_radius_box_shows_a_measure_and_rule_apart_from_its_defaults() -> None:
    lines = radius_lines(freespace=True, relativeDistanceType="longitudinal", rule="greaterThan")
    assert lines == [
        "ego, target lead",
        "measured: bounding boxes, longitudinal",
        "rule: greaterThan",
        "radius: 12 m",
    ]


def test_the_editor_offers_an_in_vehicle_radius_its_measure_and_rule() -> None:
    from sceml.editor.fields import node_fields
    from sceml.model.build import node_named

    b = ScenarioBuilder("fields", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    b.add("InVehicleRadius", ego, target=lead, name="close")
    fields = {f["name"]: f for f in node_fields(node_named(b.scenario, "close"))}
    assert fields["freespace"]["value"] is False
    assert fields["relativeDistanceType"]["value"] == "euclidean"
    assert fields["coordinateSystem"]["options"] == ["entity", "lane", "road", "trajectory"]
    assert fields["rule"]["options"] == [
        "greaterThan",
        "lessThan",
        "equalTo",
        "greaterOrEqual",
        "lessOrEqual",
    ]
    assert fields["rule"]["value"] == "lessThan"


def test_release_1_4_boxes_show_what_they_set() -> None:
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    lead = b.actor("Car", "lead", start=world(30.0, 0.0), speed=5.0)
    light = b.add(
        "LightState", ego, lightType="indicatorLeft", mode="flashing", flashingOnDuration=0.4
    )
    # The defaults (lowBeam, on, no transition) are not repeated; a ratio has no unit.
    assert action_lines(light, Scope()) == [
        "ego",
        "lightType: indicatorLeft",
        "mode: flashing",
        "flashingOnDuration: 0.4 s",
    ]
    keep = b.add(
        "MatchSpeed", ego, target=lead, relation="factor", speedFactor=0.9, continuous=True
    )
    assert action_lines(keep, Scope()) == [
        "ego, target lead",
        "relation: factor",
        "continuous: True",
        "speedFactor: 0.9",
    ]
    braking = b.add("AccelerationCondition", ego, acceleration=-0.9, direction="longitudinal")
    assert action_lines(braking, Scope())[-2:] == [
        "direction: longitudinal",
        "acceleration: -0.9 m/s²",
    ]


def test_the_palette_offers_lights_in_their_own_group() -> None:
    from sceml.editor.palette import node_groups

    groups = {g["group"]: [i["kind"] for i in g["items"]] for g in node_groups()}
    assert groups["appearance"] == ["LightState"]
    assert "MatchSpeed" in groups["longitudinal"]
    assert {"StandStill", "AccelerationCondition"} <= set(groups["condition"])


def test_a_speed_change_shows_its_shape_only_when_it_is_not_linear() -> None:
    # A speed change's shape (release 1.4) defaults to linear, a lane change's to sinusoidal:
    # each box stays quiet at its own kind's default.
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=10.0)
    plain = b.add("Accelerate", ego, targetSpeed=20.0, rate=2.0)
    cubic = b.add("Accelerate", ego, targetSpeed=25.0, rate=2.0, shape="cubic")
    assert action_lines(plain, Scope()) == [
        "ego",
        "targetSpeed: 20 m/s = 72 km/h",
        "rate: 2 m/s²",
    ]
    assert "shape: cubic" in action_lines(cubic, Scope())
    lane_change = b.add("LaneChange", ego, direction="left", shape="linear")
    assert "shape: linear" in action_lines(lane_change, Scope())


def test_trailer_coupling_boxes_say_what_they_tow() -> None:
    # Release 1.5: the trailer is the target actor, but the box reads as what the node does.
    b = ScenarioBuilder("labels", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=0.0)
    trailer = b.actor("Truck", "trailer", start=world(-4.45, 0.0), speed=0.0)
    connect = b.add("ConnectTrailer", ego, target=trailer)
    assert action_lines(connect, Scope()) == ["ego", "tows: trailer"]
    assert action_lines(b.add("DisconnectTrailer", ego), Scope()) == [
        "ego",
        "uncouples its trailer",
    ]


def test_the_palette_offers_trailer_couplings_in_their_own_group() -> None:
    from sceml.editor.palette import node_groups

    groups = {g["group"]: g for g in node_groups()}
    assert [i["kind"] for i in groups["coupling"]["items"]] == [
        "ConnectTrailer",
        "DisconnectTrailer",
    ]
    assert groups["coupling"]["label"] == "Trailer couplings"


def test_the_editor_offers_a_connect_its_trailer_and_a_disconnect_none() -> None:
    from sceml.editor.fields import node_fields
    from sceml.model.build import node_named

    b = ScenarioBuilder("fields", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=0.0)
    trailer = b.actor("Truck", "trailer", start=world(-4.45, 0.0), speed=0.0)
    b.add("ConnectTrailer", ego, target=trailer, name="couple")
    b.add("DisconnectTrailer", ego, name="uncouple")
    couple = {f["name"]: f.get("value") for f in node_fields(node_named(b.scenario, "couple"))}
    assert couple["targetActor"] == "trailer" and couple["referenceActor"] == "ego"
    uncouple = [f["name"] for f in node_fields(node_named(b.scenario, "uncouple"))]
    assert "targetActor" not in uncouple

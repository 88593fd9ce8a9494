"""A measuring condition holds when the distance its node names crosses the threshold: worked
out by hand on straight lines at constant speeds (no map, boxes 4 m x 2 m, 0.05 s steps; the
node is activated at 0.05 s, one flow after the root)."""

from __future__ import annotations

import pytest

from sceml.model.build import ScenarioBuilder, world
from sceml.simulate import simulate

SIZE = {"length": 4.0, "width": 2.0}


def ttc_run(lead_y: float, **measure: object) -> tuple[float | None, tuple[str, ...]]:
    """Ego at 20 m/s from x = 0, the lead at 10 m/s from x = 50.25 (y = lead_y), both heading
    east: when `TTC < 3 s` (ego towards the lead) finishes, and the run's notes."""
    b = ScenarioBuilder("ttc", level="concrete", max_duration=6.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=20.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(50.25, lead_y, h=0.0), speed=10.0, **SIZE)
    ttc = b.add("TimeToCollision", ego, target=lead, time=3.0, rule="lessThan", **measure)
    b.chain(b.root, ttc, b.end)
    run = simulate(b.scenario)
    return run.node(str(ttc.name)).finished, run.notes


def test_between_the_boxes_by_default() -> None:
    # Gap 50.25 - 2 - 2 = 46.25 m closing at 10 m/s: below 30 m (3 s) after 1.625 s.
    assert ttc_run(0.0)[0] == pytest.approx(1.65)


def test_between_the_reference_points_without_freespace() -> None:
    # 50.25 m closing at 10 m/s: below 30 m after 2.025 s.
    assert ttc_run(0.0, freespace=False)[0] == pytest.approx(2.05)


def test_a_lateral_distance_is_the_gap_across() -> None:
    # 3.5 m to the side: 1.5 m between the boxes' sides over 10 m/s is 0.15 s at once (at
    # its activation at 0 s), where the straight-line gap takes until its 30 m as before.
    assert ttc_run(3.5, relativeDistanceType="lateral")[0] == pytest.approx(0.0)
    straight = ttc_run(3.5)[0]
    assert straight is not None and straight > 1.5


def test_a_longitudinal_distance_ignores_the_side_offset() -> None:
    # 50.25 m ahead less the half lengths, 46.25 m, whatever the 10 m to the side: as in line.
    assert ttc_run(10.0, relativeDistanceType="longitudinal")[0] == pytest.approx(1.65)
    # The straight line to a box 10 m aside (8 m between sides) reaches 30 m later:
    # 46.25 - 10 t = sqrt(30^2 - 8^2) = 28.91 m at 1.734 s.
    assert ttc_run(10.0)[0] == pytest.approx(1.75)


def test_road_coordinates_are_measured_in_the_actor_frame_and_said() -> None:
    finished, notes = ttc_run(0.0, coordinateSystem="road")
    assert finished == pytest.approx(1.65)
    assert any("no road coordinates" in note for note in notes)


def test_traveled_distance_counts_from_the_start_not_from_the_activation() -> None:
    # The ego drives 10 m/s from t = 0; the condition is activated after a 2 s wait (at
    # 2 s, when 20 m are driven: the wait is its trigger's delay, no step of its own, and the
    # root's flow costs none) and holds once 30 m are: at 3.0 s. From its activation it would
    # be 5 s.
    b = ScenarioBuilder("traveled", level="concrete", max_duration=8.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=10.0, **SIZE)
    wait = b.add("TimeElapsed", ego, duration=2.0)
    traveled = b.add("TraveledDistance", ego, distance=30.0)
    b.chain(b.root, wait, traveled, b.end)
    run = simulate(b.scenario)
    assert run.node(str(traveled.name)).started == pytest.approx(2.0)
    assert run.node(str(traveled.name)).finished == pytest.approx(3.0)


def test_traveled_distance_of_a_standing_actor_never_holds() -> None:
    b = ScenarioBuilder("standing", level="concrete", max_duration=3.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=0.0, **SIZE)
    traveled = b.add("TraveledDistance", ego, distance=1.0)
    b.chain(b.root, traveled, b.end)
    assert simulate(b.scenario).node(str(traveled.name)).finished is None


def headway_run(lead_x: float, ego_speed: float, **measure: object) -> float | None:
    """Ego at `ego_speed` from x = 0, the lead standing at `lead_x`: when `headway < 2 s`
    (ego to the lead) finishes."""
    b = ScenarioBuilder("headway", level="concrete", max_duration=6.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=ego_speed, **SIZE)
    lead = b.actor("Car", "lead", start=world(lead_x, 0.0, h=0.0), speed=0.0, **SIZE)
    headway = b.add("TimeHeadway", ego, target=lead, time=2.0, rule="lessThan", **measure)
    b.chain(b.root, headway, b.end)
    return simulate(b.scenario).node(str(headway.name)).finished


def test_time_headway_is_the_distance_over_the_actor_speed() -> None:
    # 60.25 - 4 = 56.25 m between the boxes at 10 m/s: below 20 m (2 s) after 3.625 s.
    assert headway_run(60.25, 10.0) == pytest.approx(3.65)
    # Between the centres: 60.25 m, below 20 m after 4.025 s.
    assert headway_run(60.25, 10.0, freespace=False) == pytest.approx(4.05)


def test_time_headway_to_a_target_behind_never_holds() -> None:
    # The lead is 30 m behind: undefined, though 26 m at 20 m/s would be 1.3 s.
    assert headway_run(-30.0, 20.0) is None


def distance_run(lead_y: float, radius: float, **measure: object) -> float | None:
    """Ego at 20 m/s from x = 0, the lead at 10 m/s from x = 50.25 (y = lead_y), both heading
    east: when the ego's InVehicleRadius to the lead finishes."""
    b = ScenarioBuilder("distance", level="concrete", max_duration=6.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=20.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(50.25, lead_y, h=0.0), speed=10.0, **SIZE)
    close = b.add("InVehicleRadius", ego, target=lead, radius=radius, **measure)
    b.chain(b.root, close, b.end)
    return simulate(b.scenario).node(str(close.name)).finished


def test_in_vehicle_radius_is_between_the_reference_points_by_default() -> None:
    # 50.25 m closing at 10 m/s: within 30 m after 2.025 s.
    assert distance_run(0.0, 30.0) == pytest.approx(2.05)
    # 10 m aside: the straight line is within 30 m once 50.25 - 10 t = sqrt(30^2 - 10^2) =
    # 28.28 m, after 2.197 s.
    assert distance_run(10.0, 30.0) == pytest.approx(2.2)


def test_in_vehicle_radius_longitudinal_between_the_boxes() -> None:
    # 50.25 m ahead less the half lengths, 46.25 m, whatever the 10 m aside: within 30 m
    # after 1.625 s.
    measure = {"freespace": True, "relativeDistanceType": "longitudinal"}
    assert distance_run(10.0, 30.0, **measure) == pytest.approx(1.65)


def test_in_vehicle_radius_lateral_is_the_gap_across() -> None:
    # 3.5 m aside, 1.5 m between the boxes' sides: within 2 m at once, at t = 0 (a flow out of
    # the root costs no step).
    measure = {"freespace": True, "relativeDistanceType": "lateral"}
    assert distance_run(3.5, 2.0, **measure) == pytest.approx(0.0)
    # Between the reference points 3.5 m is not within 2 m, and never gets so.
    assert distance_run(3.5, 2.0, relativeDistanceType="lateral") is None


def test_in_vehicle_radius_beyond_the_radius_with_greater_than() -> None:
    # The lead 10 m behind at 10 m/s, the ego pulling away at 20 m/s: 10 + 10 t > 25 after
    # 1.5 s (not before: the first step past it is 1.55 s).
    # The lead 50.25 m ahead is beyond 25 m at once (t = 0); "within" would wait until 2.55 s.
    assert distance_run(0.0, 25.0, rule="greaterThan") == pytest.approx(0.0)
    assert distance_run(0.0, 25.0) == pytest.approx(2.55)
    b = ScenarioBuilder("beyond", level="concrete", max_duration=6.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=20.0, **SIZE)
    lead = b.actor("Car", "lead", start=world(-10.0, 0.0, h=0.0), speed=10.0, **SIZE)
    far = b.add("InVehicleRadius", ego, target=lead, radius=25.0, rule="greaterThan")
    b.chain(b.root, far, b.end)
    assert simulate(b.scenario).node(str(far.name)).finished == pytest.approx(1.55)


def test_the_gap_between_the_boxes_is_found_only_where_it_is_measured(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Finding the gap between two boxes was 60-70 % of a preview of UIS2, whose radius checks
    # measure between the reference points (issue 31): it is only worked out for freespace.
    from sceml.simulate import conditions

    calls: list[int] = []
    found = conditions.free_distance_now

    def counted(a: conditions.Actor, b: conditions.Actor) -> float:
        calls.append(1)
        return found(a, b)

    monkeypatch.setattr(conditions, "free_distance_now", counted)
    assert ttc_run(0.0, freespace=False)[0] == pytest.approx(2.05)
    assert calls == []
    assert ttc_run(0.0)[0] == pytest.approx(1.65)
    assert calls

"""The one definition of each maneuver's meaning, on numbers worked out by hand."""

from __future__ import annotations

import math

import pytest

import scemlmodel as scm
from sceml.players import meaning
from sceml.players.goals import goal_problems
from sceml.players.record import PlayerRun


def test_drive_distance_lasts_distance_over_speed() -> None:
    assert meaning.drive_distance_duration(20.0, 8.0) == 2.5
    assert math.isinf(meaning.drive_distance_duration(20.0, 0.0))


def test_follow_counts_the_gap_reached_within_its_slack() -> None:
    assert meaning.follow_slack(5.0) == 1.0  # at least a metre
    assert meaning.follow_slack(30.0) == 3.0  # else a tenth
    assert meaning.follow_reached(15.9, 15.0) and not meaning.follow_reached(16.6, 15.0)


def test_approach_counts_the_gap_reached_within_half_a_metre_either_side() -> None:
    assert meaning.approach_reached(10.4, 10.0) and meaning.approach_reached(9.6, 10.0)
    assert not meaning.approach_reached(10.6, 10.0)


def test_gap_keeping_is_the_players_spring_within_the_limits() -> None:
    limits = meaning.gap_limits(69.444, 10.0, 10.0)
    assert (limits.acceleration, limits.deceleration) == (3.0, 6.0)
    # 2 m too far, same speed: the deceleration limit sets the tension, 6 * 0.4 = 2.4 1/s2;
    # the spring pulls forward with 2 * 2.4 = 4.8 m/s2, cut to the 3 m/s2 limit.
    assert meaning.gap_acceleration(17.0, 15.0, 0.0, limits) == 3.0
    # 0.5 m too far, 0.5 m/s faster than the target: 0.5 * 2.4 - 0.5 * 2 * sqrt(2.4).
    expected = 0.5 * 2.4 - 0.5 * 2 * math.sqrt(2.4)
    assert meaning.gap_acceleration(15.5, 15.0, 0.5, limits) == pytest.approx(expected)
    # Far too close and closing: the deceleration limit.
    assert meaning.gap_acceleration(5.0, 15.0, 5.0, limits) == -6.0
    # A bicycle brakes at most 5 m/s2 (its performance), not 6.
    assert meaning.gap_limits(11.111, 2.0, 5.0).deceleration == 5.0


def test_time_to_collision_as_players_measure_it() -> None:
    # A follower 15 m (between the boxes) behind a leader 5 m/s slower: 3 s.
    assert meaning.time_to_collision(15.0, (15.0, 0.0), 15.0, (10.0, 0.0), 10.0) == 3.0
    # A standing target: the actor's own speed closes the gap.
    assert meaning.time_to_collision(12.0, (6.0, 0.0), 6.0, (0.0, 0.0), 0.0) == 2.0
    # Head on, 10 and 8 m/s: closing at 18 m/s.
    assert meaning.time_to_collision(36.0, (10.0, 0.0), 10.0, (-8.0, 0.0), 8.0) == 2.0
    # Falling behind, or touching: undefined.
    assert meaning.time_to_collision(15.0, (8.0, 0.0), 8.0, (10.0, 0.0), 10.0) is None
    assert meaning.time_to_collision(0.0, (8.0, 0.0), 8.0, (0.0, 0.0), 0.0) is None


def test_every_maneuver_controls_speed_or_path_and_turns_only_the_path() -> None:
    assert meaning.controls("TurnLeft") == ("path",)  # a route: it leaves the speed alone
    assert meaning.controls("Overtake") == ("speed", "path")
    assert meaning.controls("InLocationRadius") == ()


def test_controller_changes_complete_at_once_and_control_no_domain() -> None:

    for kind in ("ActivateController", "AssignController", "OverrideController"):
        assert meaning.completes_at_once(kind)
        assert meaning.controls(kind) == ()
    assert not meaning.completes_at_once("Accelerate")
    node = scm.ActivateController(name="on", lateral=True)
    run = PlayerRun("esmini")
    # Activated at 1.0 s, its event started at 1.05 s: done in that step, or one step late.
    assert goal_problems(node, (1.0, 1.05), 1.05, run, None) == []
    assert goal_problems(node, (1.0, 1.05), 1.1, run, None) == []
    assert goal_problems(node, (1.0, 1.05), 1.5, run, None) == [
        "at its finish (1.50 s) it took 0.45 s after its start; a controller change completes "
        "at once"
    ]

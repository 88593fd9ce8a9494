"""Extraction from recordings made by hand (closed-form motions on an empty plane, or where
said on maps/intersection.xodr), with the expected maneuvers, parameters and conditions worked
out on paper."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import REPO

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.extract import Recording, Track, extract
from sceml.extract.events import Event
from sceml.extract.longitudinal import end_by_crossings
from sceml.maps import load_map
from sceml.simulate import DEFAULT_STEP
from sceml.validation import validate
from sceml.xosc.meaning import FLOW_DELAY_STEPS

STEP = 0.05
#: What a flow costs in the replay (s): a node starts a step after its predecessor finished.
FLOW = FLOW_DELAY_STEPS * DEFAULT_STEP


def times(duration: float) -> np.ndarray:
    return np.round(np.arange(0.0, duration + STEP / 2, STEP), 6)


def ramp_distance(t: np.ndarray, v0: float, t1: float, t2: float, v1: float) -> np.ndarray:
    """Distance driven from 0 at speed v0, then a linear change to v1 between t1 and t2."""
    rate = (v1 - v0) / (t2 - t1)
    inside = np.clip(t, t1, t2) - t1
    return v0 * np.minimum(t, t1) + v0 * inside + rate * inside**2 / 2 + v1 * np.maximum(t - t2, 0)


def straight(
    name: str, t: np.ndarray, x0: float, y0: float, heading: float, s: np.ndarray
) -> Track:
    return Track(
        name, t, x0 + s * math.cos(heading), y0 + s * math.sin(heading), np.full(t.shape, heading)
    )


def test_a_speed_change_is_one_accelerate_with_its_target_rate_and_start() -> None:
    # 5 m/s until t = 1 s, then +2 m/s² until 9 m/s at t = 3 s.
    t = times(8.0)
    car = straight("ego", t, 0.0, 0.0, 0.0, ramp_distance(t, 5.0, 1.0, 3.0, 9.0))
    found = extract(Recording((car,), "by hand"), check_replay=True)
    (actor,) = found.actors
    assert actor.initial_speed == pytest.approx(5.0, abs=0.02)
    (event,) = actor.maneuvers
    assert event.kind == "Accelerate"
    assert event.start == pytest.approx(1.0, abs=0.05) and event.end == pytest.approx(3.0, abs=0.05)
    assert event.parameters["targetSpeed"] == pytest.approx(9.0, abs=0.02)
    assert event.parameters["rate"] == pytest.approx(2.0, abs=0.05)
    # It waited 1 s with nobody else there: a time, kept while driving as KeepVelocity. The
    # flows into and out of the wait cost a step each, and the Accelerate shows a step before
    # its node starts (it acts in that step): the wait lasts 1 s less one step, and less half
    # a step more, so that a player ends it at the nearest step (0.925 s at 0.05 s steps).
    (wait,) = found.inferred
    assert wait.explanation.kind == "KeepVelocity" and wait.explanation.confidence == "low"
    assert wait.explanation.parameters["duration"] == pytest.approx(
        1.0 - 2 * FLOW + DEFAULT_STEP / 2, abs=0.01
    )
    assert found.replay is not None and found.replay.largest < 0.1


def test_braking_to_a_standstill_is_a_stop() -> None:
    # 10 m/s, braking at 4 m/s² from t = 2 s: standing at t = 4.5 s.
    t = times(7.0)
    car = straight("ego", t, 0.0, 0.0, 0.0, ramp_distance(t, 10.0, 2.0, 4.5, 0.0))
    (actor,) = extract(Recording((car,), "by hand"), check_replay=False).actors
    (event,) = actor.maneuvers
    assert event.kind == "Stop" and event.parameters["rate"] == pytest.approx(4.0, abs=0.1)
    assert event.start == pytest.approx(2.0, abs=0.05)


def test_a_start_when_another_actor_comes_close_is_an_in_vehicle_radius() -> None:
    # The ego drives along y = 0 at 10 m/s from x = 0; a pedestrian waits at (60, -5) and walks
    # north (+1.5 m/s² to 1.5 m/s) once the ego is 15 m away: (60 - 10 t)² + 5² = 15², so at
    # t = 6 - sqrt(200) / 10 = 4.586 s.
    t = times(9.0)
    start = 6.0 - math.sqrt(200.0) / 10.0
    ego = straight("ego", t, 0.0, 0.0, 0.0, 10.0 * t)
    walker = straight(
        "walker", t, 60.0, -5.0, math.pi / 2, ramp_distance(t, 0.0, start, start + 1.0, 1.5)
    )
    # No OpenDRIVE file: a simulator town's name stands for the map, and positions are world ones.
    found = extract(Recording((ego, walker), "by hand"), map_reference="Town01")
    kinds = {a.name: (a.kind, [e.kind for e in a.maneuvers]) for a in found.actors}
    assert kinds == {"ego": ("Car", []), "walker": ("Pedestrian", ["Accelerate", "Cross"])}
    (why,) = found.inferred
    assert (why.actor, why.explanation.kind, why.explanation.target) == (
        "walker",
        "InVehicleRadius",
        "ego",
    )
    assert why.explanation.parameters == {"radius": 15.0}
    assert why.explanation.fires == pytest.approx(start, abs=STEP)
    assert why.explanation.confidence == "medium"  # the ego reaching a place would do as well
    assert found.replay is not None and found.replay.largest < 0.3
    errors = [d for d in validate(found.scenario) if d.severity >= Severity.ERROR]
    assert errors == []


def test_a_start_nothing_explains_is_a_time() -> None:
    # A car 200 m away starts at t = 3 s; the ego, far off, explains nothing.
    t = times(6.0)
    ego = straight("ego", t, 0.0, 0.0, 0.0, 10.0 * t)
    car = straight("car", t, 0.0, 200.0, math.pi, ramp_distance(t, 0.0, 3.0, 5.0, 8.0))
    found = extract(Recording((ego, car), "by hand"))
    (why,) = found.inferred
    assert why.explanation.kind == "TimeElapsed" and why.explanation.confidence == "low"
    assert why.explanation.parameters == {
        "duration": pytest.approx(3.0 - 2 * FLOW + DEFAULT_STEP / 2, abs=0.01)
    }
    graph = found.scenario
    waits = [n for n in graph.nodes if isinstance(n, scm.TimeElapsed)]
    assert [str(n.referenceActor.name) for n in waits] == ["car"]


def test_a_bike_that_turns_onto_a_lane_after_crossing_crossed_to_that_corner() -> None:
    # On maps/intersection.xodr: a bike rides north at 5 m/s along x = 4.5 until (4.5, -10) at
    # 2 s, then straight to the corner (10, 4.5) (15.51 m: 3.10 s), then east along the lane
    # whose centre is y = 4.5, as players go on after a crossing. The bend onto the lane is
    # where the crossing ended, not a second crossing.
    t = times(8.0)
    s = 5.0 * t
    leg = math.hypot(5.5, 14.5)
    on_leg = np.clip(s - 10.0, 0.0, leg) / leg
    after = np.maximum(s - 10.0 - leg, 0.0)
    x = 4.5 + 5.5 * on_leg + after
    y = -20.0 + np.minimum(s, 10.0) + 14.5 * on_leg
    bike = Track("bike", t, x, y, kind="Bicycle")
    ego = straight("ego", t, -40.0, -1.75, 0.0, np.zeros_like(t))
    road_map = load_map(REPO / "maps" / "intersection.xodr")
    found = extract(
        Recording((ego, bike), "by hand"), road_map, map_reference="../maps/intersection.xodr"
    )
    (actor,) = [a for a in found.actors if a.name == "bike"]
    (cross,) = actor.maneuvers
    assert cross.kind == "Cross" and cross.destination is not None
    assert cross.start == pytest.approx(2.0, abs=0.15)
    assert math.hypot(cross.destination[0] - 10.0, cross.destination[1] - 4.5) < 0.3
    assert found.replay is not None and found.replay.largest < 0.5


def noisy(track: Track, seed: int, every: int = 2, sd: float = 0.1) -> Track:
    """The track at every `every`-th sample (10 Hz) with Gaussian position noise of `sd` m."""
    rng = np.random.default_rng(seed)
    t = track.times[::every]
    return Track(
        track.name,
        t,
        track.x[::every] + rng.normal(0.0, sd, len(t)),
        track.y[::every] + rng.normal(0.0, sd, len(t)),
        None if track.heading is None else track.heading[::every],
        kind=track.kind,
    )


def test_a_speed_that_jumps_from_standing_is_a_drive_distance() -> None:
    # Standing until t = 2 s, then 10 m/s at once (a player's step): 60 m by t = 8 s. A ramp at
    # the car's limit would replay up to 10² / (8 x 8) = 1.6 m off; a step replays it as it was.
    t = times(8.0)
    car = straight("ego", t, 0.0, 0.0, 0.0, 10.0 * np.maximum(t - 2.0, 0.0))
    found = extract(Recording((car,), "by hand"))
    (event,) = found.actors[0].maneuvers
    assert event.kind == "DriveDistance"
    assert event.start == pytest.approx(2.0, abs=0.01)
    assert event.parameters["speed"] == pytest.approx(10.0, abs=0.01)
    # It holds that speed to the end of the recording: what it drove from the jump on.
    assert event.parameters["distance"] == pytest.approx(60.0, abs=0.2)
    assert found.replay is not None and found.replay.largest < 0.2


def test_a_jump_under_noise_is_timed_by_all_that_follows_it() -> None:
    # The same jump at 10 Hz with 0.1 m of noise: the step's time and speed are fitted over the
    # six seconds after it, so the replay stays within a metre on every seed.
    t = times(8.0)
    car = straight("ego", t, 0.0, 0.0, 0.0, 10.0 * np.maximum(t - 2.0, 0.0))
    for seed in range(6):
        found = extract(Recording((noisy(car, seed),), "by hand"))
        (event,) = found.actors[0].maneuvers
        assert event.kind == "DriveDistance", seed
        # Fitted to the raw positions: within 5 ms (along the smoothed path it came out 25 to
        # 38 ms early, a step's rounding from setting off a step early).
        assert event.start == pytest.approx(2.0, abs=0.006), seed
        assert event.parameters["speed"] == pytest.approx(10.0, abs=0.05), seed
        assert found.replay is not None and found.replay.largest < 1.0, seed


def test_a_noisy_bike_that_sets_off_straight_does_not_cross() -> None:
    # A bike stands for 1 s, then rides straight north at +1.5 m/s² to 4 m/s. With 0.1 m of
    # noise at 10 Hz its first headings are noise (the smoothing's edge, a short chord); none
    # of that is a crossing.
    t = times(6.0)
    bike = straight(
        "bike", t, 0.0, 0.0, math.pi / 2, ramp_distance(t, 0.0, 1.0, 1.0 + 4 / 1.5, 4.0)
    )
    bike = Track(bike.name, bike.times, bike.x, bike.y, bike.heading, kind="Bicycle")
    for seed in range(8):
        (actor,) = extract(Recording((noisy(bike, seed),), "by hand"), check_replay=False).actors
        assert [e.kind for e in actor.maneuvers] == ["Accelerate"], seed


def test_a_noisy_bike_that_sets_off_at_once_ramps_from_standing() -> None:
    # A bike stands for 0.1 s, then +1.5 m/s² to 4.5 m/s (until 3.1 s), 10 Hz, 0.1 m of noise.
    # Fitted with a free starting speed, the noise made a slow creep of the first moments
    # and the ramp started up to half a second late; it stood, so it ramps from 0.
    t = times(8.0)
    bike = straight("bike", t, 0.0, 0.0, math.pi / 2, ramp_distance(t, 0.0, 0.1, 3.1, 4.5))
    bike = Track(bike.name, bike.times, bike.x, bike.y, bike.heading, kind="Bicycle")
    for seed in range(8):
        (actor,) = extract(Recording((noisy(bike, seed),), "by hand"), check_replay=False).actors
        (event,) = actor.maneuvers
        assert (event.kind, event.from_speed) == ("Accelerate", 0.0), seed
        assert event.start == pytest.approx(0.1, abs=0.3), seed
        assert event.parameters["rate"] == pytest.approx(1.5, abs=0.2), seed


def test_a_walker_s_ramp_that_a_crossing_follows_ends_by_its_bend() -> None:
    # A noisy fit: 0 to 1.5 m/s from 7.0 to 9.0 s (midpoint 8.0), its start anywhere in
    # 6.8-7.8 s as far as the noise tells. The crossing bent at 8.6 s, so the ramp ended by
    # then: it starts at 2 x 8.0 - 8.6 = 7.4 s at the earliest, at 1.5 / 1.2 = 1.25 m/s².
    def walk() -> list[Event]:
        ramp = Event("Accelerate", "walker", 7.0, 9.0, {"targetSpeed": 1.5, "rate": 0.75})
        ramp.from_speed, ramp.start_range = 0.0, (6.8, 7.8)
        return [ramp, Event("Cross", "walker", 8.6, 8.6)]

    events = walk()
    end_by_crossings(events)
    ramp = events[0]
    assert (ramp.start, ramp.end) == pytest.approx((7.4, 8.6))
    assert ramp.parameters["rate"] == pytest.approx(1.25)
    assert ramp.start_range == pytest.approx((7.4, 7.8))
    # A bend after the ramp's fitted end says nothing new: it stays as fitted.
    events = walk()
    events[1].start = events[1].end = 9.5
    end_by_crossings(events)
    assert (events[0].start, events[0].end, events[0].start_range) == (7.0, 9.0, (6.8, 7.8))


def test_a_noisy_moving_start_is_placed_by_the_distance_driven() -> None:
    # A car at a steady 8 m/s from (0, 0) along x, 10 Hz, 0.1 m of noise. The smoothing's
    # first value is an extrapolated cubic (0.05 to 0.12 m off along x on these seeds); the
    # distance driven over the next seconds at the known speed puts the start within 5 cm.
    t = times(8.0)
    car = straight("ego", t, 0.0, 0.0, 0.0, 8.0 * t)
    for seed in range(8):
        found = extract(Recording((noisy(car, seed),), "by hand"))
        assert found.replay is not None
        x, _ = found.replay.run.states[0, 0, :2]
        assert abs(x) < 0.05, (seed, x)


def walker_who_sets_off_and_crosses() -> Track:
    """Stands at (0, 0) facing east until 3.0 s, +2 m/s² to 1.8 m/s at 3.9 s (0.81 m), on at
    1.8 m/s for a flow (to 3.95 s: 0.9 m), then straight north until 8 s (to y = 1.8 x 4.05
    = 7.29 m): the library's crossing as the preview plays it, a ramp, then a flow later a
    Cross."""
    t = times(8.0)
    s = ramp_distance(t, 0.0, 3.0, 3.9, 1.8)
    x, y = np.minimum(s, 0.9), np.maximum(s - 0.9, 0.0)
    return Track("walker", t, x, y, np.zeros_like(t), kind="Pedestrian")


def test_a_noisy_walker_sets_off_and_crosses_where_its_ramp_ends() -> None:
    # Fitted along the smoothed path the ramp ended 0.1 to 0.375 s late (the smoothing cuts
    # the corner and adds its sideways jitter to a slow walker's length) and the replay was
    # up to 1.1 m off; fitted to the raw positions in the plane, the bend pins its end.
    walker = walker_who_sets_off_and_crosses()
    for seed in range(8):
        found = extract(Recording((noisy(walker, seed),), "by hand"))
        (actor,) = found.actors
        ramp, cross = actor.maneuvers
        assert (ramp.kind, cross.kind) == ("Accelerate", "Cross"), seed
        # The ramp's end is fitted where the path bends (3.95 s), which is where the Cross,
        # following it, starts: within a step, where the old fit ended it up to 0.33 s late.
        assert ramp.end == pytest.approx(3.95, abs=0.1), seed
        assert cross.start == ramp.end, seed
        assert ramp.start == pytest.approx(3.0, abs=0.25), seed
        assert ramp.parameters["targetSpeed"] == pytest.approx(1.8, abs=0.06), seed
        assert found.replay is not None and found.replay.largest < 0.75, seed


def test_a_noisy_walker_that_walks_straight_to_the_end_crosses_to_where_it_ended() -> None:
    # The smoothing's last window "bent" the noisy heading by a few hundredths of a radian,
    # and the crossing was ended there, up to 0.9 m short of (0.9, 7.29).
    walker = walker_who_sets_off_and_crosses()
    for seed in range(8):
        (actor,) = extract(Recording((noisy(walker, seed),), "by hand"), check_replay=False).actors
        (cross,) = [e for e in actor.maneuvers if e.kind == "Cross"]
        assert cross.destination is not None
        x, y, _ = cross.destination
        assert math.hypot(x - 0.9, y - 7.29) < 0.3, (seed, x, y)

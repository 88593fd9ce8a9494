"""The preview of release 1.4's kinds against esmini 3.6's log of
tests/importer/files/lights-and-stops.xosc (read by hand, --fixed_timestep 0.05): LeadBrakes
starts at 2.00 s; LeadDecelerates holds at 2.05 s (acceleration -4.00 < -3.00); BrakeLightsOn
runs from 2.05 s to 2.25 s (its 0.2 s transition); LeadStandsStill holds at 8.05 s (stood
1.05 s > 1 s; the lead stops at 7.00 s); HazardLights starts at 8.05 s and is still running
when the run stops at 12.05 s (a flashing light never ends)."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.importer import import_file
from sceml.model.build import ScenarioBuilder, world
from sceml.simulate import simulate
from sceml.xosc.meaning import light_state_duration, measured_acceleration, standing_after

LIGHTS = Path(__file__).parents[1] / "importer" / "files" / "lights-and-stops.xosc"


def test_lights_and_motion_conditions_start_and_finish_as_in_esmini() -> None:
    run = simulate(import_file(LIGHTS).scenario, LIGHTS)
    assert run.node("LeadDecelerates").finished == pytest.approx(2.05)
    brake_lights = run.node("BrakeLightsOn")
    assert (brake_lights.started, brake_lights.finished) == (
        pytest.approx(2.05),
        pytest.approx(2.25),
    )
    assert run.node("LeadStandsStill").finished == pytest.approx(8.05)
    hazard = run.node("HazardLights")
    assert hazard.started == pytest.approx(8.05) and hazard.finished is None


def test_standing_is_counted_from_the_step_the_actor_stops_in() -> None:
    assert standing_after(None, 5.0, 0.05) is None
    assert standing_after(None, 0.0, 0.05) == 0.0
    assert standing_after(0.0, 0.0005, 0.05) == 0.05  # below esmini's 1 mm/s
    assert standing_after(0.05, 0.2, 0.05) is None


def test_the_measured_acceleration_is_the_magnitude_without_a_direction() -> None:
    assert measured_acceleration("total", -4.0) == 4.0
    assert measured_acceleration("longitudinal", -4.0) == -4.0
    assert measured_acceleration("lateral", -4.0) == 0.0
    assert light_state_duration(0.2, "on") == 0.2
    assert light_state_duration(0.2, "flashing") is None


def test_a_stand_still_of_an_actor_standing_from_the_start() -> None:
    # Standing from t = 0: esmini stamps the stop in the first step (0.05 s), so a stand
    # still of 0.5 s holds once 0.55 s have passed since, at 0.60 s.
    b = ScenarioBuilder("still", level="concrete", max_duration=2.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=0.0)
    still = b.add("StandStill", ego, duration=0.5)
    b.chain(b.root, still, b.end)
    assert simulate(b.scenario).node(str(still.name)).finished == pytest.approx(0.6)


RELATIVE = LIGHTS.parent / "relative-speeds.xosc"


def test_a_relative_speed_follows_the_target_as_in_esmini() -> None:
    # esmini 3.6's log of relative-speeds.xosc (read by hand): the follower starts at 18 m/s
    # (0.9 of 20) and FollowerSlows runs from 3.00 s to 4.45 s (18 to 15 m/s at 2 m/s²); the
    # preview ends a speed change a step later, as for every speed change (docs/simulate.md).
    run = simulate(import_file(RELATIVE).scenario, RELATIVE)
    keep = run.node("Init_Follower")
    assert keep.finished == pytest.approx(0.05)  # reached in its first step; it keeps on
    slows = run.node("FollowerSlows")
    assert (slows.started, slows.finished) == (pytest.approx(3.0), pytest.approx(4.5))

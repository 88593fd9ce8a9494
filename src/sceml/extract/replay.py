"""How close the extracted scenario, run in the preview, stays to the recording."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import scemlmodel as scm

from ..maps import RoadMap
from ..simulate import Run, simulate
from .recording import Recording


@dataclass(frozen=True)
class ActorFit:
    """One actor's distance (m) between replay and recording over the time both cover."""

    name: str
    largest: float
    when: float
    mean: float


@dataclass(frozen=True)
class ReplayFit:
    """The replay's fit per actor; `until` is the last time compared (the shorter run's end)."""

    actors: tuple[ActorFit, ...]
    until: float
    replay_end: float
    end_reason: str
    run: Run

    @property
    def largest(self) -> float:
        """The largest distance (m) of any actor."""
        return max((a.largest for a in self.actors), default=0.0)


def replay(scenario: scm.Scenario, recording: Recording, road_map: RoadMap | None) -> ReplayFit:
    """Run the scenario in the preview and measure its distance to each recorded track."""
    run = simulate(scenario, road_map=road_map)
    offset = recording.start  # the replay's clock starts at 0
    fits = []
    until = min(float(run.times[-1]), recording.end - offset)
    for index, info in enumerate(run.actors):
        track = recording.track(info.name)
        keep = run.times <= min(until, track.times[-1] - offset) + 1e-9
        times = run.times[keep]
        x = np.interp(times + offset, track.times, track.x)
        y = np.interp(times + offset, track.times, track.y)
        error = np.hypot(run.states[index, keep, 0] - x, run.states[index, keep, 1] - y)
        worst = int(np.argmax(error))
        fits.append(
            ActorFit(info.name, float(error[worst]), float(times[worst]), float(error.mean()))
        )
    return ReplayFit(tuple(fits), until, float(run.end_time), run.end_reason, run)

"""A recorded drive: one track per actor, sampled on one clock."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray


@dataclass(frozen=True)
class Track:
    """One actor's samples: times (s), x, y (m), and heading (rad) where the recording has it.

    `kind` and the box size are what the recording says (esmini's bounding box) or None when it
    says nothing; the extraction then guesses them from the motion (see `actors.py`).
    """

    name: str
    times: NDArray[np.float64]
    x: NDArray[np.float64]
    y: NDArray[np.float64]
    heading: NDArray[np.float64] | None = None
    kind: str | None = None
    length: float | None = None
    width: float | None = None
    ego: bool = False

    @property
    def duration(self) -> float:
        """Seconds from the first sample to the last."""
        return float(self.times[-1] - self.times[0]) if len(self.times) else 0.0


@dataclass(frozen=True)
class Recording:
    """Every actor's track, and where the recording came from (for messages)."""

    tracks: tuple[Track, ...]
    source: str = ""
    format: str = ""
    notes: tuple[str, ...] = field(default=())

    def track(self, name: str) -> Track:
        """The track of an actor by name; KeyError if there is none."""
        for track in self.tracks:
            if track.name == name:
                return track
        raise KeyError(name)

    @property
    def start(self) -> float:
        """The earliest time of any track."""
        return min(float(t.times[0]) for t in self.tracks)

    @property
    def end(self) -> float:
        """The latest time of any track."""
        return max(float(t.times[-1]) for t in self.tracks)

"""What a player's run says, whatever the player: event times, how it stopped, the actors' motion.

Readers of each player's own formats (`players.esmini`) produce a `PlayerRun`; the checker and
the comparison with the preview only read this.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..xosc import PLAYER_STEP

Array = NDArray[np.float64]


@dataclass
class EventRun:
    """When one event started, and when it ended of its own accord (None: it did not)."""

    start: float | None = None
    end: float | None = None
    #: When the player stopped it before it ended (a conflicting action, the storyboard's stop).
    stopped: float | None = None


@dataclass(frozen=True)
class CutShort:
    """The player ended an action of an event before it was done, and why."""

    time: float
    event: str
    reason: str


@dataclass(frozen=True)
class Trace:
    """One actor's motion: at each time its reference point (x, y), heading, speed and lane.

    `lane` is the player's lane id at each sample (0 where it does not say).
    """

    times: Array
    x: Array
    y: Array
    heading: Array
    speed: Array
    lane: NDArray[np.int64]

    def at(self, t: float) -> int:
        """The index of the sample nearest time `t`."""
        return int(np.argmin(np.abs(self.times - t)))


@dataclass
class PlayerRun:
    """A player's run of one exported scenario."""

    player: str
    version: str = "unknown"
    #: The OpenSCENARIO version of the file played, when the log says it.
    osc_version: str | None = None
    events: dict[str, EventRun] = field(default_factory=dict)
    #: Time and transition ("stop" or "end") of the storyboard's completion, if it completed.
    stop_time: float | None = None
    stop_how: str | None = None
    #: The trigger printed last before the storyboard stopped: groups of (condition, value).
    stop_groups: list[list[tuple[str, bool]]] = field(default_factory=list)
    cut_short: list[CutShort] = field(default_factory=list)
    traces: dict[str, Trace] = field(default_factory=dict)
    step: float = PLAYER_STEP

"""What a preview run produces: trajectories, the timeline of nodes, metrics, and why it ended."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

#: Why a run ended.
END_NODE = "end node"
MAX_DURATION = "maximum duration"


@dataclass(frozen=True)
class ActorInfo:
    """An actor as the run saw it: name, kind, ego flag, box size (m) and how far the box's
    centre lies ahead of the reference point the states follow (Actor.boxCenterX, m)."""

    name: str
    kind: str
    ego: bool
    length: float
    width: float
    box_ahead: float = 0.0
    #: The actor towing this one (Actor.trailer, release 1.4); "" when none. A coupled pair's
    #: boxes overlap by design (a semi-trailer under its tractor): no metrics for it.
    towed_by: str = ""


@dataclass(frozen=True)
class NodeRecord:
    """When a node was activated (started) and finished; None when it never was."""

    name: str
    kind: str
    actor: str | None
    started: float | None
    finished: float | None
    note: str = ""

    def running_at(self, t: float) -> bool:
        """Whether the node was active (activated, not yet finished) at time t."""
        if self.started is None or t < self.started:
            return False
        return self.finished is None or t < self.finished


@dataclass(frozen=True)
class PairMetrics:
    """Conflict measures of two actors over the whole run.

    `min_distance` is between the bounding boxes (0 once they overlap); `min_ttc` assumes both
    keep their velocity; `pet` is the post-encroachment time where the driven paths cross
    (None when they do not, or one never reaches the crossing); times are of the run's clock.
    """

    a: str
    b: str
    min_distance: float
    min_distance_time: float
    min_ttc: float | None
    min_ttc_time: float | None
    pet: float | None
    pet_point: tuple[float, float] | None
    collision: bool
    collision_time: float | None


@dataclass(frozen=True)
class Run:
    """A finished preview: states[actor, sample] = (x, y, heading, speed) at times[sample]."""

    scenario: str
    step: float
    times: NDArray[np.float64]
    actors: tuple[ActorInfo, ...]
    states: NDArray[np.float64]
    timeline: tuple[NodeRecord, ...]
    end_reason: str
    end_time: float
    metrics: tuple[PairMetrics, ...]
    notes: tuple[str, ...] = ()

    def node(self, name: str) -> NodeRecord:
        """The timeline entry of a node by name; KeyError if there is none."""
        for record in self.timeline:
            if record.name == name:
                return record
        raise KeyError(name)

    def pair(self, a: str, b: str) -> PairMetrics:
        """The metrics of two actors, in either order; KeyError if there is no such pair."""
        for metrics in self.metrics:
            if {metrics.a, metrics.b} == {a, b}:
                return metrics
        raise KeyError((a, b))

    def actor_index(self, name: str) -> int:
        return next(i for i, actor in enumerate(self.actors) if actor.name == name)

    @property
    def collided(self) -> bool:
        return any(m.collision for m in self.metrics)

"""What an actor did, as timed events: speed changes and path changes, before they are nodes."""

from __future__ import annotations

from dataclasses import dataclass, field

#: Event kinds that change the speed; the others change the path. DriveDistance is a step of
#: the speed (a recorded speed that jumps), the others change it at a rate.
LONGITUDINAL = ("Accelerate", "Decelerate", "Stop", "DriveDistance")


@dataclass
class Event:
    """A maneuver seen in a recording.

    `start` is when the motion began to change, `end` when the change was complete. A
    `flexible` event (a turn; a crossing without a visible change of heading) may be activated
    any time up to `start`: the actor follows its lane until the junction (or walks on) anyway.
    `finish` is when the maneuver node will finish in a replay (a turn or crossing: on arrival
    within its tolerance), which is what the next node of the actor waits for.
    """

    kind: str
    actor: str
    start: float
    end: float
    parameters: dict[str, object] = field(default_factory=dict)
    flexible: bool = False
    finish: float = 0.0
    #: Where a turn or crossing ends (x, y, heading), for its arrival check.
    destination: tuple[float, float, float] | None = None
    #: The speed (m/s) before a speed change.
    from_speed: float | None = None
    #: How far (rad) the heading turned, for a path change.
    turned: float = 0.0
    #: A speed change recorded steeper than the actor kind allows, extracted at its limit.
    limited: bool = False
    #: For a speed change fitted on a noisy recording: the earliest and latest start (s) of
    #: ramps with the same fit's midpoint that explain the distance driven as well, within
    #: the noise. A condition that fires in it may pin the start (`retime`).
    start_range: tuple[float, float] | None = None

    def retime(self, start: float) -> None:
        """Start a speed change at `start` instead, keeping its midpoint and target: the rate
        follows from the new duration."""
        middle = (self.start + self.end) / 2
        end = 2 * middle - start
        change = abs(float(str(self.parameters.get("targetSpeed", 0.0))) - (self.from_speed or 0))
        self.start, self.end, self.finish = start, end, end
        self.parameters["rate"] = round(change / max(end - start, 1e-3), 2)

    @property
    def longitudinal(self) -> bool:
        """Whether the event changes the speed (the others change the path)."""
        return self.kind in LONGITUDINAL

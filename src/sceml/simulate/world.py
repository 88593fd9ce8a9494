"""What every node behaviour sees while a scenario runs: the clock, the actors and the map."""

from __future__ import annotations

from dataclasses import dataclass, field

from pyecore.ecore import EObject

from ..errors import SceMLError
from ..maps import RoadMap
from ..maps.positions import centre
from .actors import Actor


class SimulationError(SceMLError):
    """A scenario the preview cannot run: not concrete, no usable start, a position off the map.

    The input does not fit the request (like asking the map view of a town), hence exit code 2.
    """

    exit_code = 2


@dataclass
class World:
    """The running scenario: time, actors by name, the map (None without one) and notes on
    what the preview had to simplify."""

    road_map: RoadMap | None
    actors: dict[str, Actor]
    dt: float
    t: float = 0.0
    notes: list[str] = field(default_factory=list)

    def actor(self, participant: EObject | None, node: str) -> Actor:
        """The actor a node's reference or target names."""
        name = getattr(participant, "name", None)
        if name not in self.actors:
            raise SimulationError(f"{node}: names no actor of the scenario", element=node)
        return self.actors[name]

    def point(self, position: EObject | None, what: str) -> tuple[float, float]:
        """The world point of a concrete position."""
        try:
            located = centre(position, self.road_map)
        except ValueError as error:
            raise SimulationError(f"{what}: {error}", element=what) from None
        if located is None:
            raise SimulationError(f"{what} has no usable position", element=what)
        return located.x, located.y

    def note(self, text: str) -> None:
        if text not in self.notes:
            self.notes.append(text)

"""What every node behaviour sees while a scenario runs: the clock, the actors and the map."""

from __future__ import annotations

from dataclasses import dataclass, field

from pyecore.ecore import EObject

from ..errors import SceMLError
from ..maps import RoadMap, WorldPose
from ..maps.positions import centre
from ..maps.resolve import is_relative, resolve
from ..model.towing import Coupling
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
    #: The scenario's parameters and variables by (variable?, name): their current text, set
    #: from the root's declarations and changed by SetParameter and SetVariable.
    values: dict[tuple[bool, str], str] = field(default_factory=dict)
    #: Who tows whom, towers first (`model.towing.couplings`); dragged after every step.
    couplings: list[Coupling] = field(default_factory=list)
    #: Every trailer coupled during the run (ConnectTrailer, release 1.5) and its last tower:
    #: a pair coupled at any time gets no gap or collision metrics.
    towed_by: dict[str, str] = field(default_factory=dict)

    def actor(self, participant: EObject | None, node: str) -> Actor:
        """The actor a node's reference or target names."""
        name = getattr(participant, "name", None)
        if name not in self.actors:
            raise SimulationError(f"{node}: names no actor of the scenario", element=node)
        return self.actors[name]

    def point(self, position: EObject | None, what: str) -> tuple[float, float]:
        """The world point of a concrete position; a relative one where its entity is now (a
        destination is asked for when its maneuver starts, a condition's at every step)."""
        if is_relative(position):
            assert position is not None
            return self._relative_point(position, what)
        try:
            located = centre(position, self.road_map)
        except ValueError as error:
            raise SimulationError(f"{what}: {error}", element=what) from None
        if located is None:
            raise SimulationError(f"{what} has no usable position", element=what)
        return located.x, located.y

    def _relative_point(self, position: EObject, what: str) -> tuple[float, float]:
        entity = position.entity
        actor = self.actors.get(str(getattr(entity, "name", None)))
        if actor is None:
            raise SimulationError(f"{what} is relative to no actor of the scenario", element=what)
        try:
            pose = resolve(
                position, self.road_map, {entity: WorldPose(actor.x, actor.y, actor.heading)}
            )
        except ValueError as error:
            raise SimulationError(f"{what}: {error}", element=what) from None
        if pose is None:
            raise SimulationError(f"{what} has no usable position", element=what)
        return pose.x, pose.y

    def note(self, text: str) -> None:
        if text not in self.notes:
            self.notes.append(text)

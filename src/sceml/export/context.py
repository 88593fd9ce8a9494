"""What every mapping function shares while one scenario is exported: names, values, version."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..maps.resolve import is_relative
from .names import SEPARATOR, NameTable, sanitize
from .triggers import Group
from .values import Values
from .versions import Traits

if TYPE_CHECKING:
    from ..xosc.vehicle_catalog import VehicleCatalogFolder


@dataclass(frozen=True)
class Action:
    """One OpenSCENARIO Action; `kind` selects the template branch, `data` fills it."""

    name: str
    kind: str
    data: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Event:
    """One Event in its own Maneuver, in the ManeuverGroup of `actor`."""

    name: str
    actor: str
    actions: list[Action]
    groups: list[Group]
    #: maximumExecutionCount: how many times the event may run (the node's maxRuns).
    runs: int = 1


@dataclass
class Context:
    """Export state for one scenario: traits, profile, values and the name table."""

    traits: Traits
    profile: str
    values: Values
    names: NameTable
    ego: str
    marker: str
    entity_names: dict[EObject, str] = field(default_factory=dict)
    event_names: dict[EObject, str] = field(default_factory=dict)
    #: Nodes written into their successor's trigger, with no event (`xosc.flows.inlined`).
    inline: set[EObject] = field(default_factory=set)
    #: The root node's vehicle catalog (release 1.5): actors read from it are referred to.
    vehicle_catalog: VehicleCatalogFolder | None = None

    def entity(self, actor: scm.Participant | None) -> str:
        """The ScenarioObject name of an actor."""
        return self.entity_names[actor]

    def extra_event(self, node: EObject, suffix: str) -> str:
        """A further event of `node`, e.g. `TurnRight_1__arrived`."""
        return self.names.claim(f"{self.event_names[node]}{SEPARATOR}{suffix}")

    def action_name(self, event: str) -> str:
        """The name of the (single) action of an event."""
        return self.names.claim(f"{event}{SEPARATOR}action")

    def position(self, position: scm.Position) -> dict[str, Any]:
        """A Position as a small dict the `position` macro renders."""
        text = self.values.text
        if isinstance(position, scm.LanePosition):
            return {
                "kind": "lane",
                "roadId": str(position.roadId),
                "laneId": str(position.laneId),
                "s": text(position, "s"),
                "offset": text(position, "offset"),
                "h": None if position.h is None else text(position, "h"),
            }
        if isinstance(position, scm.RoadPosition):
            return {
                "kind": "road",
                "roadId": str(position.roadId),
                "s": text(position, "s"),
                "t": text(position, "t"),
                "h": None if position.h is None else text(position, "h"),
            }
        if is_relative(position):
            return self._relative(position)
        if isinstance(position, scm.RoutePosition):
            return self._route(position)
        return {
            "kind": "world",
            "x": text(position, "x"),
            "y": text(position, "y"),
            "z": text(position, "z"),
            "h": text(position, "h"),
        }

    def _route(self, position: scm.RoutePosition) -> dict[str, Any]:
        """A route position writes its route inline (a catalog's route included: the export
        refers to no route catalog) and its place on it in lane or road coordinates."""
        text = self.values.text
        on_lane = position.laneId is not None
        return {
            "kind": "route",
            "name": sanitize(position.routeName, fallback="Route"),
            "closed": "true" if position.closed else "false",
            "waypoints": [
                {"strategy": w.routeStrategy.name, "position": self.position(w.position)}
                for w in position.waypoints
            ],
            "pathS": text(position, "pathS"),
            "laneId": str(int(position.laneId)) if on_lane else None,
            "laneOffset": text(position, "laneOffset") if on_lane else None,
            "t": None if on_lane else text(position, "t"),
        }

    def _relative(self, position: scm.Position) -> dict[str, Any]:
        """A relative position names its entity's ScenarioObject; every offset is written, h
        (RelativeObjectPosition) only when set, as a relative Orientation."""
        text = self.values.text
        kind = position.eClass.name
        features = {
            "RelativeLanePosition": ("ds", "offset"),
            "RelativeRoadPosition": ("ds", "dt"),
            "RelativeObjectPosition": ("dx", "dy", "dz"),
            "RelativeWorldPosition": ("dx", "dy", "dz"),
        }[kind]
        attributes = {name: text(position, name) for name in features}
        if kind == "RelativeLanePosition":
            attributes = {"dLane": str(int(position.dLane or 0)), **attributes}
        h = getattr(position, "h", None)
        return {
            "kind": "relative",
            "tag": kind,
            "entity": self.entity(position.entity),
            "attributes": attributes,
            "h": None if h is None else text(position, "h"),
        }

    def marker_action(self, event: str, value: str) -> Action:
        """The harmless set action a marker event performs."""
        kind = "variable_set" if self.traits.variables else "parameter_set"
        return Action(self.action_name(event), kind, {"ref": self.marker, "value": value})


def node_name(node: EObject) -> str:
    """The sanitized base name of a node's events."""
    return sanitize(getattr(node, "name", None), fallback=node.eClass.name)

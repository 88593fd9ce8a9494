"""What every stage of one import shares: the source, the scenario being built, actors, names,
the map (when readable) and the report."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from lxml import etree

import scemlmodel as scm

from ..files.safexml import hardened_parser
from ..model.build import GraphBuilder
from .reading import CATALOG_ENTRY, ORIGIN, Source
from .report import ImportReport
from .traced import TRACE

if TYPE_CHECKING:
    from ..maps import RoadMap


@dataclass
class Build:
    """The import of one file in progress."""

    source: Source
    report: ImportReport
    scenario: scm.Scenario
    root: scm.RootNode
    end: scm.EndNode
    graph: GraphBuilder
    road_map: RoadMap | None = None
    #: ScenarioObject name -> actor.
    actors: dict[str, scm.Actor] = field(default_factory=dict)
    ego: scm.Actor | None = None
    #: The marker parameter/variable of a SceML export (`SceML_marker`), if the file is one.
    marker: str | None = None
    #: Actor name -> its speed once a gradual Init speed change (a node after the root) is done.
    init_speeds: dict[str, float] = field(default_factory=dict)
    #: Actor name -> (maxAcceleration, maxDeceleration) of its Vehicle's Performance: players
    #: slow a speed change whose (peak) rate is above them down to them.
    performance: dict[str, tuple[float, float]] = field(default_factory=dict)
    #: (activating node, the condition's content) -> its node: one node for the same condition
    #: after the same node in several triggers (`triggers.Trigger.condition`).
    conditions: dict[tuple[int, bytes], scm.GraphElement] = field(default_factory=dict)
    #: Node id -> the place of the event it performs in the storyboard (document order), for
    #: ordering an actor's maneuvers (`overlaps.separate`).
    event_order: dict[int, int] = field(default_factory=dict)
    #: (tower, the entity its TrailerRef names, the Trailer element): linked once every
    #: entity is read (`entities.py`).
    trailer_refs: list[tuple[scm.Actor, str, etree._Element]] = field(default_factory=list)
    #: Entities of vehicleCategory trailer or semitrailer: never guessed to be the ego.
    trailer_entities: set[str] = field(default_factory=set)
    _taken: set[str] = field(default_factory=set)

    @property
    def from_sceml(self) -> bool:
        """Whether the file is one of SceML's own exports (it declares the marker)."""
        return self.marker is not None

    def name(self, wanted: str) -> str:
        """A node name not yet used in the scenario: `wanted`, else `wanted_2`, ..."""
        candidate, number = wanted, 1
        while candidate in self._taken:
            number += 1
            candidate = f"{wanted}_{number}"
        self._taken.add(candidate)
        return candidate

    def add(self, node: scm.GraphElement, wanted: str) -> scm.GraphElement:
        """Put a node into the scenario under a unique name."""
        node.name = self.name(wanted)
        self.scenario.nodes.append(node)
        return node

    def flow(self, source: scm.GraphElement, target: scm.GraphElement) -> None:
        """A flow, unless the same one exists already."""
        if any(flow.target is target for flow in source.outgoing):
            return
        self.graph.flow(source, target)

    def where(self, element: etree._Element) -> tuple[str, int | None]:
        """File and line of an element, for the report."""
        return self.source.where(element)

    def actor(self, entity: str | None, element: etree._Element) -> scm.Actor:
        """The actor of a ScenarioObject name; a dangling reference is an input error."""
        if entity is not None:
            found = self.actors.get(_last(entity))
            if found is not None:
                return found
        raise self.source.error(f"<{element.tag}> refers to an unknown entity {entity!r}", element)

    def default_actor(self) -> scm.Actor:
        """The actor global actions and conditions are attached to: the ego."""
        if self.ego is None:
            raise self.source.error("the file declares no entities")
        return self.ego


def _last(reference: str) -> str:
    """The name of a reference that may be qualified with name spaces (`a::b::name`)."""
    return reference.split("::")[-1]


def kept_xml(element: etree._Element) -> str:
    """An element as the text an OpaqueAction keeps: resolved values, no import bookkeeping."""
    copy = etree.fromstring(etree.tostring(element, with_tail=False), hardened_parser())
    etree.strip_attributes(copy, ORIGIN, CATALOG_ENTRY, TRACE)
    for child in copy.iter():
        if child.tail is not None:
            child.tail = None
        if (
            isinstance(child.tag, str)
            and len(child)
            and child.text is not None
            and not child.text.strip()
        ):
            child.text = None
    etree.cleanup_namespaces(copy)
    return str(etree.tostring(copy, encoding="unicode"))


def last_name(reference: str) -> str:
    """The name of a possibly name-spaced reference (`a::b::name` -> `name`)."""
    return _last(reference)

"""What an operation works on: the graph being edited, its ids, the recorder, and lookups."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.graph import root_node
from ..model.traversal import all_contents, cross_references
from .changes import Recorder
from .errors import OperationError
from .ids import Ids


@dataclass
class Clipboard:
    """Deep copies of the copied nodes and the flows among them (as index pairs)."""

    nodes: list[scm.GraphElement] = field(default_factory=list)
    flows: list[tuple[int, int]] = field(default_factory=list)


@dataclass
class EditContext:
    """Everything one operation needs; `created` collects the ids of nodes the ops made."""

    graph: scm.Graph
    ids: Ids
    #: A library file as an op names it (relative to the edited file) -> its Library and path;
    #: with `create`, a missing file becomes a new, empty library (not yet written).
    find_library: Callable[[str, bool], tuple[scm.Library, Path]]
    clipboard: Clipboard
    rec: Recorder = field(default_factory=Recorder)
    created: list[str] = field(default_factory=list)
    #: Why a known object is no longer in the model ("was deleted in another tab"), if known.
    why_gone: Callable[[EObject], str | None] = lambda obj: None

    @property
    def root(self) -> scm.RootNode | None:
        """The scenario's root node; None when a module definition is edited."""
        return root_node(self.graph) if isinstance(self.graph, scm.Scenario) else None

    def node(self, identifier: object) -> scm.GraphElement:
        """The graph's node with this id; OperationError for anything else."""
        found = self.ids.find(identifier)
        if isinstance(found, scm.GraphElement) and found.eContainer() is self.graph:
            return found
        if isinstance(identifier, str) and "/" in identifier:
            raise OperationError(f"node {identifier} is inside a module use and cannot be edited")
        self._gone(found)
        raise OperationError(f"unknown node {identifier!r}")

    def _gone(self, found: EObject | None) -> None:
        """OperationError naming a node, flow or actor the model held once but holds no more."""
        if found is None:
            return
        name = getattr(found, "name", None)
        if isinstance(found, scm.Flow):
            ends = (getattr(found.source, "name", "?"), getattr(found.target, "name", "?"))
            name = f"{ends[0]} -> {ends[1]}"
        reason = self.why_gone(found) or "was deleted, or its addition undone"
        raise OperationError(f"'{name}' {reason}")

    def flow(self, identifier: object) -> scm.Flow:
        """The graph's flow with this id."""
        found = self.ids.find(identifier)
        if isinstance(found, scm.Flow) and found.eContainer() is self.graph:
            return found
        self._gone(found)
        raise OperationError(f"unknown edge {identifier!r}")

    def actor(self, identifier: object) -> scm.Actor:
        """The scenario's actor with this id."""
        found = self.ids.find(identifier)
        root = self.root
        if isinstance(found, scm.Actor) and root is not None and found.eContainer() is root:
            return found
        if root is None:
            raise OperationError("a module's roles are edited in its library, not here")
        self._gone(found)
        raise OperationError(f"unknown actor {identifier!r}")

    def participants(self) -> dict[str, scm.Participant]:
        """What nodes may name as actors: the scenario's actors, or the module's roles."""
        if isinstance(self.graph, scm.ModuleDefinition):
            return {str(role.name): role for role in self.graph.roles}
        root = self.root
        return {str(actor.name): actor for actor in (root.actors if root is not None else [])}

    def participant(self, name: object) -> scm.Participant | None:
        """The actor (or role) with this name; None for None; OperationError if unknown."""
        if name is None:
            return None
        known = self.participants()
        if not isinstance(name, str) or name not in known:
            options = ", ".join(known) or "none"
            raise OperationError(f"no actor named {name!r} (there are: {options})")
        return known[name]

    def find_parameter(self, name: str) -> scm.ModuleParameter | None:
        """A parameter of the edited module (None in a scenario: `ref` is refused there)."""
        if not isinstance(self.graph, scm.ModuleDefinition):
            return None
        return next((p for p in self.graph.parameters if p.name == name), None)

    @property
    def parameter_lookup(self) -> Callable[[str], scm.ModuleParameter | None] | None:
        """`find_parameter` inside a module, None in a scenario."""
        return self.find_parameter if isinstance(self.graph, scm.ModuleDefinition) else None

    def node_names(self) -> set[str]:
        """The names the graph's nodes have."""
        return {str(node.name) for node in self.graph.nodes if node.name}


def referrers(graph: EObject, target: EObject) -> Iterator[tuple[EObject, str]]:
    """Every (object, single-valued reference) in `graph` that points at `target`."""
    for obj in all_contents(graph):
        for feature in cross_references(obj.eClass):
            if not feature.many and obj.eGet(feature) is target:
                yield obj, str(feature.name)


#: The longest name of a node, actor, scenario or module: names are shown in boxes and written
#: into OpenSCENARIO names, and a longer one is a mistake (a paste into the wrong field).
MAX_NAME_LENGTH = 200
#: The longest other text (a description, a map path, a simulator model).
MAX_TEXT_LENGTH = 10_000
#: Attributes that are names, held to MAX_NAME_LENGTH.
NAME_FEATURES = frozenset({"name", "scenarioName"})


def check_text(feature: str, value: str) -> None:
    """OperationError if `value` is longer than a `feature` may be."""
    limit = MAX_NAME_LENGTH if feature in NAME_FEATURES else MAX_TEXT_LENGTH
    require(
        len(value) <= limit,
        f"{feature} may be at most {limit:,} characters long, not {len(value):,}",
    )


def require(condition: bool, message: str) -> None:
    """OperationError(message) unless `condition`."""
    if not condition:
        raise OperationError(message)


def argument(op: dict[str, Any], key: str) -> Any:
    """A required key of an operation."""
    if key not in op:
        raise OperationError(f"operation {op.get('op')!r} needs {key!r}")
    return op[key]

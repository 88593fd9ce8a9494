"""The view the browser draws: nodes with labels and fields, edges, actors, problems, palette."""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic
from ..model import catalog
from ..model.graph import finishes_with_first
from ..modules import naming
from ..render.flow import inner_scope
from ..render.labels import (
    Scope,
    action_lines,
    loaded_definition,
    root_lines,
    scenario_title,
    use_lines,
)
from ..validation.edits import Change
from .fields import actor_fields, node_fields, root_fields
from .ids import Ids
from .values import default_text, value_text, value_to_json

_LOOKS = {
    "RootNode": "root",
    "EndNode": "end",
    "JoinAllFinished": "joinAll",
    "JoinOneFinished": "joinOne",
    "InPort": "inPort",
    "OutPort": "outPort",
}
_PORT_IDS = {"InPort": "in", "OutPort": "out"}


@dataclass
class Listing:
    """The nodes and edges of a view, and which listed id shows each model object."""

    nodes: list[dict[str, Any]] = field(default_factory=list)
    edges: list[dict[str, Any]] = field(default_factory=list)
    #: Model object (a module internal too) -> the id it is listed under (first listing wins).
    shown: dict[EObject, str] = field(default_factory=dict)
    #: Module definition -> the id of the first use that shows it.
    uses_of: dict[EObject, str] = field(default_factory=dict)


def look(node: EObject) -> str:
    """The protocol's look of a node (docs/editor-protocol.md, Node)."""
    if isinstance(node, scm.ActionNode):
        return catalog.category(node) or "longitudinal"
    if isinstance(node, scm.ModuleUse):
        return "module" if loaded_definition(node) is not None else "brokenModule"
    if isinstance(node, scm.EndNode) and finishes_with_first(node):
        return "endOne"
    return _LOOKS.get(node.eClass.name, "longitudinal")


def title_and_lines(node: EObject, scope: Scope) -> tuple[str, list[str]]:
    """The box's text as `sceml render` writes it (render/labels.py)."""
    if isinstance(node, scm.ActionNode):
        return node.eClass.name, action_lines(node, scope)
    if isinstance(node, scm.RootNode):
        scenario = node.eContainer()
        if isinstance(scenario, scm.Scenario):
            return scenario_title(scenario), root_lines(node, scenario)
        return str(node.name), []
    if isinstance(node, scm.ModuleUse):
        definition = loaded_definition(node)
        name = str(definition.name) if definition is not None else str(node.name)
        return name, use_lines(node, scope)
    if isinstance(node, scm.EndNode):
        return ("End ?" if look(node) == "endOne" else "End"), []
    return _PORT_IDS.get(node.eClass.name, node.eClass.name), []


def _position(node: scm.GraphElement) -> dict[str, float] | None:
    held = node.diagramPosition
    return None if held is None else {"x": held.x, "y": held.y}


def library_text(definition: EObject, folder: Path) -> str | None:
    """The file of a definition, relative to the edited file's folder, as ops name it."""
    resource = definition.eResource
    if resource is None:
        return None
    path = Path(resource.uri.normalize()).resolve()
    return Path(os.path.relpath(path, folder.resolve())).as_posix()


def module_info(use: scm.ModuleUse, folder: Path) -> dict[str, Any]:
    """The Module of a ModuleUse node: definition, library, bindings and parameters."""
    definition = loaded_definition(use)
    bound = {binding.role: binding.actor for binding in use.bindings}
    given = {override.parameter: override.value for override in use.overrides}
    roles = list(definition.roles) if definition is not None else []
    parameters = list(definition.parameters) if definition is not None else []
    return {
        "definition": str(definition.name) if definition is not None else None,
        "library": library_text(definition, folder) if definition is not None else None,
        "resolved": definition is not None,
        "bindings": [
            {
                "role": str(role.name),
                "allowedKinds": [str(k.kind.name) for k in role.allowedKinds if k.kind],
                "actor": _name(bound.get(role.name)),
            }
            for role in roles
        ],
        "parameters": [
            {
                "name": str(p.name),
                "unit": str(p.unit or ""),
                "default": value_to_json(p.default),
                "override": value_to_json(given.get(p.name)),
                "defaultText": default_text(p.default, str(p.unit or "")),
                "text": value_text(given.get(p.name), str(p.unit or "")),
            }
            for p in parameters
        ],
    }


def _name(obj: EObject | None) -> str | None:
    return None if obj is None else str(obj.name)


class NodeCache:
    """What each top-level node lists (its entry, a use's internals), kept until a change
    touches that node, so that a view after one edit lists one node anew, not all of them.

    A node's entry depends on the node and what it contains, on the actors it names (their
    names and kinds, held by the root) and on module definitions (other files). A change inside
    a node forgets that node; a change to the graph's lists forgets the nodes added or removed;
    a change anywhere else (the root and its actors, another file) forgets everything.

    It also keeps the actors' (or roles') listing, the other part of a view every edit would
    build again: it depends only on the root's actors or the module's roles, so it is kept
    while every change lies inside another node or in the graph's lists of nodes and flows.
    """

    def __init__(self) -> None:
        self._fragments: dict[EObject, Listing] = {}
        self._actors: list[dict[str, Any]] | None = None

    def actors(self, graph: scm.Graph, ids: Ids) -> list[dict[str, Any]]:
        """`actors(graph, ids)`, listed anew only after a change that can alter it."""
        if self._actors is None:
            self._actors = actors(graph, ids)
        return self._actors

    def get(self, node: EObject) -> Listing | None:
        """What `node` listed last, if nothing touched it since."""
        return self._fragments.get(node)

    def keep(self, node: EObject, fragment: Listing) -> None:
        """Remember what `node` listed."""
        self._fragments[node] = fragment

    def forget_all(self) -> None:
        """Forget every node (opened, saved, or changed outside what the changes show)."""
        self._fragments.clear()
        self._actors = None

    def forget(self, changes: Iterable[Change], graph: EObject) -> None:
        """Forget the nodes `changes` touched (or all, for a change outside any one node)."""
        for change in changes:
            if change.owner is graph:
                for item in (change.old, change.new):
                    self._fragments.pop(item, None)
                # A module's roles are its own list; the root holds a scenario's actors.
                if change.feature not in ("nodes", "flows") or any(
                    isinstance(item, scm.RootNode) for item in (change.old, change.new)
                ):
                    self._actors = None
                continue
            top = _top_level(change.owner, graph)
            if top is None or isinstance(top, scm.RootNode):
                self.forget_all()
                return
            if not isinstance(top, scm.GraphElement | scm.Flow):
                self._actors = None  # a role of a module, or another object of the graph's
            self._fragments.pop(top, None)


def _top_level(obj: EObject, graph: EObject) -> EObject | None:
    """The node of `graph` that contains `obj` (or is it), or None."""
    current: EObject | None = obj
    while current is not None:
        container = current.eContainer()
        if container is graph:
            return current
        current = container
    return None


class Lister:
    """Lists a graph's nodes and edges, and the insides of its module uses, read-only."""

    def __init__(self, ids: Ids, folder: Path, cache: NodeCache | None = None) -> None:
        self.ids = ids
        self.folder = folder
        self.listing = Listing()
        self.cache = cache

    def graph(self, graph: scm.Graph) -> Listing:
        """Every node and flow of the edited graph, module internals after their use."""
        for node in graph.nodes:
            self._top_level_node(node)
        for flow in graph.flows:
            if flow.source is not None and flow.target is not None:
                self.edge(
                    self.ids.of(flow, "f"),
                    self.ids.of(flow.source, "n"),
                    self.ids.of(flow.target, "n"),
                )
        return self.listing

    def _top_level_node(self, node: EObject) -> None:
        fragment = self.cache.get(node) if self.cache is not None else None
        if fragment is None:
            whole, self.listing = self.listing, Listing()
            self.node(node, self.ids.of(node, "n"), Scope(), None)
            whole, fragment = self.listing, whole
            self.listing = fragment
            if self.cache is not None:
                self.cache.keep(node, whole)
            fragment = whole
        # Entries are copied: problems are marked on them per view.
        self.listing.nodes += [dict(entry) for entry in fragment.nodes]
        self.listing.edges += fragment.edges
        for obj, listed in fragment.shown.items():
            self.listing.shown.setdefault(obj, listed)
        for definition, use in fragment.uses_of.items():
            self.listing.uses_of.setdefault(definition, use)

    def node(
        self, node: EObject, node_id: str, scope: Scope, parent: str | None, within: str = ""
    ) -> None:
        """One node; a module use also lists its definition's nodes under its id.

        `within` is the name of the expanded use that shows the node: its name is scoped by it
        (`CrossingManeuver_1.Accelerate_1`, as flatten names copies), so that two boxes on the
        canvas never share a label.
        """
        title, lines = title_and_lines(node, scope)
        own = str(node.name or "")
        entry: dict[str, Any] = {
            "id": node_id,
            "kind": node.eClass.name,
            "look": look(node),
            "name": naming.scoped(within, own) if within and own else own,
            "title": title,
            "lines": lines,
            "position": _position(node),
            "parent": parent,
            "readOnly": parent is not None,
            "severity": None,
            "problems": 0,
            "fields": root_fields(node) if isinstance(node, scm.RootNode) else node_fields(node),
        }
        self.listing.nodes.append(entry)
        self.listing.shown.setdefault(node, node_id)
        if isinstance(node, scm.ModuleUse):
            entry["module"] = module_info(node, self.folder)
            self.inside(node, node_id, scope, entry["name"])

    def edge(self, edge_id: str, source: str, target: str) -> None:
        """One edge between listed nodes."""
        self.listing.edges.append({"id": edge_id, "source": source, "target": target})

    def inside(self, use: scm.ModuleUse, use_id: str, scope: Scope, shown_name: str) -> None:
        """A use's definition: its nodes as `<use>/<index>` (ports `<use>/in`, `/out`)."""
        definition = loaded_definition(use)
        if definition is None or any(definition is seen for seen in scope.chain):
            return
        self.listing.uses_of.setdefault(definition, use_id)
        inner = inner_scope(use, definition, scope, f"{use_id}/")
        local: dict[EObject, str] = {}
        for index, node in enumerate(definition.nodes):
            local[node] = f"{use_id}/{_PORT_IDS.get(node.eClass.name, index)}"
            self.node(node, local[node], inner, use_id, shown_name)
        for index, flow in enumerate(definition.flows):
            if flow.source in local and flow.target in local:
                self.edge(f"{use_id}/f{index}", local[flow.source], local[flow.target])


def diagnostic_json(diagnostic: Diagnostic, node: str | None, actor: str | None) -> dict[str, Any]:
    """A Diagnostic as the protocol's JSON: Diagnostic.to_json's fields the page shows, and the
    node or actor it is about."""
    shown = diagnostic.to_json()
    return {
        **{key: shown[key] for key in ("severity", "code", "message", "path")},
        "node": node,
        "actor": actor,
        "line": shown["line"],
    }


def target_of(element: EObject | None, listing: Listing, ids: Ids) -> tuple[str | None, str | None]:
    """(node id, actor id) a diagnostic is about: the nearest listed container of its element."""
    current = element
    while current is not None:
        if isinstance(current, scm.Actor | scm.ActorRole) and ids.known(current):
            return None, ids.known(current)
        if current in listing.shown:
            return listing.shown[current], None
        if isinstance(current, scm.ModuleDefinition) and current in listing.uses_of:
            return listing.uses_of[current], None
        current = current.eContainer()
    return None, None


def problems(diagnostics: list[Diagnostic], listing: Listing, ids: Ids) -> list[dict[str, Any]]:
    """The diagnostics as JSON, each mapped to its node or actor; nodes get severity and count."""
    by_id = {entry["id"]: entry for entry in listing.nodes}
    found = []
    for diagnostic in diagnostics:
        node, actor = target_of(diagnostic.element, listing, ids)
        found.append(diagnostic_json(diagnostic, node, actor))
        # A problem inside a use also marks the use, which is all a collapsed box shows.
        marked = {node, node.split("/")[0]} if node else set()
        for node_id in marked:
            _mark(by_id.get(node_id), str(diagnostic.severity))
    return found


_RANK = {None: -1, "info": 0, "warning": 1, "error": 2}


def _mark(entry: dict[str, Any] | None, severity: str) -> None:
    if entry is None:
        return
    entry["problems"] += 1
    if _RANK[severity] > _RANK[entry["severity"]]:
        entry["severity"] = severity


def summary(found: list[dict[str, Any]]) -> dict[str, int]:
    """How many errors, warnings and infos."""
    counts = {"errors": 0, "warnings": 0, "infos": 0}
    for item in found:
        counts[item["severity"] + "s"] += 1
    return counts


def actors(graph: scm.Graph, ids: Ids) -> list[dict[str, Any]]:
    """The scenario's actors with their fields, or the module's roles with their kinds."""
    if isinstance(graph, scm.ModuleDefinition):
        return [
            {
                "id": ids.of(role, "a"),
                "name": str(role.name),
                "allowedKinds": [str(k.kind.name) for k in role.allowedKinds if k.kind],
            }
            for role in graph.roles
        ]
    root = next((n for n in graph.nodes if isinstance(n, scm.RootNode)), None)
    return [
        {
            "id": ids.of(actor, "a"),
            "name": str(actor.name),
            "kind": actor.eClass.name,
            "isEgo": bool(actor.isEgo),
            "fields": actor_fields(actor),
        }
        for actor in (root.actors if root is not None else [])
    ]


def relative(path: Path, folder: Path) -> str:
    """A file as ops name it: relative to the edited file's folder, with forward slashes."""
    return Path(os.path.relpath(path.resolve(), folder.resolve())).as_posix()

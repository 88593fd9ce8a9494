"""Flatten a scenario: expand every module use, recursively, into plain nodes and flows."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..collector import collector_paused
from ..copying import Copier, copy_tree
from ..graph import predecessors, successors
from ..io import model_path
from ..traversal import all_contents, cross_references
from . import naming
from .errors import FlattenError
from .resolve import definition_key, location, resolved_definition, unwrap

__all__ = ["FlattenError", "Flattened", "expand", "flatten"]


@dataclass
class Flattened:
    """A flattened copy of a scenario and the uses that were expanded, outermost first."""

    scenario: scm.Scenario
    expanded: list[str] = field(default_factory=list)


def flatten(scenario: scm.Scenario) -> scm.Scenario:
    """A copy of `scenario` with every module use expanded; the input is left untouched.

    Expanded nodes are named `<use>.<node>` (e.g. `CrossingManeuver_1.Accelerate_1`), roles are
    replaced by the actors they are bound to, parameter references by the use's overrides or the
    module's defaults, and flows into and out of a use are rewired through its ports.
    """
    return expand(scenario).scenario


def expand(scenario: scm.Scenario) -> Flattened:
    """Like `flatten`, and also report which uses were expanded."""
    with collector_paused():
        return _expand(scenario)


def _expand(scenario: scm.Scenario) -> Flattened:
    copier = Copier()
    flat = copier.copy(scenario)
    copier.copy_references()
    expansion = _Expansion(flat, {copy: original for original, copy in copier.copies.items()})
    for use in [node for node in flat.nodes if isinstance(node, scm.ModuleUse)]:
        expansion.inline(use, ())
    expansion.commit()
    _check_self_contained(flat)
    return Flattened(flat, expansion.expanded)


class _Expansion:
    """The state of one flattening: the flat graph, its names, and where each copy came from."""

    def __init__(self, graph: scm.Scenario, origins: dict[EObject, EObject]) -> None:
        self.graph = graph
        # Copies are not in any file; errors point at the element they were copied from.
        self.origins = origins
        self.taken = {str(node.name) for node in graph.nodes if node.name}
        self.expanded: list[str] = []
        # The graph's own collections are pyecore ordered sets, whose insert and remove cost
        # O(n); the expansion collects its changes in plain containers and commits them once,
        # which keeps flattening linear in the size of the result.
        self.replacements: dict[EObject, list[scm.GraphElement]] = {}
        self.added_flows: list[scm.Flow] = []
        self.dead_flows: set[scm.Flow] = set()

    def commit(self) -> None:
        """Give the graph its final nodes, in reading order, and its live flows."""
        nodes: list[scm.GraphElement] = []
        pending = list(reversed(self.graph.nodes))
        while pending:
            node = pending.pop()
            if node in self.replacements:
                pending.extend(reversed(self.replacements[node]))
            else:
                nodes.append(node)
        flows = [f for f in (*self.graph.flows, *self.added_flows) if f not in self.dead_flows]
        self.graph.nodes.clear()
        self.graph.nodes.extend(nodes)
        self.graph.flows.clear()
        self.graph.flows.extend(flows)

    def where(self, obj: EObject) -> dict[str, Any]:
        """Location keywords of the element `obj` was copied from."""
        return location(self.origins.get(obj, obj))

    def inline(self, use: scm.ModuleUse, chain: tuple[tuple[tuple[str, str], str], ...]) -> None:
        """Replace `use` by a copy of its definition's graph, then expand the uses inside it."""
        definition = resolved_definition(self.origins.get(use, use), self.where)
        key = definition_key(definition)
        if any(seen == key for seen, _ in chain):
            names = " -> ".join(name for _, name in (*chain, (key, str(definition.name))))
            raise FlattenError(f"module uses itself: {names}", **self.where(use))
        if not use.name:
            use.name = naming.numbered(str(definition.name), self.taken)
        copier = Copier()
        nodes = copier.copy_all(definition.nodes)
        flows = copier.copy_all(definition.flows)
        copier.copy_references()
        self.origins.update({copy: original for original, copy in copier.copies.items()})
        in_port, out_port = _ports(definition, nodes)
        _bind_roles(use, definition, nodes, self.where)
        _bind_parameters(use, definition, nodes, self.where)
        self._place(use, nodes, flows, in_port, out_port)
        self.expanded.append(str(use.name))
        inner = (*chain, (key, str(definition.name)))
        for nested in [n for n in nodes if isinstance(n, scm.ModuleUse)]:
            self.inline(nested, inner)

    def _place(
        self,
        use: scm.ModuleUse,
        nodes: list[scm.GraphElement],
        flows: list[scm.Flow],
        in_port: scm.InPort,
        out_port: scm.OutPort,
    ) -> None:
        for node in nodes:
            node.name = naming.unique(naming.scoped(str(use.name), str(node.name)), self.taken)
            self.taken.add(node.name)
        self.replacements[use] = [n for n in nodes if n is not in_port and n is not out_port]
        self.added_flows.extend(flows)
        self._rewire(use, in_port, out_port)

    def _rewire(self, use: scm.ModuleUse, in_port: scm.InPort, out_port: scm.OutPort) -> None:
        entries = successors(in_port)
        exits = predecessors(out_port)
        before = predecessors(use)
        after = successors(use)
        # A module whose in-port leads straight to its out-port passes activation through.
        sources = [*exits, *(before if out_port in entries else [])]
        for source in before:
            for entry in entries:
                if entry is not out_port:
                    self.added_flows.append(scm.Flow(source=source, target=entry))
        for exit_ in sources:
            if exit_ is in_port:
                continue
            for target in after:
                self.added_flows.append(scm.Flow(source=exit_, target=target))
        for node in (use, in_port, out_port):
            for flow in [*node.incoming, *node.outgoing]:
                flow.source = None
                flow.target = None
                self.dead_flows.add(flow)


def _ports(
    definition: scm.ModuleDefinition, nodes: list[scm.GraphElement]
) -> tuple[scm.InPort, scm.OutPort]:
    in_ports = [n for n in nodes if isinstance(n, scm.InPort)]
    out_ports = [n for n in nodes if isinstance(n, scm.OutPort)]
    if len(in_ports) != 1 or len(out_ports) != 1:
        raise FlattenError(
            f"module {definition.name!r} needs one in-port and one out-port, "
            f"has {len(in_ports)} and {len(out_ports)}",
            **location(definition),
        )
    in_port, out_port = in_ports[0], out_ports[0]
    if not successors(in_port) or not predecessors(out_port):
        unwired = in_port.name if not successors(in_port) else out_port.name
        raise FlattenError(
            f"module {definition.name!r}: port {unwired!r} is not wired", **location(definition)
        )
    return in_port, out_port


def _bind_roles(
    use: scm.ModuleUse,
    definition: scm.ModuleDefinition,
    nodes: list[EObject],
    where: Callable[[EObject], dict[str, Any]],
) -> None:
    bound = {binding.role: binding.actor for binding in use.bindings}
    actors: dict[EObject, EObject] = {}
    for role in definition.roles:
        if bound.get(role.name) is None:
            raise FlattenError(
                f"role {role.name!r} of module {definition.name!r} is not bound",
                **where(use),
            )
        actors[role] = bound[role.name]
    for obj in _with_contents(nodes):
        for feature in cross_references(obj.eClass):
            if feature.many:
                continue
            target = obj.eGet(feature)
            if target is not None and unwrap(target) in actors:
                obj.eSet(feature, actors[unwrap(target)])


def _bind_parameters(
    use: scm.ModuleUse,
    definition: scm.ModuleDefinition,
    nodes: list[EObject],
    where: Callable[[EObject], dict[str, Any]],
) -> None:
    overrides = {override.parameter: override.value for override in use.overrides}
    declared = {parameter.name: parameter for parameter in definition.parameters}
    unknown = sorted(set(overrides) - set(declared))
    if unknown:
        raise FlattenError(
            f"module {definition.name!r} has no parameter {unknown[0]!r} "
            f"(it has: {', '.join(declared) or 'none'})",
            **where(use),
        )
    for ref in [o for o in _with_contents(nodes) if isinstance(o, scm.ParameterRef)]:
        parameter = ref.parameter
        if parameter is None or declared.get(parameter.name) is not unwrap(parameter):
            raise FlattenError(
                f"a parameter reference in module {definition.name!r} names no parameter of it",
                **location(ref),
            )
        chosen = overrides.get(parameter.name)
        if chosen is None:
            chosen = parameter.default
        # An unset value means the language default, as everywhere else in a scenario.
        ref.eContainer().eSet(
            ref.eContainmentFeature(), copy_tree(chosen) if chosen is not None else None
        )


def _with_contents(nodes: list[EObject]) -> list[EObject]:
    return [obj for node in nodes for obj in (node, *all_contents(node))]


def _check_self_contained(flat: scm.Scenario) -> None:
    # Anything still pointing into a library (a role of another module, say) would make the
    # flattened file depend on the library it is meant to replace.
    for obj in all_contents(flat):
        for feature in cross_references(obj.eClass):
            if feature.many:
                continue
            target = obj.eGet(feature)
            if target is not None and _root_of(unwrap(target)) is not flat:
                raise FlattenError(
                    f"{feature.name} still refers to {model_path(unwrap(target))} outside the "
                    "scenario after expansion",
                    element=model_path(obj),
                )


def _root_of(obj: EObject) -> EObject:
    while obj.eContainer() is not None:
        obj = obj.eContainer()
    return obj

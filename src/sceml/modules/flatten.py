"""Flatten a scenario: expand every module use, recursively, into plain nodes and flows."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..collector import collector_paused
from ..copying import Copier
from ..graph import predecessors, successors
from ..io import model_path
from ..traversal import all_contents, cross_references
from . import naming
from .errors import FlattenError
from .resolve import definition_key, location, resolved_definition, unwrap

__all__ = ["FlattenError", "Flattened", "Origin", "expand", "flatten"]


@dataclass(frozen=True)
class Origin:
    """Where one element of a flattened scenario came from.

    `element` is what it is a copy of: an element of the input scenario, or of a module
    definition (in a library), or, for a value that replaced a parameter reference, the use's
    override value or the parameter's default. `uses` are the module uses whose expansion put it
    where it is, outermost first: the first is a node of the input scenario, the others belong
    to module definitions. An element of the scenario's own graph has no uses.
    """

    element: EObject
    uses: tuple[scm.ModuleUse, ...] = ()

    @property
    def from_module(self) -> bool:
        """Whether the element was expanded from a module use."""
        return bool(self.uses)

    @property
    def in_scenario(self) -> EObject:
        """What the input scenario shows for it: the outermost use, or the element itself."""
        return self.uses[0] if self.uses else self.element


@dataclass
class Flattened:
    """A flattened copy of a scenario, the uses that were expanded (outermost first), and the
    origin of every element of the copy (flows made to rewire ports excepted: they copy none)."""

    scenario: scm.Scenario
    expanded: list[str] = field(default_factory=list)
    origins: dict[EObject, Origin] = field(default_factory=dict)

    def origin(self, obj: EObject) -> Origin | None:
        """Where an element of the flattened scenario came from; None for one it does not hold."""
        return self.origins.get(obj)


def flatten(scenario: scm.Scenario) -> scm.Scenario:
    """A copy of `scenario` with every module use expanded; the input is left untouched.

    Expanded nodes are named `<use>.<node>` (e.g. `CrossingManeuver_1.Accelerate_1`), roles are
    replaced by the actors they are bound to, parameter references by the use's overrides or the
    module's defaults, and flows into and out of a use are rewired through its ports. Where each
    element came from is told by `expand`; names are for people, not for finding that out.
    """
    return expand(scenario).scenario


def expand(scenario: scm.Scenario) -> Flattened:
    """Like `flatten`, and also report which uses were expanded and where each element came from."""
    with collector_paused():
        return _expand(scenario)


def _expand(scenario: scm.Scenario) -> Flattened:
    copier = Copier()
    flat = copier.copy(scenario)
    copier.copy_references()
    expansion = _Expansion(flat, {copy: original for original, copy in copier.copies.items()})
    for use in [node for node in flat.nodes if isinstance(node, scm.ModuleUse)]:
        expansion.inline(use, (), ())
    expansion.commit()
    _check_self_contained(flat)
    return Flattened(flat, expansion.expanded, expansion.provenance())


class _Expansion:
    """The state of one flattening: the flat graph, its names, and where each copy came from."""

    def __init__(self, graph: scm.Scenario, origins: dict[EObject, EObject]) -> None:
        self.graph = graph
        # Copies are not in any file; errors point at the element they were copied from.
        self.origins = origins
        # The uses expanded to make each copy, outermost first, as original model objects.
        self.chains: dict[EObject, tuple[scm.ModuleUse, ...]] = {}
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

    def provenance(self) -> dict[EObject, Origin]:
        """The origin of every element the flat graph holds in the end."""
        held = [self.graph, *all_contents(self.graph)]
        return {
            obj: Origin(self.origins[obj], self.chains.get(obj, ()))
            for obj in held
            if obj in self.origins
        }

    def copied(self, copier: Copier, uses: tuple[scm.ModuleUse, ...]) -> None:
        """Record the copies `copier` made, inside `uses`, by the original each one stands for."""
        for source, copy in copier.copies.items():
            self.origins[copy] = self.origins.get(source, source)
            self.chains[copy] = uses

    def where(self, obj: EObject) -> dict[str, Any]:
        """Location keywords of the element `obj` was copied from."""
        return location(self.origins.get(obj, obj))

    def inline(
        self,
        use: scm.ModuleUse,
        chain: tuple[tuple[tuple[str, str], str], ...],
        uses: tuple[scm.ModuleUse, ...],
    ) -> None:
        """Replace `use` by a copy of its definition's graph, then expand the uses inside it.

        `chain` holds the definitions entered so far (to refuse recursion), `uses` the original
        uses expanded so far (the copies' provenance).
        """
        original = self.origins.get(use, use)
        assert isinstance(original, scm.ModuleUse)
        definition = resolved_definition(original, self.where)
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
        inside = (*uses, original)
        self.copied(copier, inside)
        in_port, out_port = _ports(definition, nodes)
        _bind_roles(use, definition, nodes, self.where)
        for value_copier in _bind_parameters(use, definition, nodes, self.where):
            self.copied(value_copier, inside)
        self._place(use, nodes, flows, in_port, out_port)
        self.expanded.append(str(use.name))
        inner = (*chain, (key, str(definition.name)))
        for nested in [n for n in nodes if isinstance(n, scm.ModuleUse)]:
            self.inline(nested, inner, inside)

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
) -> list[Copier]:
    """Replace each parameter reference by a copy of the value chosen for it; returns the copiers
    that made those copies, so that each copy can be traced to the value it was made from."""
    overrides = {override.parameter: override.value for override in use.overrides}
    declared = {parameter.name: parameter for parameter in definition.parameters}
    unknown = sorted(set(overrides) - set(declared))
    if unknown:
        raise FlattenError(
            f"module {definition.name!r} has no parameter {unknown[0]!r} "
            f"(it has: {', '.join(declared) or 'none'})",
            **where(use),
        )
    copiers: list[Copier] = []
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
            ref.eContainmentFeature(), _copy(chosen, copiers) if chosen is not None else None
        )
    return copiers


def _copy(value: EObject, copiers: list[Copier]) -> EObject:
    copier = Copier()
    duplicate = copier.copy(value)
    copier.copy_references()
    copiers.append(copier)
    return duplicate


def _with_contents(nodes: list[EObject]) -> list[EObject]:
    return [obj for node in nodes for obj in (node, *all_contents(node))]


def _check_self_contained(flat: scm.Scenario) -> None:
    # Anything still pointing into a library (a role of another module, say) would make the
    # flattened file depend on the library it is meant to replace.
    inside: dict[EObject, bool] = {}  # by target: thousands of nodes name the same few actors
    for obj in all_contents(flat):
        for feature in cross_references(obj.eClass):
            if feature.many:
                continue
            target = obj.eGet(feature)
            if target is None:
                continue
            target = unwrap(target)
            if target not in inside:
                inside[target] = _root_of(target) is flat
            if not inside[target]:
                raise FlattenError(
                    f"{feature.name} still refers to {model_path(target)} outside the "
                    "scenario after expansion",
                    element=model_path(obj),
                )


def _root_of(obj: EObject) -> EObject:
    while obj.eContainer() is not None:
        obj = obj.eContainer()
    return obj

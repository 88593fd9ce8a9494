"""Expand a scenario's module uses without copying the scenario itself.

What a flattened scenario would hold is worked out here once: the scenario's own nodes (the
originals, not copies), bound copies of every module use's internals, and the flows between them
as a plain adjacency (`Wiring`). Validation reads that directly, so checking a 10,000-node
scenario copies only what its module uses expand to. `flatten.expand` turns the same result into
a real flat copy for the `flatten` command and the exporter; both therefore name, bind and wire
expanded nodes in exactly the same way.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from pyecore.ecore import EClass, EObject, EProxy
from pyecore.valuecontainer import EValue

import scemlmodel as scm

from ..model.collector import collector_paused
from ..model.copying import Copier
from ..model.fastobjects import replace_child, slot
from ..model.locating import model_path
from ..model.traversal import (
    all_contents,
    children,
    containments,
    cross_references,
    root_of,
    single_references,
    stored,
)
from . import naming
from .errors import FlattenError
from .resolve import definition_key, location, resolved_definition, unwrap


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


class Edge:
    """One flow of the expanded graph: its ends, and the Flow it stands for (None for a flow
    made to rewire a use's ports)."""

    __slots__ = ("alive", "flow", "source", "target")

    def __init__(self, source: EObject | None, target: EObject | None, flow: EObject | None):
        self.source = source
        self.target = target
        self.flow = flow
        self.alive = True


class Wiring:
    """Flows as adjacency lists, kept in the order pyecore would keep `incoming` and `outgoing`
    of the same flows, so that everything read from them comes out in the same order."""

    def __init__(self) -> None:
        self.edges: list[Edge] = []
        self._incoming: dict[EObject, list[Edge]] = {}
        self._outgoing: dict[EObject, list[Edge]] = {}

    def connect(self, source: EObject | None, target: EObject | None, flow: EObject | None) -> None:
        """Add a flow; a missing end leaves it dangling, as an unset Flow end does."""
        edge = Edge(source, target, flow)
        self.edges.append(edge)
        if source is not None:
            self._outgoing.setdefault(source, []).append(edge)
        if target is not None:
            self._incoming.setdefault(target, []).append(edge)

    def cut(self, node: EObject) -> None:
        """Remove every flow into or out of `node` (a use or port that is replaced)."""
        for edge in [*self._incoming.pop(node, ()), *self._outgoing.pop(node, ())]:
            edge.alive = False
            if edge.source is not None and edge.source is not node:
                self._outgoing[edge.source].remove(edge)
            if edge.target is not None and edge.target is not node:
                self._incoming[edge.target].remove(edge)

    def predecessors(self, node: EObject) -> list[EObject]:
        """Nodes with a flow into `node`, in flow order; dangling flows are skipped."""
        return [e.source for e in self._incoming.get(node, ()) if e.source is not None]

    def successors(self, node: EObject) -> list[EObject]:
        """Nodes `node` has a flow to, in flow order; dangling flows are skipped."""
        return [e.target for e in self._outgoing.get(node, ()) if e.target is not None]

    def live(self) -> list[Edge]:
        """The flows left in the end, in the order they were made."""
        return [edge for edge in self.edges if edge.alive]


@dataclass
class Expansion:
    """A scenario's module uses expanded: its nodes in reading order, their flows, and where each
    copy came from. Nodes of the scenario's own graph are its original objects; module internals
    are bound copies that belong to no container (see `holds`)."""

    scenario: scm.Scenario
    nodes: list[scm.GraphElement]
    wiring: Wiring
    expanded: list[str] = field(default_factory=list)
    #: Every copy made (module internals, their contents, values given to parameters).
    origins: dict[EObject, Origin] = field(default_factory=dict)

    def holds(self, obj: EObject) -> bool:
        """Whether `obj` is a copy made by the expansion (or inside one)."""
        return obj in self.origins

    def release(self, keep: Collection[EObject] = ()) -> None:
        """Forget, in the objects they refer to, the references of the copies not in `keep`
        (see `forget_references`)."""
        forget_references(copy for copy in self.origins if copy not in keep)

    def from_module(self, node: EObject) -> bool:
        """Whether a node of the expanded graph was expanded from a module use."""
        origin = self.origins.get(node)
        return origin is not None and origin.from_module

    def origin(self, node: EObject) -> EObject:
        """The element of the input scenario a node stands for: itself, or the outermost use."""
        origin = self.origins.get(node)
        return origin.in_scenario if origin is not None else node

    def predecessors(self, node: EObject) -> list[EObject]:
        """Nodes of the expanded graph with a flow into `node`."""
        return self.wiring.predecessors(node)

    def successors(self, node: EObject) -> list[EObject]:
        """Nodes of the expanded graph `node` has a flow to."""
        return self.wiring.successors(node)

    def flows(self) -> list[tuple[EObject, EObject]]:
        """(source, target) of every flow of the expanded graph with both ends set."""
        return [
            (edge.source, edge.target)
            for edge in self.wiring.live()
            if edge.source is not None and edge.target is not None
        ]


def forget_references(copies: Iterable[EObject]) -> None:
    """Remove what the objects `copies` refer to records of them; the copies keep their values.

    pyecore records every reference without an opposite in its target (`_inverse_rels`), so a
    throwaway copy that names a scenario's actor or a library's parameter would stay reachable
    from that object: an editor validating after every edit would grow without bound.
    """
    for copy in copies:
        for feature in cross_references(copy.eClass):
            value = stored(copy, feature.name)
            for target in (list(value) if feature.many else [value]) if value else ():
                try:
                    links = getattr(unwrap(target), "_inverse_rels", None)
                except Exception:  # an unresolvable proxy: nothing was recorded in it
                    continue
                if links is not None:
                    links.discard((copy, feature))


def expansion(scenario: scm.Scenario) -> Expansion:
    """Expand every module use of `scenario`, recursively; the scenario is left untouched.

    Expanded nodes are named `<use>.<node>` (e.g. `CrossingManeuver_1.Accelerate_1`), roles are
    replaced by the actors they are bound to, parameter references by the use's overrides or the
    module's defaults, and flows into and out of a use are rewired through its ports.
    FlattenError says why a use cannot be expanded.
    """
    with collector_paused():
        builder = _Builder(scenario)
        for use in [node for node in scenario.nodes if isinstance(node, scm.ModuleUse)]:
            builder.inline(use, (), ())
        result = builder.result()
        _check_self_contained(result)
        return result


class _Builder:
    """The state of one expansion: the wiring, the names taken, and where each copy came from."""

    def __init__(self, scenario: scm.Scenario) -> None:
        self.scenario = scenario
        self.wiring = Wiring()
        for flow in scenario.flows:
            self.wiring.connect(flow.source, flow.target, flow)
        # Copies are not in any file; errors point at the element they were copied from.
        self.origins: dict[EObject, EObject] = {}
        # The uses expanded to make each copy, outermost first, as original model objects.
        self.chains: dict[EObject, tuple[scm.ModuleUse, ...]] = {}
        self.taken = {str(node.name) for node in scenario.nodes if node.name}
        self.expanded: list[str] = []
        # The scenario's uses keep their (possibly empty) names; the names they expand under.
        self.use_names: dict[EObject, str] = {}
        self.replacements: dict[EObject, list[scm.GraphElement]] = {}
        # A definition's file and name, worked out once: it resolves the file's path.
        self.keys: dict[EObject, tuple[str, str]] = {}
        # What binding a use of each definition needs to know of it, worked out once.
        self.plans: dict[EObject, _Plan] = {}

    def result(self) -> Expansion:
        """The expanded graph's nodes in reading order, with the wiring and provenance."""
        nodes: list[scm.GraphElement] = []
        pending = list(reversed(self.scenario.nodes))
        while pending:
            node = pending.pop()
            if node in self.replacements:
                pending.extend(reversed(self.replacements[node]))
            else:
                nodes.append(node)
        origins = {copy: Origin(self.origins[copy], uses) for copy, uses in self.chains.items()}
        return Expansion(self.scenario, nodes, self.wiring, self.expanded, origins)

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
        """Replace `use` by a bound copy of its definition's nodes, then expand the uses inside.

        `chain` holds the definitions entered so far (to refuse recursion), `uses` the original
        uses expanded so far (the copies' provenance).
        """
        original = self.origins.get(use, use)
        assert isinstance(original, scm.ModuleUse)
        definition = resolved_definition(original, self.where)
        key = self.keys.get(definition)
        if key is None:
            key = self.keys[definition] = definition_key(definition)
        if any(seen == key for seen, _ in chain):
            names = " -> ".join(name for _, name in (*chain, (key, str(definition.name))))
            raise FlattenError(f"module uses itself: {names}", **self.where(use))
        use_name = str(use.name) if use.name else naming.numbered(str(definition.name), self.taken)
        # An unnamed use's chosen name is taken from here on: a second unnamed use of the same
        # module must not be numbered alike (its copies would come out as `X.A~2`).
        self.taken.add(use_name)
        self.use_names[use] = use_name
        plan = self.plans.get(definition)
        if plan is None:
            plan = self.plans[definition] = _Plan(definition)
        # Refused in the order the steps below would meet each problem on a copy.
        plan.check_ports()
        actors = _bound_actors(use, definition, self.where)
        # Roles are bound as the definition is copied: references to a role point at its actor.
        copier = Copier(stand_ins=None if plan.roles_by_walk else actors)
        nodes = copier.copy_all(definition.nodes)
        copier.copy_references()
        for flow in definition.flows:
            source, target = flow.source, flow.target
            self.wiring.connect(
                copier.copies.get(source, source), copier.copies.get(target, target), flow
            )
        inside = (*uses, original)
        self.copied(copier, inside)
        if plan.roles_by_walk:
            _bind_roles_by_walk(nodes, actors)
        for value_copier in _bind_parameters(use, plan, copier.copies, self.where):
            self.copied(value_copier, inside)
        in_port, out_port = copier.copies[plan.in_port], copier.copies[plan.out_port]
        self._place(use, use_name, nodes, in_port, out_port)
        self.expanded.append(use_name)
        inner = (*chain, (key, str(definition.name)))
        for nested in [n for n in nodes if isinstance(n, scm.ModuleUse)]:
            self.inline(nested, inner, inside)

    def _place(
        self,
        use: scm.ModuleUse,
        use_name: str,
        nodes: list[scm.GraphElement],
        in_port: scm.InPort,
        out_port: scm.OutPort,
    ) -> None:
        for node in nodes:
            name = naming.unique(naming.scoped(use_name, str(node.name)), self.taken)
            _rename(node, name)
            self.taken.add(name)
        self.replacements[use] = [n for n in nodes if n is not in_port and n is not out_port]
        self._rewire(use, in_port, out_port)

    def _rewire(self, use: scm.ModuleUse, in_port: scm.InPort, out_port: scm.OutPort) -> None:
        wiring = self.wiring
        entries = wiring.successors(in_port)
        exits = wiring.predecessors(out_port)
        before = wiring.predecessors(use)
        after = wiring.successors(use)
        # A module whose in-port leads straight to its out-port passes activation through.
        sources = [*exits, *(before if out_port in entries else [])]
        for source in before:
            for entry in entries:
                if entry is not out_port:
                    wiring.connect(source, entry, None)
        for exit_ in sources:
            if exit_ is in_port:
                continue
            for target in after:
                wiring.connect(exit_, target, None)
        for node in (use, in_port, out_port):
            wiring.cut(node)


class _Plan:
    """What binding a use of one definition needs to know of the definition, worked out once per
    expansion rather than once per use: its ports, whether its roles can be bound as it is
    copied, and its parameter references in the order they are replaced."""

    def __init__(self, definition: scm.ModuleDefinition) -> None:
        self.definition = definition
        nodes = list(definition.nodes)
        self.in_ports = [n for n in nodes if isinstance(n, scm.InPort)]
        self.out_ports = [n for n in nodes if isinstance(n, scm.OutPort)]
        self.in_port: EObject | None = self.in_ports[0] if len(self.in_ports) == 1 else None
        self.out_port: EObject | None = self.out_ports[0] if len(self.out_ports) == 1 else None
        flows = [(flow.source, flow.target) for flow in definition.flows]
        # As the wiring sees a copy's ports: flows out of the in-port that lead somewhere, and
        # into the out-port that come from somewhere.
        self.in_port_wired = any(s is self.in_port and t is not None for s, t in flows)
        self.out_port_wired = any(t is self.out_port and s is not None for s, t in flows)
        contents = _with_contents(nodes)
        roles = set(definition.roles)
        # A reference to a role through a cross-file proxy is not the role object itself: the
        # copier cannot map it, so such a definition's copies are bound by a walk afterwards.
        self.roles_by_walk = any(
            target is not unwrap(target) and unwrap(target) in roles
            for obj in contents
            for _, target in single_references(obj)
        )
        self.nameless = next((p for p in definition.parameters if not p.name), None)
        self.declared = {parameter.name: parameter for parameter in definition.parameters}
        #: The parameter references in containment order, with the parameter each one names
        #: (None from the first one that names no parameter of the definition on).
        self.references: list[tuple[EObject, EObject | None]] = []
        broken = False
        for ref in contents:
            if not isinstance(ref, scm.ParameterRef):
                continue
            parameter = ref.parameter
            broken = broken or (
                parameter is None or self.declared.get(parameter.name) is not unwrap(parameter)
            )
            self.references.append((ref, None if broken else parameter))

    def check_ports(self) -> None:
        """Refuse a definition without exactly one in-port and one out-port, both wired."""
        definition = self.definition
        if self.in_port is None or self.out_port is None:
            raise FlattenError(
                f"module {definition.name!r} needs one in-port and one out-port, "
                f"has {len(self.in_ports)} and {len(self.out_ports)}",
                **location(definition),
            )
        if not self.in_port_wired or not self.out_port_wired:
            unwired = self.in_port.name if not self.in_port_wired else self.out_port.name
            raise FlattenError(
                f"module {definition.name!r}: port {unwired!r} is not wired",
                **location(definition),
            )


def _bound_actors(
    use: scm.ModuleUse,
    definition: scm.ModuleDefinition,
    where: Callable[[EObject], dict[str, Any]],
) -> dict[EObject, EObject]:
    """The actor each role of the definition is bound to by the use; FlattenError for a role
    left unbound."""
    bound = {binding.role: binding.actor for binding in use.bindings}
    actors: dict[EObject, EObject] = {}
    for role in definition.roles:
        if bound.get(role.name) is None:
            raise FlattenError(
                f"role {role.name!r} of module {definition.name!r} is not bound",
                **where(use),
            )
        actors[role] = bound[role.name]
    return actors


def _bind_roles_by_walk(nodes: list[EObject], actors: dict[EObject, EObject]) -> None:
    for obj in _with_contents(nodes):
        for feature, target in list(single_references(obj)):
            if unwrap(target) in actors:
                obj.eSet(feature, actors[unwrap(target)])


def _bind_parameters(
    use: scm.ModuleUse,
    plan: _Plan,
    copies: dict[EObject, EObject],
    where: Callable[[EObject], dict[str, Any]],
) -> list[Copier]:
    """Replace each parameter reference of the copies by a copy of the value chosen for it;
    returns the copiers that made those copies, so that each copy can be traced to the value it
    was made from."""
    definition = plan.definition
    if plan.nameless is not None:  # overrides and references find parameters by name
        raise FlattenError(
            f"module {definition.name!r} has a parameter without a name",
            **location(plan.nameless),
        )
    overrides = {override.parameter: override.value for override in use.overrides}
    declared = plan.declared
    unknown = sorted(set(overrides) - set(declared))
    if unknown:
        raise FlattenError(
            f"module {definition.name!r} has no parameter {unknown[0]!r} "
            f"(it has: {', '.join(declared) or 'none'})",
            **where(use),
        )
    copiers: list[Copier] = []
    for original, parameter in plan.references:
        ref = copies[original]
        if parameter is None:
            raise FlattenError(
                f"a parameter reference in module {definition.name!r} names no parameter of it",
                **location(ref),
            )
        chosen = overrides.get(parameter.name)
        if chosen is None:
            chosen = parameter.default
        # An unset value means the language default, as everywhere else in a scenario.
        value = _copy(chosen, copiers) if chosen is not None else None
        holder, feature = ref.eContainer(), ref.eContainmentFeature()
        if not replace_child(holder, slot(feature), value):
            holder.eSet(feature, value)
    return copiers


def _rename(node: EObject, name: str) -> None:
    """`node.name = name` for a copy nothing listens to: its holder's value, when it has one."""
    holder = node.__dict__.get("name")
    if type(holder) is EValue:
        holder._value = name
    else:
        node.name = name


def _copy(value: EObject, copiers: list[Copier]) -> EObject:
    copier = Copier()
    duplicate = copier.copy(value)
    copier.copy_references()
    copiers.append(copier)
    return duplicate


def _with_contents(nodes: Iterable[EObject]) -> list[EObject]:
    return [obj for node in nodes for obj in (node, *all_contents(node))]


def _check_self_contained(result: Expansion) -> None:
    # Anything still pointing into a library (a role of another module, say) would make the
    # flattened scenario depend on the library it is meant to replace. Checked in the order of
    # the flattened scenario's contents: its nodes, then the rest (its flows).
    scenario = result.scenario
    tops: list[EObject] = list(result.nodes)
    for feature in containments(scenario.eClass):
        if feature.name == "nodes":
            continue
        held = scenario.eGet(feature)
        tops.extend(held if feature.many else [held] if held is not None else [])
    _check_trees(tops, result)


@cache
def _walk_plan(eclass: EClass) -> tuple[tuple[str, ...], bool]:
    """The names of a metaclass's single-valued cross references, and whether it has
    containments."""
    references = tuple(f.name for f in cross_references(eclass) if not f.many)
    return references, bool(containments(eclass))


def _check_trees(tops: list[EObject], result: Expansion) -> None:
    """`_check_references` on each of `tops` and everything it contains, depth first in
    containment order; written out because it visits every object of the scenario (about five
    per node), and most of what they refer to was seen before."""
    scenario = result.scenario
    inside: set[EObject] = set()  # targets found inside: thousands of nodes name a few actors
    pending = tops[::-1]
    while pending:
        obj = pending.pop()
        references, contains = _walk_plan(obj.eClass)
        state = obj.__dict__
        for name in references:
            holder = state.get(name)
            target = holder._value if type(holder) is EValue else stored(obj, name)
            if target is None or target in inside:
                continue
            if type(target) is not EProxy and target.eContainer() is scenario:
                inside.add(target)  # a node or an actor of the scenario, named by a flow or node
                continue
            _check_references(obj, result, inside)
            break
        if contains:
            found = children(obj)
            found.reverse()
            pending.extend(found)


def _check_references(obj: EObject, result: Expansion, inside: set[EObject]) -> None:
    scenario = result.scenario
    for feature, held in single_references(obj):
        if held in inside:
            continue
        target = unwrap(held)
        top = root_of(target)
        if top is scenario or result.holds(top):
            inside.add(held)
            continue
        where = model_path(obj)
        if result.holds(obj):  # a copy belongs to no container: name it in the scenario
            where = "/".join(p for p in (model_path(scenario), where) if p)
        raise FlattenError(
            f"{feature.name} still refers to {model_path(target)} outside the "
            "scenario after expansion",
            element=where,
        )

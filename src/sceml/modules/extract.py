"""Extract a single-entry, single-exit part of a scenario into a library module and use it there.

A selection S of nodes can become a module when:

1. S is not empty and holds only maneuvers, conditions, joins and module uses;
2. every flow entering S comes from one node P outside S (the *source*), and there is one;
3. every flow leaving S comes from one node Q inside S (the *exit*), and there is one;
4. every node of S can be reached, inside S, from the nodes P leads to (the *entries*), and
   reaches Q inside S.

The module's in-port then leads to the entries and Q leads to its out-port; in the scenario,
P leads to the new use and the use to Q's former successors outside S. This keeps the meaning
(SPEC §3): the entries start when P finishes, and whatever followed Q starts when Q finishes.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model import catalog
from ..model.build import ModuleBuilder
from ..model.copying import Copier, copy_tree
from ..model.graph import predecessors, root_node, successors, topological_order
from ..model.params import as_parameter
from .errors import ExtractError
from .library import instantiate


@dataclass(frozen=True)
class RoleSpec:
    """How an actor becomes a role: the role's name and the actor kinds it accepts."""

    name: str
    kinds: tuple[str, ...]


@dataclass
class Region:
    """A selection that can become a module (see the module docstring for the terms)."""

    nodes: list[scm.GraphElement]
    source: scm.GraphElement
    entries: list[scm.GraphElement]
    exit: scm.GraphElement
    targets: list[scm.GraphElement]


@dataclass
class Extraction:
    """What extracting would do to a scenario, worked out on a copy of it (`plan_extraction`).

    The scenario is not changed: a caller applies it in its own way (the editor through its
    undo recorder) by removing the region's nodes and their flows, putting `use` at `position`
    among the scenario's nodes, and adding the flows `connections` names.
    """

    #: The selection, in the scenario's own nodes.
    region: Region
    #: The use that takes the selection's place; in no graph yet, bound to the scenario's actors.
    use: scm.ModuleUse
    #: Where the use goes among the scenario's nodes: where the selection's first node was.
    position: int

    def connections(self) -> list[tuple[scm.GraphElement, scm.GraphElement]]:
        """The flows (source, target) that connect the use in the selection's place."""
        return connections(self.region, self.use)


def connections(
    region: Region, use: scm.ModuleUse
) -> list[tuple[scm.GraphElement, scm.GraphElement]]:
    """The use's flows in the selection's place: from the selection's source to the use, and
    from the use to every node that followed the selection's exit (SPEC §3: same meaning)."""
    return [(region.source, use), *((use, target) for target in region.targets)]


def position_of(scenario: scm.Scenario, region: Region) -> int:
    """Where the use goes among the scenario's nodes: where the selection's first node was."""
    return min(list(scenario.nodes).index(n) for n in region.nodes)


def parse_role(text: str) -> tuple[str, RoleSpec]:
    """Read `actor=role:Kind1|Kind2` into (actor name, RoleSpec).

    The role name or the kinds may be left out (`bike=crosser`, `bike=:Bicycle|Pedestrian`); an
    empty name keeps the actor's name and no kinds keep the actor's own kind.
    """
    actor, equals, rest = text.partition("=")
    role, _, kinds_text = rest.partition(":")
    kinds = tuple(kind.strip() for kind in kinds_text.split("|") if kind.strip())
    if not equals or not actor.strip() or not (role.strip() or kinds):
        raise ExtractError(f"role option {text!r} is not of the form actor=role:Kind1|Kind2")
    for kind in kinds:
        if scm.ActorKind.getEEnumLiteral(kind) is None:
            options = ", ".join(literal.name for literal in scm.ActorKind.eLiterals)
            raise ExtractError(f"unknown actor kind {kind!r} in {text!r}; choose from {options}")
    return actor.strip(), RoleSpec(role.strip(), kinds)


def find_region(graph: scm.Graph, selected: Sequence[scm.GraphElement]) -> Region:
    """Check that `selected` is a single-entry, single-exit part of `graph`; ExtractError if not."""
    members = set(selected)
    _check_kinds(selected)
    entering = [f for n in selected for f in n.incoming if f.source not in members]
    leaving = [f for n in selected for f in n.outgoing if f.target not in members]
    sources = _distinct(f.source for f in entering)
    exits = _distinct(f.source for f in leaving)
    if len(sources) != 1:
        raise ExtractError(
            "the selection must be entered from exactly one node, "
            f"but is entered from {_names(sources) or 'none'}"
        )
    if len(exits) != 1:
        raise ExtractError(
            "the selection must be left from exactly one of its nodes, "
            f"but is left from {_names(exits) or 'none'}"
        )
    entries = _distinct(f.target for f in entering)
    exit_ = exits[0]
    forward = _reach(entries, members, successors)
    backward = _reach([exit_], members, predecessors)
    stray = [n for n in selected if n not in forward or n not in backward]
    if stray:
        raise ExtractError(
            f"{_names(stray)} do not lie on a path from the selection's entry "
            f"({_names(entries)}) to its exit ({exit_.name})"
        )
    order, _ = topological_order(graph)
    ordered = [n for n in order if n in members] or list(selected)
    return Region(ordered, sources[0], entries, exit_, _distinct(f.target for f in leaving))


def _check_kinds(selected: Sequence[scm.GraphElement]) -> None:
    if not selected:
        raise ExtractError("select at least one node")
    wrong = [n for n in selected if not isinstance(n, scm.ModuleElement | scm.ModuleUse)]
    if wrong:
        raise ExtractError(
            f"only maneuvers, conditions, joins and module uses can go into a module, "
            f"not {_names(wrong)}"
        )


def _distinct(items: Iterable[scm.GraphElement]) -> list[scm.GraphElement]:
    return list(dict.fromkeys(item for item in items if item is not None))


def _names(nodes: Iterable[scm.GraphElement]) -> str:
    return ", ".join(str(node.name) for node in nodes)


def _reach(
    starts: list[scm.GraphElement],
    members: set[scm.GraphElement],
    step: Callable[[scm.GraphElement], list[scm.GraphElement]],
) -> set[scm.GraphElement]:
    seen = {s for s in starts if s in members}
    todo = list(seen)
    while todo:
        for neighbour in step(todo.pop()):
            if neighbour in members and neighbour not in seen:
                seen.add(neighbour)
                todo.append(neighbour)
    return seen


def extract(
    scenario: scm.Scenario,
    node_names: Sequence[str],
    name: str,
    library: scm.Library,
    *,
    roles: Mapping[str, RoleSpec] | None = None,
    parametrize: bool = False,
) -> scm.ModuleUse:
    """Move the named nodes into a new module `name` of `library`, and use it in their place.

    Each actor the nodes refer to becomes a role named after it that accepts its kind, unless
    `roles` (actor name -> RoleSpec) says otherwise. With `parametrize`, every value the nodes
    hold becomes a module parameter (default: that value) and the use overrides it with the same
    value. Nothing is changed when an ExtractError is raised.
    """
    if not name:
        raise ExtractError("the new module needs a name")
    if name in {str(d.name) for d in library.modules}:
        raise ExtractError(f"the library already has a module {name!r}")
    selected = _select(scenario, node_names)
    region = find_region(scenario, selected)
    actor_roles = _roles_for(_actors_of(region.nodes), roles or {})
    # Everything that can fail has been checked; from here on the models are changed.
    definition = scm.ModuleDefinition(name=name, description=_description(scenario, region))
    library.modules.append(definition)
    builder = ModuleBuilder(definition)
    role_of = {actor: builder.role(spec.name, *spec.kinds) for actor, spec in actor_roles.items()}
    position = position_of(scenario, region)
    _move(scenario, region, builder, role_of)
    overrides = _parametrize(builder, region.nodes) if parametrize else {}
    bindings = {role.name: actor for actor, role in role_of.items()}
    use = instantiate(scenario, definition, bindings, overrides)
    scenario.nodes.remove(use)
    scenario.nodes.insert(position, use)
    for source, target in connections(region, use):
        scenario.flows.append(scm.Flow(source=source, target=target))
    return use


def plan_extraction(
    scenario: scm.Scenario,
    node_names: Sequence[str],
    name: str,
    library: scm.Library,
    *,
    roles: Mapping[str, RoleSpec] | None = None,
    parametrize: bool = False,
) -> Extraction:
    """`extract` run on a copy of the scenario: the new module is added to `library`, the
    scenario is left as it is, and the Extraction says how to change it (see there).

    For callers that change the scenario in their own way, e.g. with undo.
    """
    region = find_region(scenario, _select(scenario, node_names))
    copier = Copier()
    duplicate = copier.copy(scenario)
    copier.copy_references()
    original = {copy: source for source, copy in copier.copies.items()}
    use = extract(duplicate, node_names, name, library, roles=roles, parametrize=parametrize)
    duplicate.nodes.remove(use)
    for flow in [*use.incoming, *use.outgoing]:  # the copy's flows, thrown away with it
        flow.source = flow.target = None
    for binding in use.bindings:
        binding.actor = original.get(binding.actor, binding.actor)
    return Extraction(region, use, position_of(scenario, region))


def _select(scenario: scm.Scenario, node_names: Sequence[str]) -> list[scm.GraphElement]:
    by_name = {str(node.name): node for node in scenario.nodes}
    unknown = [n for n in node_names if n not in by_name]
    if unknown:
        raise ExtractError(
            f"the scenario has no node {', '.join(map(repr, unknown))} "
            f"(it has: {', '.join(by_name)})"
        )
    return [by_name[n] for n in dict.fromkeys(node_names)]


def _actors_of(nodes: Sequence[scm.GraphElement]) -> list[scm.Participant]:
    found: dict[scm.Participant, None] = {}
    for node in nodes:
        if isinstance(node, scm.ActionNode):
            candidates = [node.referenceActor, node.targetActor]
        elif isinstance(node, scm.ModuleUse):
            candidates = [binding.actor for binding in node.bindings]
        else:
            candidates = []
        found.update((actor, None) for actor in candidates if actor is not None)
    return list(found)


def _roles_for(
    actors: list[scm.Participant], given: Mapping[str, RoleSpec]
) -> dict[scm.Participant, RoleSpec]:
    names = {str(actor.name) for actor in actors}
    unused = sorted(set(given) - names)
    if unused:
        raise ExtractError(
            f"a role is given for {', '.join(unused)}, which the selected nodes do not use "
            f"(they use: {', '.join(sorted(names)) or 'no actor'})"
        )
    chosen: dict[scm.Participant, RoleSpec] = {}
    for actor in actors:
        spec = given.get(str(actor.name))
        name = spec.name if spec is not None and spec.name else str(actor.name)
        kinds = spec.kinds if spec is not None and spec.kinds else (actor.eClass.name,)
        if not any(catalog.is_kind_of(actor, kind) for kind in kinds):
            raise ExtractError(
                f"role {name!r} ({'|'.join(kinds)}) would not accept its own actor "
                f"{actor.name!r}, a {actor.eClass.name}"
            )
        chosen[actor] = RoleSpec(name, kinds)
    role_names = [spec.name for spec in chosen.values()]
    doubled = sorted({n for n in role_names if role_names.count(n) > 1})
    if doubled:
        raise ExtractError(f"two actors would get the same role name {doubled[0]!r}")
    return chosen


def _description(scenario: scm.Scenario, region: Region) -> str:
    root = root_node(scenario)
    origin = root.scenarioName if root is not None and root.scenarioName else "a scenario"
    return f"Extracted from {origin}: {_names(region.nodes)}."


def _move(
    scenario: scm.Scenario,
    region: Region,
    builder: ModuleBuilder,
    role_of: Mapping[scm.Participant, scm.ActorRole],
) -> None:
    members = set(region.nodes)
    touching = _distinct_flows(f for n in region.nodes for f in (*n.incoming, *n.outgoing))
    internal = [f for f in touching if f.source in members and f.target in members]
    for flow in touching:
        if flow not in internal:
            flow.source = flow.target = None
            scenario.flows.remove(flow)
    for entry in region.entries:
        builder.flow(builder.in_port, entry)
    builder.definition.flows.extend(internal)
    for node in region.nodes:
        builder.definition.nodes.append(node)
        for obj in (node, *node.eAllContents()):
            _rebind(obj, role_of)
    builder.flow(region.exit, builder.out_port)


def _distinct_flows(flows: Iterable[scm.Flow]) -> list[scm.Flow]:
    return list(dict.fromkeys(flows))


def _rebind(obj: EObject, role_of: Mapping[scm.Participant, scm.ActorRole]) -> None:
    for feature in obj.eClass.eAllReferences():
        if feature.containment or feature.many or feature.derived or feature.transient:
            continue
        target = obj.eGet(feature)
        if target in role_of:
            obj.eSet(feature, role_of[target])


def _parametrize(
    builder: ModuleBuilder, nodes: Sequence[scm.GraphElement]
) -> dict[str, scm.ParameterValue]:
    overrides: dict[str, scm.ParameterValue] = {}
    for node in nodes:
        if not isinstance(node, scm.ActionNode):
            continue
        for holder, feature, held in _values_in(node):
            label = "_".join([str(node.name), *_feature_path(node, holder), feature])
            unit = catalog.parameter(holder, feature).unit
            declared = builder.parameter(label, unit, copy_tree(held))
            overrides[label] = copy_tree(held)
            holder.eSet(feature, as_parameter(declared))
    return overrides


def _values_in(node: scm.ActionNode) -> list[tuple[EObject, str, scm.ParameterValue]]:
    found = []
    for holder in (node, *node.eAllContents()):
        if isinstance(holder, scm.ParameterValue):
            continue
        for spec in catalog.parameters(holder):
            held = holder.eGet(spec.name)
            if held is not None:
                found.append((holder, spec.name, held))
    return found


def _feature_path(node: EObject, holder: EObject) -> list[str]:
    steps: list[str] = []
    while holder is not node:
        feature = holder.eContainmentFeature()
        container = holder.eContainer()
        index = f"{container.eGet(feature).index(holder) + 1}" if feature.many else ""
        steps.append(f"{feature.name}{index}")
        holder = container
    return list(reversed(steps))


__all__ = [
    "Extraction",
    "Region",
    "RoleSpec",
    "connections",
    "extract",
    "find_region",
    "parse_role",
    "plan_extraction",
    "position_of",
]

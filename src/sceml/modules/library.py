"""Read module libraries: list and show definitions, and instantiate them in a graph."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from pyecore.ecore import EAttribute, EObject, EReference

import scemlmodel as scm

from ..errors import BuildError
from ..model import catalog, params
from ..model.build import GraphBuilder
from ..model.graph import successors, topological_order
from ..model.params import ParameterInput
from . import naming
from .errors import FlattenError, UnknownModuleError
from .resolve import definition_key, location, resolved_definition

#: Features every node has, shown in their own columns rather than among its parameters.
_OWN_COLUMNS = {"name", "description", "referenceActor", "targetActor", *catalog.NOTATION_FEATURES}


@dataclass
class RoleInfo:
    """An actor role and the actor kinds it accepts."""

    name: str
    kinds: list[str]


@dataclass
class ParameterInfo:
    """A module parameter: name, unit and default (None when it has none)."""

    name: str
    unit: str
    default: str | None
    description: str | None = None


@dataclass
class Size:
    """How big a definition is; `depth` is None when it cannot be computed (see `problem`)."""

    nodes: int
    flows: int
    uses: int
    depth: int | None
    problem: str | None = None


@dataclass
class DefinitionSummary:
    """One line of `sceml module list`."""

    name: str
    description: str | None
    roles: list[RoleInfo]
    parameters: list[ParameterInfo]
    size: Size


@dataclass
class NodeInfo:
    """A node of a definition: kind, who performs it, and its parameters as text."""

    name: str
    kind: str
    category: str | None
    actor: str | None = None
    target: str | None = None
    parameters: dict[str, str] = field(default_factory=dict)


@dataclass
class UseInfo:
    """A sub-module use: which definition, from which file, with which bindings and overrides."""

    name: str
    definition: str
    file: str | None
    bindings: dict[str, str]
    overrides: dict[str, str]


@dataclass
class DefinitionDetail(DefinitionSummary):
    """What `sceml module show` reports."""

    nodes: list[NodeInfo] = field(default_factory=list)
    flows: list[tuple[str, str]] = field(default_factory=list)
    uses: list[UseInfo] = field(default_factory=list)


def definition_named(library: scm.Library, name: str) -> scm.ModuleDefinition:
    """The definition called `name`; UnknownModuleError lists the names the library has."""
    for definition in library.modules:
        if definition.name == name:
            return definition
    names = ", ".join(str(d.name) for d in library.modules) or "none"
    where = location(library)
    raise UnknownModuleError(
        f"library has no module {name!r} (it has: {names})", file=where.get("file")
    )


def list_definitions(library: scm.Library) -> list[DefinitionSummary]:
    """Every definition of a library with its roles, parameters and size, in file order."""
    return [_summary(definition) for definition in library.modules]


def show(library: scm.Library, name: str) -> DefinitionDetail:
    """One definition in detail: nodes in topological order, flows and sub-module uses."""
    definition = definition_named(library, name)
    summary = _summary(definition)
    order, on_cycles = topological_order(definition)
    nodes = [*order, *[n for n in definition.nodes if n in on_cycles]]
    return DefinitionDetail(
        **vars(summary),
        nodes=[node_info(node) for node in nodes],
        flows=[
            (str(node.name), str(successor.name))
            for node in nodes
            for successor in successors(node)
        ],
        uses=[_use_info(n) for n in nodes if isinstance(n, scm.ModuleUse)],
    )


def instantiate(
    graph: scm.Graph,
    definition: scm.ModuleDefinition,
    bindings: Mapping[str, scm.Participant],
    overrides: Mapping[str, ParameterInput] | None = None,
    *,
    name: str | None = None,
) -> scm.ModuleUse:
    """Add a use of `definition` to `graph`, binding every role; flows are up to the caller.

    BuildError when a role is left unbound or a role or parameter name is not the definition's.
    """
    roles = {str(role.name) for role in definition.roles}
    declared = {str(parameter.name) for parameter in definition.parameters}
    problems = [f"unknown role {r!r}" for r in sorted(set(bindings) - roles)]
    problems += [f"role {r!r} is not bound" for r in sorted(roles - set(bindings))]
    problems += [f"unknown parameter {p!r}" for p in sorted(set(overrides or {}) - declared)]
    if problems:
        raise BuildError(f"cannot use module {definition.name!r}: {'; '.join(problems)}")
    taken = {str(node.name) for node in graph.nodes}
    chosen = name or naming.numbered(str(definition.name), taken)
    return GraphBuilder(graph).use(definition, bindings, overrides, name=chosen)


def depth(definition: scm.ModuleDefinition) -> int:
    """Nesting depth: 1 for a module without sub-module uses, else one more than its deepest use.

    FlattenError when a use cannot be resolved or the module uses itself.
    """
    return _depth(definition, ())


def _depth(definition: scm.ModuleDefinition, chain: tuple[tuple[str, str], ...]) -> int:
    key = definition_key(definition)
    if key in chain:
        names = " -> ".join(name for _, name in (*chain, key))
        raise FlattenError(f"module uses itself: {names}", **location(definition))
    deepest = 0
    for use in definition.nodes:
        if isinstance(use, scm.ModuleUse):
            deepest = max(deepest, _depth(resolved_definition(use), (*chain, key)))
    return deepest + 1


def _summary(definition: scm.ModuleDefinition) -> DefinitionSummary:
    return DefinitionSummary(
        name=str(definition.name),
        description=definition.description,
        roles=[
            RoleInfo(str(role.name), [kind.kind.name for kind in role.allowedKinds])
            for role in definition.roles
        ],
        parameters=[
            ParameterInfo(
                str(p.name),
                str(p.unit or ""),
                params.describe(p.default, p.unit or "") if p.default is not None else None,
                p.description,
            )
            for p in definition.parameters
        ],
        size=_size(definition),
    )


def _size(definition: scm.ModuleDefinition) -> Size:
    inner = [n for n in definition.nodes if not isinstance(n, scm.InPort | scm.OutPort)]
    uses = sum(isinstance(n, scm.ModuleUse) for n in inner)
    size = Size(nodes=len(inner), flows=len(definition.flows), uses=uses, depth=None)
    try:
        size.depth = depth(definition)
    except FlattenError as error:
        size.problem = error.message
    return size


def node_info(node: scm.GraphElement) -> NodeInfo:
    """A node's kind, actors and parameters as short text (positions, enums and numbers)."""
    info = NodeInfo(str(node.name), node.eClass.name, catalog.category(node))
    if isinstance(node, scm.ActionNode):
        info.actor = _participant(node.referenceActor)
        info.target = _participant(node.targetActor)
        info.parameters = describe_features(node)
    elif isinstance(node, scm.ModuleUse):
        info.parameters = {"definition": _definition_name(node)}
    return info


def describe_features(obj: EObject) -> dict[str, str]:
    """The set features of an action node or position, as name -> readable value."""
    units = {spec.name: spec.unit for spec in catalog.parameters(obj)}
    described: dict[str, str] = {}
    for feature in obj.eClass.eAllStructuralFeatures():
        if feature.name in _OWN_COLUMNS or feature.derived or feature.transient:
            continue
        if not obj.eIsSet(feature):
            continue
        held = obj.eGet(feature)
        if isinstance(feature, EAttribute):
            described[feature.name] = str(getattr(held, "name", held))
        elif isinstance(feature, EReference) and feature.containment:
            items = list(held) if feature.many else [held]
            texts = [_describe_child(item, units.get(feature.name, "")) for item in items]
            described[feature.name] = ", ".join(texts) if feature.many else texts[0]
    return described


def _describe_child(child: EObject, unit: str) -> str:
    if isinstance(child, scm.ParameterValue):
        return params.describe(child, unit)
    inner = ", ".join(f"{key}={text}" for key, text in describe_features(child).items())
    return f"{child.eClass.name}({inner})"


def _participant(participant: scm.Participant | None) -> str | None:
    return str(participant.name) if participant is not None else None


def _definition_name(use: scm.ModuleUse) -> str:
    try:
        return str(resolved_definition(use).name)
    except FlattenError as error:
        return f"(unresolved: {error.message})"


def _use_info(use: scm.ModuleUse) -> UseInfo:
    file = None
    try:
        target = resolved_definition(use)
        file = location(target).get("file")
    except FlattenError:
        pass
    return UseInfo(
        name=str(use.name),
        definition=_definition_name(use),
        file=str(file) if file is not None else None,
        bindings={str(b.role): _participant(b.actor) or "?" for b in use.bindings},
        overrides={
            str(o.parameter): params.describe(o.value) if o.value is not None else "default"
            for o in use.overrides
        },
    )

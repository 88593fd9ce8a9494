"""Module rules: uses bind roles completely and compatibly, ports are wired, no recursion, hrefs resolve."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..model.graph import nodes_of
from ..model.loading import unresolved_references
from .actors import declared_participants, label
from .context import Context, is_kind
from .reads import ABOVE, ACTORS, EXPANSION, LEVEL, MODULES, SELF, SHAPE, Aspect, Reads
from .registry import Finding, constraint

ERROR, WARNING, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO


def _bindings_by_role(use: scm.ModuleUse) -> Counter[str]:
    return Counter(str(binding.role) for binding in use.bindings)


@constraint(
    "SCEML-M001",
    ERROR,
    "ModuleUse",
    "a use binds every role of its module",
    # and its definition's roles
    reads=Reads(SELF, MODULES),
)
def roles_bound(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    definition = context.definition_of(use)
    if definition is None:
        return  # M013 says why
    bound = _bindings_by_role(use)
    for role in definition.roles:
        if bound[str(role.name)] == 0:
            yield use, f"use {use.name!r} does not bind role {role.name!r} of {definition.name!r}"


@constraint(
    "SCEML-M002",
    ERROR,
    "ModuleUse",
    "a use binds each role only once",
    reads=Reads(SELF),
)
def roles_bound_once(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    for role, count in _bindings_by_role(use).items():
        if count > 1:
            yield use, f"use {use.name!r} binds role {role!r} {count} times"


@constraint(
    "SCEML-M003",
    ERROR,
    "ModuleUse",
    "a use binds only roles its module declares",
    reads=Reads(SELF, MODULES),
)
def bindings_name_roles(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    definition = context.definition_of(use)
    if definition is None:
        return
    roles = {str(role.name) for role in definition.roles}
    for binding in use.bindings:
        if str(binding.role) not in roles:
            yield (
                binding,
                f"use {use.name!r} binds {binding.role!r}, which is no role of "
                f"{definition.name!r} (roles: {', '.join(sorted(roles)) or 'none'})",
            )


def _allowed(role: scm.ActorRole) -> list[str]:
    return [str(allowed.kind.name) for allowed in role.allowedKinds if allowed.kind is not None]


def _kind_fits(kinds: list[str], allowed: list[str]) -> bool:
    """Every kind in `kinds` is one of `allowed` or a subclass of one (abstract kinds included)."""
    return all(any(is_kind(kind, a) for a in allowed) for kind in kinds)


@constraint(
    "SCEML-M004",
    ERROR,
    "ModuleUse",
    "the actor bound to a role is of a kind the role allows (TwoWheeler accepts Bicycle and "
    "Motorcycle); an outer role bound to an inner one allows no more than it",
    reads=Reads(SELF | ACTORS, MODULES | Aspect.CAST),
)
def bound_kind_allowed(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    definition = context.definition_of(use)
    if definition is None:
        return
    roles = {str(role.name): role for role in definition.roles}
    for binding in use.bindings:
        role, actor = roles.get(str(binding.role)), binding.actor
        if role is None or actor is None or not _allowed(role):
            continue
        if isinstance(actor, scm.Actor):
            kinds = [actor.eClass.name]
        elif isinstance(actor, scm.ActorRole):
            kinds = _allowed(actor) or ["Actor"]
        else:
            continue
        if not _kind_fits(kinds, _allowed(role)):
            yield (
                binding,
                f"role {role.name!r} of {definition.name!r} accepts {' | '.join(_allowed(role))}, "
                f"but {label(actor)} is {' | '.join(kinds)}",
            )


@constraint(
    "SCEML-M005",
    ERROR,
    "ModuleUse",
    "a use overrides only parameters its module declares",
    reads=Reads(SELF, MODULES),
)
def overrides_name_parameters(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    definition = context.definition_of(use)
    if definition is None:
        return
    known = {str(parameter.name) for parameter in definition.parameters}
    for override in use.overrides:
        if str(override.parameter) not in known:
            yield (
                override,
                f"use {use.name!r} overrides {override.parameter!r}, which is no parameter of "
                f"{definition.name!r}",
            )


@constraint(
    "SCEML-M006",
    ERROR,
    "ModuleUse",
    "in a logical or concrete scenario, a use overrides every module parameter without a default",
    paper_rule="2",
    reads=Reads(SELF, MODULES | LEVEL),
)
def required_parameters_given(use: scm.ModuleUse, context: Context) -> Iterator[Finding]:
    level = context.level_of(use)
    definition = context.definition_of(use)
    if level not in ("logical", "concrete") or definition is None:
        return
    given = {str(override.parameter) for override in use.overrides if override.value is not None}
    for parameter in definition.parameters:
        if parameter.default is None and str(parameter.name) not in given:
            yield (
                use,
                f"{use.name}.{parameter.name} is missing: parameter {parameter.name!r} of "
                f"{definition.name!r} has no default, and a {level} scenario needs a value",
            )


@constraint(
    "SCEML-M007",
    ERROR,
    "ModuleDefinition",
    "a module definition has exactly one InPort and one OutPort",
    reads=Reads(aspects=SHAPE | MODULES),
)
def one_port_each(definition: scm.ModuleDefinition, context: Context) -> Iterator[Finding]:
    for kind in (scm.InPort, scm.OutPort):
        count = len(nodes_of(definition, kind))
        if count != 1:
            yield (
                definition,
                f"module {definition.name!r} has {count} {kind.__name__}s; it needs one",
            )


@constraint(
    "SCEML-M008",
    ERROR,
    "InPort",
    "an InPort has no incoming flow and at least one outgoing flow",
    reads=Reads(SELF),
)
def in_port_wired(port: scm.InPort, context: Context) -> Iterator[Finding]:
    if not isinstance(port.eContainer(), scm.ModuleDefinition):
        return  # SCEML-M011: a port outside a module is wrong as a whole
    if len(port.incoming):
        yield port, f"in-port {port.name!r} has incoming flows"
    if not len(port.outgoing):
        yield port, f"in-port {port.name!r} leads nowhere: it needs an outgoing flow"


@constraint(
    "SCEML-M009",
    ERROR,
    "OutPort",
    "an OutPort has exactly one incoming flow and no outgoing flow",
    reads=Reads(SELF),
)
def out_port_wired(port: scm.OutPort, context: Context) -> Iterator[Finding]:
    if not isinstance(port.eContainer(), scm.ModuleDefinition):
        return
    count = len(port.incoming)
    if count != 1:
        hint = "; merge with a join first" if count > 1 else ""
        yield port, f"out-port {port.name!r} has {count} incoming flows, not one{hint}"
    if len(port.outgoing):
        yield port, f"out-port {port.name!r} has outgoing flows"


@constraint(
    "SCEML-M010",
    ERROR,
    ("RootNode", "EndNode"),
    "a module definition holds no RootNode or EndNode",
    reads=Reads(SELF),
)
def no_root_or_end_in_module(node: scm.GraphElement, context: Context) -> Iterator[Finding]:
    if isinstance(node.eContainer(), scm.ModuleDefinition):
        yield node, f"{node.eClass.name} {node.name!r} inside a module; use its ports instead"


@constraint(
    "SCEML-M011",
    ERROR,
    ("InPort", "OutPort"),
    "a scenario holds no module ports",
    reads=Reads(SELF),
)
def no_ports_in_scenario(node: scm.GraphElement, context: Context) -> Iterator[Finding]:
    if isinstance(node.eContainer(), scm.Scenario):
        yield node, f"{node.eClass.name} {node.name!r} in a scenario; ports belong to modules"


@constraint(
    "SCEML-M012",
    ERROR,
    "ModuleDefinition",
    "a module does not use itself, directly or through other modules",
    source="SPEC §4",
    reads=Reads(aspects=SHAPE | MODULES),
)
def no_recursion(definition: scm.ModuleDefinition, context: Context) -> Iterator[Finding]:
    chain = _path_back_to(definition, context)
    if chain:
        names = " -> ".join(str(d.name) for d in (definition, *chain))
        yield definition, f"module {definition.name!r} uses itself: {names}"


def _path_back_to(
    start: scm.ModuleDefinition, context: Context
) -> list[scm.ModuleDefinition] | None:
    """The definitions leading from `start` back to itself through uses, or None."""
    stack: list[tuple[scm.ModuleDefinition, list[scm.ModuleDefinition]]] = [(start, [])]
    visited: set[EObject] = set()
    while stack:
        definition, path = stack.pop()
        for use in nodes_of(definition, scm.ModuleUse):
            used = context.definition_of(use)
            if used is None:
                continue
            if used is start:
                return [*path, used]
            if used not in visited:
                visited.add(used)
                stack.append((used, [*path, used]))
    return None


@constraint(
    "SCEML-M013",
    ERROR,
    ("Scenario", "ModuleDefinition"),
    "every module use refers to a definition, and cross-file references resolve",
    reads=Reads(aspects=SHAPE | MODULES),
)
def references_resolve(graph: scm.Graph, context: Context) -> Iterator[Finding]:
    for use in nodes_of(graph, scm.ModuleUse):
        if use.definition is None:
            yield use, f"use {use.name!r} refers to no module definition"
        elif context.definition_of(use) is None:
            # Only broken uses are asked again, for the reason and the path that was tried.
            for holder, href, reason in unresolved_references(use):
                yield holder, f"reference {href!r} does not resolve: {reason}"


@constraint(
    "SCEML-M014",
    ERROR,
    "Library",
    "module names are unique within a library built in memory (the builder API, the editor); "
    "a library file with two modules of one name is refused when it is read",
    # a library's modules are its contents
    reads=Reads(SELF),
)
def module_names_unique(library: scm.Library, context: Context) -> Iterator[Finding]:
    counts = Counter(str(module.name) for module in library.modules)
    for name, count in counts.items():
        if count > 1:
            first = next(m for m in library.modules if str(m.name) == name)
            yield first, f"{count} modules are named {name!r}; uses refer to modules by name"


@constraint(
    "SCEML-M015",
    ERROR,
    "RoleBinding",
    "a role is bound to an actor of the scenario (inside a module: to one of its roles)",
    reads=Reads(SELF | ABOVE | ACTORS, Aspect.CAST),
)
def binding_actor_declared(binding: scm.RoleBinding, context: Context) -> Iterator[Finding]:
    use = binding.eContainer()
    graph = use.eContainer() if use is not None else None
    if binding.actor is None:
        yield (
            binding,
            f"role {binding.role!r} of use {getattr(use, 'name', None)!r} is bound to nothing",
        )
    elif binding.actor not in declared_participants(graph, context):
        yield (
            binding,
            f"role {binding.role!r} is bound to {label(binding.actor)}, not declared here",
        )


@constraint(
    "SCEML-M016",
    ERROR,
    "ModuleDefinition",
    "roles and parameters of a module definition have names, each unique within it",
    reads=Reads(aspects=SHAPE | MODULES),
)
def module_member_names_unique(
    definition: scm.ModuleDefinition, context: Context
) -> Iterator[Finding]:
    for what, members in (("roles", definition.roles), ("parameters", definition.parameters)):
        for member in members:
            if not member.name:  # bindings and overrides name them: a nameless one is unusable
                yield member, f"module {definition.name!r} has one of its {what} without a name"
        counts = Counter(str(member.name) for member in members if member.name)
        for name, count in counts.items():
            if count > 1:
                yield definition, f"module {definition.name!r} has {count} {what} named {name!r}"


@constraint(
    "SCEML-M017",
    INFO,
    "Scenario",
    "module uses can be expanded; otherwise the checks that look inside them are skipped",
    source="engineer",
    reads=Reads(aspects=EXPANSION),
)
def uses_can_be_expanded(scenario: scm.Scenario, context: Context) -> Iterator[Finding]:
    context.flat()
    if context.flat_failure is not None:
        yield (
            scenario,
            "module uses cannot be expanded, so simultaneity, level and plausibility checks "
            f"inside them were skipped: {context.flat_failure}",
        )

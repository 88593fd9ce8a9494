"""Flatten a scenario: expand every module use, recursively, into plain nodes and flows."""

from __future__ import annotations

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from ..copying import Copier, copy_tree
from ..errors import SceMLError
from ..graph import predecessors, successors
from ..io import model_path


class FlattenError(SceMLError):
    """A module use cannot be expanded: unresolved definition, unbound role, or recursion."""


def flatten(scenario: scm.Scenario) -> scm.Scenario:
    """A copy of `scenario` with every module use expanded; the input is left untouched.

    Expanded nodes are named `<use>.<node>` (e.g. `CrossingManeuver_1.Accelerate_1`), roles are
    replaced by the actors they are bound to, parameter references by the use's overrides or the
    module's defaults, and flows into and out of a use are rewired through its ports.
    """
    copier = Copier()
    flat = copier.copy(scenario)
    copier.copy_references()
    for use in [node for node in flat.nodes if isinstance(node, scm.ModuleUse)]:
        _inline(flat, use, ())
    return flat


def resolved_definition(use: scm.ModuleUse) -> scm.ModuleDefinition:
    """The definition a use refers to, loaded if it lives in another file."""
    definition = use.definition
    if definition is None:
        raise FlattenError("module use refers to no definition", element=model_path(use))
    if isinstance(definition, EProxy):
        try:
            definition.force_resolve()
        except Exception as error:
            raise FlattenError(
                f"module definition {definition._proxy_path!r} cannot be loaded: {error}",
                element=model_path(use),
            ) from None
    return definition


def _inline(graph: scm.Graph, use: scm.ModuleUse, chain: tuple[scm.ModuleDefinition, ...]) -> None:
    definition = resolved_definition(use)
    if any(definition is seen for seen in chain):
        names = " -> ".join(str(d.name) for d in (*chain, definition))
        raise FlattenError(f"module uses itself: {names}", element=model_path(use))
    copier = Copier()
    nodes = copier.copy_all(definition.nodes)
    flows = copier.copy_all(definition.flows)
    copier.copy_references()
    _bind_roles(use, definition, nodes)
    _bind_parameters(use, definition, nodes)
    for node in nodes:
        node.name = f"{use.name}.{node.name}"
    in_port = next(n for n in nodes if isinstance(n, scm.InPort))
    out_port = next(n for n in nodes if isinstance(n, scm.OutPort))
    position = list(graph.nodes).index(use)
    for offset, node in enumerate(n for n in nodes if not isinstance(n, scm.InPort | scm.OutPort)):
        graph.nodes.insert(position + offset, node)
    for flow in flows:
        graph.flows.append(flow)
    _rewire(graph, use, in_port, out_port)
    for nested in [n for n in nodes if isinstance(n, scm.ModuleUse)]:
        _inline(graph, nested, (*chain, definition))


def _bind_roles(use: scm.ModuleUse, definition: scm.ModuleDefinition, nodes: list) -> None:
    bound = {binding.role: binding.actor for binding in use.bindings}
    actors: dict[EObject, EObject] = {}
    for role in definition.roles:
        if bound.get(role.name) is None:
            raise FlattenError(f"role {role.name!r} is not bound", element=model_path(use))
        actors[role] = bound[role.name]
    for obj in _with_contents(nodes):
        for feature in ("referenceActor", "targetActor", "actor"):
            if obj.eClass.findEStructuralFeature(feature) is None:
                continue
            target = obj.eGet(feature)
            if target in actors:
                obj.eSet(feature, actors[target])


def _bind_parameters(use: scm.ModuleUse, definition: scm.ModuleDefinition, nodes: list) -> None:
    overrides = {override.parameter: override.value for override in use.overrides}
    known = {parameter.name for parameter in definition.parameters}
    unknown = sorted(set(overrides) - known)
    if unknown:
        raise FlattenError(f"unknown parameter override {unknown[0]!r}", element=model_path(use))
    for ref in [o for o in _with_contents(nodes) if isinstance(o, scm.ParameterRef)]:
        parameter = ref.parameter
        chosen = overrides.get(parameter.name) if parameter is not None else None
        if chosen is None and parameter is not None:
            chosen = parameter.default
        container, feature = ref.eContainer(), ref.eContainmentFeature()
        container.eSet(feature, copy_tree(chosen) if chosen is not None else None)


def _with_contents(nodes: list) -> list[EObject]:
    return [obj for node in nodes for obj in (node, *node.eAllContents())]


def _rewire(
    graph: scm.Graph, use: scm.ModuleUse, in_port: scm.InPort, out_port: scm.OutPort
) -> None:
    entries = successors(in_port)
    exits = predecessors(out_port)
    before = [flow.source for flow in use.incoming]
    after = [flow.target for flow in use.outgoing]
    sources = [*exits] + (before if out_port in entries else [])
    for source in before:
        for entry in entries:
            if entry is not out_port:
                graph.flows.append(scm.Flow(source=source, target=entry))
    for exit_ in sources:
        for target in after:
            graph.flows.append(scm.Flow(source=exit_, target=target))
    for node in (use, in_port, out_port):
        for flow in [*node.incoming, *node.outgoing]:
            _remove_flow(graph, flow)
    graph.nodes.remove(use)


def _remove_flow(graph: scm.Graph, flow: scm.Flow) -> None:
    flow.source = None
    flow.target = None
    if flow in graph.flows:
        graph.flows.remove(flow)

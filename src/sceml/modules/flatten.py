"""Flatten a scenario: a copy with every module use expanded, recursively, into plain nodes and flows.

The expansion itself (names, bindings, wiring) is `expansion.expansion`; this module makes it a
scenario of its own, for the `flatten` command and the exporter.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.collector import collector_paused
from ..model.copying import Copier
from ..model.traversal import all_contents, cross_references
from .errors import FlattenError
from .expansion import Edge, Expansion, Origin, expansion, forget_references

__all__ = ["FlattenError", "Flattened", "Origin", "expand", "flatten"]


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
    expanded = expansion(scenario)
    copier = Copier()
    flat = copier.copy(scenario)
    copier.copy_references()
    copies = copier.copies
    origins = {copy: Origin(original) for original, copy in copies.items()}
    # The expansion's copies refer to the scenario's own objects (the actors roles are bound
    # to); in the flat copy they refer to the copies of those.
    for node in expanded.nodes:
        if expanded.holds(node):
            for obj in (node, *all_contents(node)):
                _point_into(obj, copies)
    origins.update(expanded.origins)
    flows: list[scm.Flow] = []
    for edge in expanded.wiring.edges:
        flow = copies.get(edge.flow) if edge.flow is not None else None
        if not edge.alive:
            if flow is not None:  # a flow of the scenario into or out of a use: dropped
                flow.source = None
                flow.target = None
            continue
        if flow is None:  # a flow inside a module, or one made to rewire a use's ports
            flow = scm.Flow(
                source=copies.get(edge.source, edge.source) if edge.source is not None else None,
                target=copies.get(edge.target, edge.target) if edge.target is not None else None,
            )
            if edge.flow is not None:
                origins[flow] = Origin(edge.flow, _uses_of(edge, expanded))
        flows.append(flow)
    flat.nodes.clear()
    flat.nodes.extend(copies.get(node, node) for node in expanded.nodes)
    flat.flows.clear()
    flat.flows.extend(flows)
    held = {flat, *all_contents(flat)}
    # Copies left out (uses, ports, parameter references that were replaced) are garbage.
    expanded.release(keep=held)
    forget_references(copy for copy in copies.values() if copy not in held)
    provenance = {obj: origin for obj, origin in origins.items() if obj in held}
    return Flattened(flat, expanded.expanded, provenance)


def _point_into(obj: EObject, copies: dict[EObject, EObject]) -> None:
    for feature in cross_references(obj.eClass):
        if feature.many:
            held = obj.eGet(feature)
            if any(target in copies for target in held):
                mapped = [copies.get(target, target) for target in held]
                held.clear()
                held.extend(mapped)
            continue
        target = obj.eGet(feature)
        if target is not None and target in copies:
            obj.eSet(feature, copies[target])


def _uses_of(edge: Edge, expanded: Expansion) -> tuple[scm.ModuleUse, ...]:
    """The uses a module's flow was expanded inside: those of the copies it connects."""
    for end in (edge.source, edge.target):
        if end is not None and expanded.holds(end):
            return expanded.origins[end].uses
    return ()

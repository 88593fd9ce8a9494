"""Export readiness (concrete level): what OpenSCENARIO needs beyond a valid graph.

Missing destinations, positions and required values are level rules (SCEML-P002); here are the
map, start positions, and whether each node kind used has a mapping for the chosen version.
"""

from __future__ import annotations

from collections.abc import Iterator

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from .context import Context
from .registry import Finding, constraint

ERROR = Severity.ERROR


@constraint("SCEML-E001", ERROR, "RootNode", "a concrete scenario names its map")
def map_is_set(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    if context.level_of(root) == "concrete" and not (root.map or "").strip():
        yield root, "a concrete scenario needs a map (an OpenDRIVE file or a simulator town)"


@constraint("SCEML-E002", ERROR, "Actor", "in a concrete scenario every actor has a start position")
def actor_has_start(actor: scm.Actor, context: Context) -> Iterator[Finding]:
    if context.level_of(actor) == "concrete" and actor.startPosition is None:
        yield actor, f"actor {actor.name!r} has no start position"


def _used_kinds(scenario: scm.Scenario, context: Context) -> dict[str, EObject]:
    """The first node of each ModuleElement kind, module internals included (via the flat view)."""
    flat = context.flat()
    nodes = flat.scenario.nodes if flat is not None else scenario.nodes
    first: dict[str, EObject] = {}
    for node in nodes:
        if isinstance(node, scm.ModuleElement):
            first.setdefault(node.eClass.name, flat.origin(node) if flat is not None else node)
    return first


@constraint(
    "SCEML-E003",
    ERROR,
    "Scenario",
    "with a target OpenSCENARIO version given, every node kind used has a mapping for it",
)
def kinds_exportable(scenario: scm.Scenario, context: Context) -> Iterator[Finding]:
    if context.osc_version is None or context.level_of(scenario) != "concrete":
        return
    # Imported late: the export package runs this validation before it exports.
    from ..export.support import unsupported_reason

    for kind, node in _used_kinds(scenario, context).items():
        reason = unsupported_reason(kind, context.osc_version)
        if reason:
            yield node, f"{kind} cannot be exported to OpenSCENARIO {context.osc_version}: {reason}"

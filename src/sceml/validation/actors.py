"""Actor rules: who performs each node, who it targets, and the scenario's cast (names, one ego)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from .. import catalog
from ..diagnostics import Severity
from ..graph import nodes_of
from .context import Context
from .registry import Finding, constraint

ERROR, WARNING = Severity.ERROR, Severity.WARNING


def declared_participants(graph: EObject | None, context: Context) -> set[EObject]:
    """The actors a scenario declares, or the roles of a module definition."""
    if graph is None:
        return set()

    def collect() -> set[EObject]:
        if isinstance(graph, scm.ModuleDefinition):
            return set(graph.roles)
        if isinstance(graph, scm.Scenario):
            return {actor for root in nodes_of(graph, scm.RootNode) for actor in root.actors}
        return set()

    return context.memo(("participants", graph), collect)


def label(participant: EObject) -> str:
    """A participant's name for messages, without resolving a proxy (which may be broken)."""
    if isinstance(participant, EProxy):
        return f"<reference {participant._proxy_path}>"
    return repr(str(participant.name))


@constraint(
    "SCEML-A001",
    ERROR,
    "ActionNode",
    "every maneuver and condition has a reference actor",
)
def has_reference_actor(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if node.referenceActor is None:
        yield node, f"{node.eClass.name} {node.name!r} has no reference actor"


@constraint(
    "SCEML-A002",
    ERROR,
    "ActionNode",
    "reference and target actors are declared in the scenario (in a module: roles of that module)",
)
def actors_declared_here(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    graph = node.eContainer()
    declared = declared_participants(graph, context)
    where = "module roles" if isinstance(graph, scm.ModuleDefinition) else "scenario's actors"
    for feature in ("referenceActor", "targetActor"):
        participant = node.eGet(feature)
        if participant is not None and participant not in declared:
            yield node, f"{feature} {label(participant)} of {node.name!r} is not one of the {where}"


@constraint(
    "SCEML-A003",
    ERROR,
    "ActionNode",
    "kinds that act relative to another actor (Follow, Approach, Overtake, InVehicleRadius, "
    "TimeToCollision, TimeHeadway) have a target actor",
)
def target_actor_where_needed(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if catalog.needs_target(node.eClass.name) and node.targetActor is None:
        yield node, f"{node.eClass.name} {node.name!r} needs a target actor"


@constraint(
    "SCEML-A004",
    WARNING,
    "ActionNode",
    "kinds that do not use a target actor have none (it would be ignored)",
    source="engineer",
)
def target_actor_only_where_used(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if not catalog.allows_target(node.eClass.name) and node.targetActor is not None:
        yield (
            node,
            f"{node.eClass.name} {node.name!r} does not use a target actor; "
            f"{label(node.targetActor)} is ignored",
        )


@constraint("SCEML-A005", ERROR, "ActionNode", "the target actor differs from the reference actor")
def target_differs_from_reference(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if node.targetActor is not None and node.targetActor is node.referenceActor:
        yield node, f"{node.name!r} targets its own reference actor {label(node.targetActor)}"


@constraint("SCEML-A006", ERROR, "RootNode", "every actor has a name, and actor names are unique")
def actor_names_unique(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    if not isinstance(root.eContainer(), scm.Scenario):
        return  # SCEML-M010: a root node inside a module is wrong as a whole
    counts = Counter(actor.name for actor in root.actors)
    reported: set[object] = set()
    for actor in root.actors:
        if not actor.name:
            yield actor, f"a {actor.eClass.name} actor has no name"
        elif counts[actor.name] > 1 and actor.name not in reported:
            reported.add(actor.name)
            yield actor, f"{counts[actor.name]} actors are named {actor.name!r}"


@constraint("SCEML-A007", ERROR, "RootNode", "exactly one actor is the ego")
def exactly_one_ego(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    if not isinstance(root.eContainer(), scm.Scenario):
        return
    egos = [actor for actor in root.actors if actor.isEgo]
    if not egos:
        yield root, "no actor is the ego; mark exactly one with isEgo"
    for extra in egos[1:]:
        first = egos[0].name
        yield extra, f"{extra.name!r} is a second ego besides {first!r}; there is exactly one"

"""Actor rules: who performs each node, who it targets, and the scenario's cast (names, one ego)."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from functools import cache
from typing import NamedTuple

from pyecore.ecore import EClass, EObject, EProxy

import scemlmodel as scm

from ..diagnostics import Severity
from ..maps.resolve import RELATIVE_KINDS, is_relative
from ..model import catalog
from ..model.graph import nodes_of
from ..model.traversal import single_value
from .context import Context
from .reads import ACTORS, SELF, VALUE, Aspect, Reads
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


class _KindActors(NamedTuple):
    """What the catalog says of a node kind's actors."""

    performed_by_actor: bool
    needs_target: bool
    allows_target: bool


@cache
def _kind(eclass: EClass) -> _KindActors:
    """The catalog's answers for a node kind, once per metaclass: SCEML-A001, A003 and A004
    ask them of every node."""
    name = str(eclass.name)
    return _KindActors(
        catalog.performed_by_actor(name), catalog.needs_target(name), catalog.allows_target(name)
    )


def label(participant: EObject) -> str:
    """A participant's name for messages, without resolving a proxy (which may be broken)."""
    if isinstance(participant, EProxy):
        return f"<reference {participant._proxy_path}>"
    return repr(str(participant.name))


@constraint(
    "SCEML-A001",
    ERROR,
    "ActionNode",
    "every maneuver and condition has a reference actor; a global kind (the parameter, variable "
    "and traffic signal nodes) has none",
    reads=Reads(SELF),
    export=True,
)
def has_reference_actor(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    global_kind = not _kind(node.eClass).performed_by_actor
    actor = single_value(node, "referenceActor")
    if actor is None and not global_kind:
        yield node, f"{node.eClass.name} {node.name!r} has no reference actor"
    if actor is not None and global_kind:
        yield (
            node,
            f"{node.eClass.name} {node.name!r} is performed by no actor; "
            f"its reference actor {label(actor)} has no meaning",
        )


@constraint(
    "SCEML-A002",
    ERROR,
    "ActionNode",
    "reference and target actors are declared in the scenario (in a module: roles of that module)",
    # and the graph's declared participants
    reads=Reads(SELF | ACTORS, Aspect.CAST),
)
def actors_declared_here(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    graph = node.eContainer()
    declared = declared_participants(graph, context)
    for feature in ("referenceActor", "targetActor"):
        participant = single_value(node, feature)
        if participant is not None and participant not in declared:
            where = (
                "module roles" if isinstance(graph, scm.ModuleDefinition) else "scenario's actors"
            )
            yield node, f"{feature} {label(participant)} of {node.name!r} is not one of the {where}"


@constraint(
    "SCEML-A003",
    ERROR,
    "ActionNode",
    "kinds that act relative to another actor (Follow, Approach, MatchSpeed, Overtake, "
    "InVehicleRadius, TimeToCollision, TimeHeadway; ConnectTrailer its trailer) have a target "
    "actor",
    reads=Reads(SELF),
    export=True,
)
def target_actor_where_needed(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if _kind(node.eClass).needs_target and single_value(node, "targetActor") is None:
        yield node, f"{node.eClass.name} {node.name!r} needs a target actor"


@constraint(
    "SCEML-A004",
    WARNING,
    "ActionNode",
    "kinds that do not use a target actor have none (it would be ignored)",
    source="engineer",
    # the target's name
    reads=Reads(SELF | ACTORS),
)
def target_actor_only_where_used(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    if _kind(node.eClass).allows_target:
        return
    target = single_value(node, "targetActor")
    if target is not None:
        yield (
            node,
            f"{node.eClass.name} {node.name!r} does not use a target actor; "
            f"{label(target)} is ignored",
        )


@constraint(
    "SCEML-A005",
    ERROR,
    "ActionNode",
    "the target actor differs from the reference actor",
    reads=Reads(SELF | ACTORS),
)
def target_differs_from_reference(node: scm.ActionNode, context: Context) -> Iterator[Finding]:
    target = single_value(node, "targetActor")
    if target is not None and target is single_value(node, "referenceActor"):
        yield node, f"{node.name!r} targets its own reference actor {label(target)}"


@constraint(
    "SCEML-A006",
    ERROR,
    "RootNode",
    "every actor has a name, and actor names are unique",
    # the root's actors are its contents
    reads=Reads(SELF),
)
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


@constraint(
    "SCEML-A007",
    ERROR,
    "RootNode",
    "exactly one actor is the ego",
    reads=Reads(SELF),
)
def exactly_one_ego(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    if not isinstance(root.eContainer(), scm.Scenario):
        return
    egos = [actor for actor in root.actors if actor.isEgo]
    if not egos:
        yield root, "no actor is the ego; mark exactly one with isEgo"
    for extra in egos[1:]:
        first = egos[0].name
        yield extra, f"{extra.name!r} is a second ego besides {first!r}; there is exactly one"


@constraint(
    "SCEML-A009",
    ERROR,
    "RootNode",
    "an actor tows another actor of the scenario, not a pedestrian and not itself; an actor is "
    "towed by at most one other, and towing forms no loop (release 1.4's Actor.trailer)",
    # the root's actors and their trailers are its contents
    reads=Reads(SELF, Aspect.CAST),
)
def trailers_form_chains(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    actors = list(root.actors)
    towers: dict[EObject, list[scm.Actor]] = {}
    for actor in actors:
        towed = actor.trailer
        if towed is None:
            continue
        if towed is actor or towed not in actors:
            what = "itself" if towed is actor else f"{label(towed)}, not an actor of the scenario"
            yield actor, f"actor {label(actor)} tows {what}"
        elif isinstance(actor, scm.Pedestrian) or isinstance(towed, scm.Pedestrian):
            yield (
                actor,
                f"actor {label(actor)} tows {label(towed)}: pedestrians neither tow nor are towed",
            )
        else:
            towers.setdefault(towed, []).append(actor)
    for towed, by in towers.items():
        if len(by) > 1:
            names = ", ".join(label(a) for a in by)
            yield towed, f"actor {label(towed)} is towed by {len(by)} actors ({names}); at most one"
    yield from _towing_loops(actors)


@constraint(
    "SCEML-A010",
    ERROR,
    ("ConnectTrailer", "DisconnectTrailer"),
    "a trailer coupling's actors are vehicles: pedestrians neither tow nor are towed (release "
    "1.5's ConnectTrailer and DisconnectTrailer, as for Actor.trailer)",
    # the reference's and target's kinds
    reads=Reads(SELF | ACTORS),
)
def couplings_join_vehicles(node: scm.CouplingManeuver, context: Context) -> Iterator[Finding]:
    for role, participant in (("tower", node.referenceActor), ("trailer", node.targetActor)):
        if isinstance(participant, scm.Pedestrian):
            yield (
                node,
                f"{node.eClass.name} {node.name!r}: its {role} {label(participant)} is a "
                "pedestrian; pedestrians neither tow nor are towed",
            )


def _towing_loops(actors: list[scm.Actor]) -> Iterator[Finding]:
    reported: set[EObject] = set()
    for first in actors:
        chain, current = [first], first.trailer
        while current is not None and current is not first and current not in chain:
            chain.append(current)
            current = current.trailer
        if current is first and first.trailer is not first and not reported & set(chain):
            reported.update(chain)
            names = " -> ".join(label(actor) for actor in [*chain, first])
            yield first, f"actors tow each other in a loop: {names}"


@constraint(
    "SCEML-A008",
    ERROR,
    RELATIVE_KINDS,
    "a relative position names its entity, an actor of the scenario (in a module: a role); a "
    "relative start names another actor, and relative starts do not name each other in a cycle",
    # A relative start follows the chain of the other actors' starts.
    reads=Reads(VALUE, Aspect.CAST | Aspect.POSITIONS | Aspect.ROLES),
)
def relative_position_has_an_anchor(position: EObject, context: Context) -> Iterator[Finding]:
    holder = position.eContainer()
    entity = position.entity
    if entity is None:
        yield position, f"the {position.eClass.name} of {_owner(holder)} names no entity"
        return
    graph = holder.eContainer() if isinstance(holder, scm.Actor) else holder
    while graph is not None and not isinstance(graph, scm.Graph):
        graph = graph.eContainer()
    declared = declared_participants(graph, context)
    if declared and entity not in declared:
        what = f"the {position.eClass.name} of {_owner(holder)}"
        yield position, f"{what} names {label(entity)}, which is not declared here"
        return
    if not isinstance(holder, scm.Actor) or position.eContainmentFeature().name != "startPosition":
        return  # a destination or condition may be relative to its own actor, where it is then
    chain, current = [holder], entity
    while True:
        if current in chain:
            names = " -> ".join(label(actor) for actor in [*chain, current])
            yield position, f"start positions relative to each other in a cycle: {names}"
            return
        chain.append(current)
        start: EObject | None = getattr(current, "startPosition", None)
        if start is None or not is_relative(start) or start.entity is None:
            return
        current = start.entity


def _owner(holder: EObject | None) -> str:
    if isinstance(holder, scm.Actor):
        return f"the start of actor {label(holder)}"
    if holder is None:
        return "nothing"
    return repr(str(getattr(holder, "name", None) or holder.eClass.name))

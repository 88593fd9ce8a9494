"""What a rule reads, as each rule declares it where it is registered (`constraint(reads=...)`).

Incremental validation (sceml.validation.incremental) re-runs a rule on an object only when
something the rule reads changed: the object itself and what it contains (SELF), the objects
above it (ABOVE), the actors it or its node refers to (ACTORS), or one of the model-wide
`Aspect`s (then on every object it applies to). A rule that declares nothing re-runs everywhere,
every time: slow, never wrong.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Flag, auto

from pyecore.ecore import EObject

from .edits import Aspect, Impact, refers_to

__all__ = [
    "ABOVE",
    "ACTORS",
    "ACTOR_VALUES",
    "EXPANSION",
    "LEVEL",
    "MODULES",
    "ROUTE",
    "SELF",
    "SHAPE",
    "VALUE",
    "Aspect",
    "Reads",
    "Scope",
    "stale",
    "stale_where",
]


class Scope(Flag):
    """What a rule reads around the object it runs on."""

    NONE = 0
    #: The object, everything it contains, its container, and for a node the flows at it, for a
    #: flow the nodes at its ends (their names and graphs).
    SELF = auto()
    #: The objects it lies in, up to its node, actor, use or module parameter: parameter paths
    #: (`ego.Accelerate_1.targetSpeed`) and "start of actor 'ego'" name them.
    ABOVE = auto()
    #: The actors or roles it, its node or its use refers to: their names, kinds, whether declared.
    #: (Incremental validation re-runs these rules also when something an actor holds changed.)
    ACTORS = auto()
    #: Values those actors hold that judge this object's values: their own limits (maxSpeed,
    #: maxAcceleration, maxDeceleration). Declared beside ACTORS; what tells a change of values
    #: alone (a sample's, `stale(values_only=True)`) from one of names or kinds.
    ACTOR_VALUES = auto()


@dataclass(frozen=True)
class Reads:
    """What one rule reads: around its object (`scope`) and across the model (`aspects`)."""

    scope: Scope = Scope.NONE
    aspects: Aspect = Aspect.NONE


# Shorthands the rule modules use in their declarations.
SELF, ABOVE, ACTORS, ACTOR_VALUES = Scope.SELF, Scope.ABOVE, Scope.ACTORS, Scope.ACTOR_VALUES
#: A rule on a value or a position: its parameter path names its containers, node and actor.
VALUE = SELF | ABOVE | ACTORS
#: The graph's shape: its nodes and flows, and their names.
SHAPE = Aspect.STRUCTURE | Aspect.NAMES
#: What expanding a scenario's module uses reads (C001, E003 and M017 look at the expansion).
EXPANSION = SHAPE | Aspect.ROLES | Aspect.CAST | Aspect.MODULES
#: Where an actor is when a turn or crossing starts: the earlier maneuvers of the same actor
#: along the flows, their destinations, its start position; and the map.
ROUTE = Aspect.STRUCTURE | Aspect.ROLES | Aspect.CAST | Aspect.POSITIONS | Aspect.SETTINGS
#: The scenario's level and map (held by the root node).
LEVEL = Aspect.SETTINGS
MODULES = Aspect.MODULES


def stale_where(
    reads: Reads | None, impact: Impact, *, values_only: bool = False
) -> tuple[bool, bool, bool, bool]:
    """Where the changes of `impact` make a rule that reads `reads` (None: it declares nothing)
    stale: (everywhere, on the objects they touched or that hold one, on the objects a touched
    one holds, on the objects referring to a touched actor or role).

    With `values_only`, the changes only set the numbers of values (a sample): an actor that
    holds one kept its name, kind and declaration, so through it only rules reading
    ACTOR_VALUES are stale."""
    if reads is None:
        return True, False, False, False
    scope = reads.scope
    through_actors = ACTOR_VALUES if values_only else ACTORS
    return (
        bool(reads.aspects & impact.aspects),
        bool(scope & Scope.SELF),
        bool(scope & Scope.ABOVE),
        bool(scope & through_actors) and bool(impact.participants),
    )


def stale(reads: Reads | None, obj: EObject, impact: Impact, *, values_only: bool = False) -> bool:
    """Whether a rule that reads `reads` reads, on `obj`, something the changes of `impact`
    changed (`stale_where`; incremental validation's `_Pass` works it out per rule once a run
    and decides per object the same way)."""
    everywhere, on_self, on_above, on_actors = stale_where(reads, impact, values_only=values_only)
    return (
        everywhere
        or (on_self and obj in impact.around)
        or (on_above and obj in impact.inside)
        or (on_actors and refers_to(obj, impact.participants))
    )

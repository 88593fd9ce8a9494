"""Plausibility rules (paper rule 5): speeds and rates fit the kind of actor that has to reach them.

A value is judged by the largest size (absolute number) it allows: a range or uniform
distribution by its larger end, a normal distribution by its bounds (and its mean when a side is
unbounded), a discrete one by its largest option; a negative speed (reversing) by its size. Exceeding a limit is an error: the limits are plausible maxima, and a project that means
to go beyond them raises them in a limits file (`sceml validate --limits FILE`).
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache

from pyecore.ecore import EClass, EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..model import catalog
from ..model.params import describe
from ..model.traversal import single_value
from .context import Context, performer
from .parameters import parameter_path
from .reads import ACTOR_VALUES, SELF, VALUE, Reads
from .registry import Finding, constraint

ERROR = Severity.ERROR

#: The kinds with a parameter an actor limit bounds; which one, the metamodel's `limit` says.
_KINDS = catalog.limited_kinds()


def highest(value: EObject | None) -> float | None:
    """The largest size (absolute number) a parameter value allows, or None when it states none.

    Sizes, not signed numbers: a speed below zero is driving backwards (release 1.4), and
    reversing at 40 m/s is as far beyond a car's limit as driving forwards at 40 m/s.
    """
    if type(value) is scm.Value:
        # Most values are single: read without the descriptor (`single_value` reads both kinds
        # of object as `value.value` does).
        number = single_value(value, "value")
        return None if number is None else abs(number)
    bounds: list[float | None] = []
    if isinstance(value, scm.Value):
        bounds = [value.value]
    elif isinstance(value, scm.Range | scm.UniformDistribution):
        bounds = [value.min, value.max]
    elif isinstance(value, scm.NormalDistribution):
        bounds = [value.lowerBound, value.upperBound]
        if value.upperBound is None or value.lowerBound is None:
            bounds.append(value.mean)
    elif isinstance(value, scm.DiscreteDistribution):
        bounds = [option.value for option in value.options]
    sizes = [abs(bound) for bound in bounds if bound is not None]
    return max(sizes) if sizes else None


#: Limit key -> the Actor feature (release 1.4) that states the actor's own limit.
OWN_LIMITS = {
    "max_speed": "maxSpeed",
    "max_acceleration": "maxAcceleration",
    "max_deceleration": "maxDeceleration",
}
#: Limit key -> the unit its values are stated in.
LIMIT_UNITS = {"max_speed": "m/s", "max_acceleration": "m/s2", "max_deceleration": "m/s2"}


def own_limit(actor: EObject, key: str) -> float | None:
    """The limit `key` the actor states itself (release 1.4's Actor.maxSpeed, ...), or None."""
    # Read past eGet: SCEML-L005 asks for each of the three limits of every node's performer.
    own = single_value(actor, OWN_LIMITS[key]) if isinstance(actor, scm.Actor) else None
    return highest(own)


def actor_limit(actor: EObject, context: Context, key: str) -> tuple[float | None, str]:
    """The limit `key` above which an actor's values are implausible (L001..L003), and whose
    it is: its kind's, unless the actor states a higher one itself (esmini's catalog bus is good
    for 70 m/s, and plays so). An own limit below the kind's does not make a value beyond it
    implausible: the players hold the actor to it, which SCEML-L005 says.

    Once per run, actor and key: each of an actor's nodes asks for each of its limits.
    """
    return context.memo(("actor limit", actor, key), lambda: _actor_limit(actor, context, key))


def _actor_limit(actor: EObject, context: Context, key: str) -> tuple[float | None, str]:
    kind = context.limits.limit(actor.eClass.name, key)
    own = own_limit(actor, key)
    if own is not None and (kind is None or own > kind):
        return own, f"{actor.name}'s own"
    return kind, f"the {actor.eClass.name}"


@cache
def _limited(eclass: EClass, key: str) -> tuple[str, ...]:
    """`catalog.limited` once per metaclass and limit: L001..L003 and L005 ask for every node."""
    return catalog.limited(eclass.name, key)


def _over(
    owner: EObject, key: str, unit: str, limit: float | None, whose: str
) -> Iterator[Finding]:
    if limit is None:
        return
    for name in _limited(owner.eClass, key):
        value = single_value(owner, name)
        top = highest(value)
        if top is not None and top > limit:
            in_kmh = f" ({limit * 3.6:g} km/h)" if unit == "m/s" else ""
            yield (
                value,
                f"{parameter_path(owner, name)} is {describe(value, unit)}, above "
                f"{whose} limit of {limit:g} {unit}{in_kmh}",
            )


def _over_limit(owner: EObject, context: Context, key: str, unit: str) -> Iterator[Finding]:
    actor = performer(owner)
    if actor is not None:
        yield from _over(owner, key, unit, *actor_limit(actor, context, key))


@constraint(
    "SCEML-L001",
    ERROR,
    _KINDS,
    "speeds (initial, target, driving, overtaking, compared) do not exceed the actor kind's "
    "max_speed (or its own maxSpeed where that is higher)",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE | ACTOR_VALUES),
    judges_stated_values=True,
)
def speed_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_speed", "m/s")


@constraint(
    "SCEML-L002",
    ERROR,
    _KINDS,
    "acceleration rates do not exceed the actor kind's max_acceleration (or its own "
    "maxAcceleration where that is higher)",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE | ACTOR_VALUES),
    judges_stated_values=True,
)
def acceleration_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_acceleration", "m/s2")


@constraint(
    "SCEML-L003",
    ERROR,
    _KINDS,
    "deceleration rates (Decelerate, Stop) do not exceed the actor kind's max_deceleration "
    "(or its own maxDeceleration where that is higher)",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE | ACTOR_VALUES),
    judges_stated_values=True,
)
def deceleration_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_deceleration", "m/s2")


@constraint(
    "SCEML-L004",
    Severity.WARNING,
    "Actor",
    "an actor's own performance (maxSpeed, maxAcceleration, maxDeceleration) does not exceed its "
    "kind's plausible limits",
    paper_rule="5",
    # the actor's own values and kind
    reads=Reads(SELF),
    judges_stated_values=True,
)
def performance_plausible(actor: scm.Actor, context: Context) -> Iterator[Finding]:
    # A warning, not an error: real catalogs state generous limits (esmini's bus: 70 m/s) that
    # only cap the motion; the speeds the scenario asks for are still judged (L001..L003).
    for key, feature in OWN_LIMITS.items():
        value = single_value(actor, feature)  # most actors state none: no holder made for it
        top = highest(value)
        limit = context.limits.limit(actor.eClass.name, key)
        if top is not None and limit is not None and top > limit:
            unit = LIMIT_UNITS[key]
            yield (
                value,
                f"{parameter_path(actor, feature)} is {describe(value, unit)}, above the "
                f"{actor.eClass.name} limit of {limit:g} {unit}",
            )


@constraint(
    "SCEML-L005",
    Severity.WARNING,
    _KINDS,
    "speeds and rates do not exceed the actor's own maxSpeed, maxAcceleration and "
    "maxDeceleration (where they are below its kind's limits: the players hold it to them)",
    paper_rule="5",
    through_modules=True,
    # the performer's own limits
    reads=Reads(VALUE | ACTOR_VALUES),
    judges_stated_values=True,
)
def within_own_performance(owner: EObject, context: Context) -> Iterator[Finding]:
    actor = performer(owner)
    if actor is None:
        return
    # Not kept per actor: read through actor_limit's memo, which lasts one run (in sampling,
    # one sample: levels/checks.py), it would be one more table to keep right.
    for key, unit in LIMIT_UNITS.items():
        own = own_limit(actor, key)
        if own is None:
            continue  # no own limit
        ceiling, _ = actor_limit(actor, context, key)
        if ceiling is not None and own >= ceiling:
            continue  # it is the ceiling L001..L003 judge by
        for value, message in _over(owner, key, unit, own, f"{actor.name}'s own"):
            yield value, f"{message}: the players hold it to that"

"""Plausibility rules (paper rule 5): speeds and rates fit the kind of actor that has to reach them.

A value is judged by the largest size (absolute number) it allows: a range or uniform
distribution by its larger end, a normal distribution by its bounds (and its mean when a side is
unbounded), a discrete one by its largest option; a negative speed (reversing) by its size. Exceeding a limit is an error: the limits are plausible maxima, and a project that means
to go beyond them raises them in a limits file (`sceml validate --limits FILE`).
"""

from __future__ import annotations

from collections.abc import Iterator

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..model import catalog
from ..model.params import describe
from .context import Context, performer
from .parameters import parameter_path
from .reads import VALUE, Reads
from .registry import Finding, constraint

ERROR = Severity.ERROR

#: The kinds with a parameter an actor limit bounds; which one, the metamodel's `limit` says.
_KINDS = catalog.limited_kinds()


def highest(value: EObject | None) -> float | None:
    """The largest size (absolute number) a parameter value allows, or None when it states none.

    Sizes, not signed numbers: a speed below zero is driving backwards (release 1.4), and
    reversing at 40 m/s is as far beyond a car's limit as driving forwards at 40 m/s.
    """
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


def _over_limit(owner: EObject, context: Context, key: str, unit: str) -> Iterator[Finding]:
    actor = performer(owner)
    if actor is None:
        return
    kind = actor.eClass.name
    limit = context.limits.limit(kind, key)
    if limit is None:
        return
    for name in catalog.limited(owner.eClass.name, key):
        value = owner.eGet(name)
        top = highest(value)
        if top is not None and top > limit:
            in_kmh = f" ({limit * 3.6:g} km/h)" if unit == "m/s" else ""
            yield (
                value,
                f"{parameter_path(owner, name)} is {describe(value, unit)}, above the "
                f"{kind} limit of {limit:g} {unit}{in_kmh}",
            )


@constraint(
    "SCEML-L001",
    ERROR,
    _KINDS,
    "speeds (initial, target, driving, overtaking, compared) do not exceed the actor kind's "
    "max_speed",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE),
    judges_stated_values=True,
)
def speed_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_speed", "m/s")


@constraint(
    "SCEML-L002",
    ERROR,
    _KINDS,
    "acceleration rates do not exceed the actor kind's max_acceleration",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE),
    judges_stated_values=True,
)
def acceleration_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_acceleration", "m/s2")


@constraint(
    "SCEML-L003",
    ERROR,
    _KINDS,
    "deceleration rates (Decelerate, Stop) do not exceed the actor kind's max_deceleration",
    paper_rule="5",
    through_modules=True,
    # the performer's kind
    reads=Reads(VALUE),
    judges_stated_values=True,
)
def deceleration_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_deceleration", "m/s2")

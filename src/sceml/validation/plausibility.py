"""Plausibility rules (paper rule 5): speeds and rates fit the kind of actor that has to reach them.

A value is judged by the highest number it allows: a range or uniform distribution by its max, a
normal distribution by its upper bound (by its mean when unbounded), a discrete one by its largest
option. Exceeding a limit is an error: the limits are plausible maxima, and a project that means
to go beyond them raises them in a limits file (`sceml validate --limits FILE`).
"""

from __future__ import annotations

from collections.abc import Iterator

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..model import catalog
from ..model.params import describe
from ..model.traversal import single_value
from .context import Context, performer
from .parameters import parameter_path
from .reads import VALUE, Reads
from .registry import Finding, constraint

ERROR = Severity.ERROR

#: The kinds with a parameter an actor limit bounds; which one, the metamodel's `limit` says.
_KINDS = catalog.limited_kinds()


def highest(value: EObject | None) -> float | None:
    """The largest number a parameter value allows, or None when it states none."""
    bound: float | None = None
    if isinstance(value, scm.Value):
        bound = value.value
    elif isinstance(value, scm.Range | scm.UniformDistribution):
        bound = value.max
    elif isinstance(value, scm.NormalDistribution):
        bound = value.upperBound if value.upperBound is not None else value.mean
    elif isinstance(value, scm.DiscreteDistribution):
        options = [option.value for option in value.options if option.value is not None]
        bound = max(options) if options else None
    return bound


def _over_limit(owner: EObject, context: Context, key: str, unit: str) -> Iterator[Finding]:
    actor = performer(owner)
    if actor is None:
        return
    kind = actor.eClass.name
    limit = context.limits.limit(kind, key)
    if limit is None:
        return
    for name in catalog.limited(owner.eClass.name, key):
        value = single_value(owner, name)
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
)
def deceleration_fits_actor(owner: EObject, context: Context) -> Iterator[Finding]:
    yield from _over_limit(owner, context, "max_deceleration", "m/s2")

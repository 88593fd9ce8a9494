"""A distribution put into an imported scenario: the places its parameters fill become logical.

Every `scm.Value` whose number is `Traced` (read from a distributed `$parameter`) is replaced by
a copy of that parameter's SceML distribution, and the root becomes `logical`. What cannot be
carried over is reported with its line and keeps the declared value: a distribution SceML has
no value for, a use inside an expression or one that fills no SceML value (an opaque node's XML,
a choice of node kind), a parameter the scenario never declares or uses, and the shared draw of
a parameter used in several places (SceML samples each place on its own).
"""

from __future__ import annotations

import scemlmodel as scm

from ..levels.paths import LevelError, slots
from ..model import params
from ..model.copying import copy_tree
from .context import Build
from .distribution import Distribution, Spec
from .parameters import Use
from .traced import Traced


def apply_distribution(build: Build, distribution: Distribution, uses: list[Use]) -> None:
    """Replace the traced values by the distribution's and report what became logical."""
    report = build.report
    report.distribution = str(distribution.path)
    for message, line in distribution.notes:
        report.add("not represented", message, distribution.where(line))
    for spec in distribution.repeated:
        report.add(
            "not represented",
            f"{spec.parameter} is distributed again: the first distribution is used",
            distribution.where(spec.line),
        )
    placed = _place(build, distribution, uses)
    for spec in distribution.specs.values():
        _check(build, distribution, spec, uses, placed.get(spec.parameter, []))
    if report.logical:
        build.root.level = scm.AbstractionLevel.logical


def _place(
    build: Build, distribution: Distribution, uses: list[Use]
) -> dict[str, list[tuple[int | None, str]]]:
    """Swap each traced Value for its distribution; returns parameter -> places filled."""
    paths = _paths(build.scenario)
    files = {use.place(): use.file for use in uses}
    placed: dict[str, list[tuple[int | None, str]]] = {}
    traced = [
        v for v in build.scenario.eAllContents() if isinstance(v, scm.Value) and _traced(v.value)
    ]
    for held in traced:
        number: Traced = held.value
        held.value = float(number)
        spec = distribution.specs.get(number.parameter)
        if spec is None or spec.value is None:
            continue
        owner, feature = held.eContainer(), held.eContainmentFeature()
        placed_value = applied(copy_tree(spec.value), number.link.scale, number.link.shift)
        owner.eSet(feature, placed_value)
        path = paths.get((id(owner), str(feature.name)), f"{owner.eClass.name}.{feature.name}")
        placed.setdefault(number.parameter, []).append((number.line, number.attribute))
        described = params.describe(placed_value)
        build.report.logical[path] = f"{number.link.text()}: {described}"
        build.report.add(
            "mapped",
            f"{path} <- {number.link.text()}: {described} (logical)",
            (files.get(number.place(), str(build.source.path)), number.line),
        )
    return placed


def applied(value: scm.ParameterValue, scale: float, shift: float) -> scm.ParameterValue:
    """`value` (a fresh copy) with every number it can take mapped by scale * x + shift: what a
    file computes from a distributed parameter with an affine expression. A negative scale
    turns the order of bounds round; spreads scale by |scale|; weights stay."""
    if scale == 1.0 and shift == 0.0:
        return value

    def line(x: float) -> float:
        return scale * x + shift

    def bounds(low: float | None, high: float | None) -> tuple[float | None, float | None]:
        ends = (None if low is None else line(low), None if high is None else line(high))
        return ends if scale > 0 else (ends[1], ends[0])

    if isinstance(value, scm.Value):
        value.value = line(value.value)
    elif isinstance(value, (scm.Range, scm.UniformDistribution)):
        value.min, value.max = bounds(value.min, value.max)
        if isinstance(value, scm.Range) and value.step is not None:
            value.step = abs(scale) * value.step
    elif isinstance(value, scm.NormalDistribution):
        value.mean = line(value.mean)
        value.standardDeviation = abs(scale) * value.standardDeviation
        value.lowerBound, value.upperBound = bounds(value.lowerBound, value.upperBound)
    elif isinstance(value, scm.DiscreteDistribution):
        for option in value.options:
            option.value = line(option.value)
    return value


def _traced(number: object) -> bool:
    return isinstance(number, Traced)


def _paths(scenario: scm.Scenario) -> dict[tuple[int, str], str]:
    """(owner, feature) -> parameter path, for the report (none when an actor and a node share
    a name, which validation reports; the report then names the class and feature)."""
    try:
        known = slots(scenario)
    except LevelError:
        return {}
    return {(id(slot.owner), slot.feature): path for path, slot in known.items()}


def _check(
    build: Build,
    distribution: Distribution,
    spec: Spec,
    uses: list[Use],
    placed: list[tuple[int | None, str]],
) -> None:
    report = build.report
    where = distribution.where(spec.line)
    name = spec.parameter
    declared = report.parameters.get(name)
    if spec.value is None:
        kept = (
            f"it keeps its declared value {declared}"
            if declared is not None
            else "and the scenario does not declare it"
        )
        report.add(
            "not represented",
            f"{name}: {spec.text} has no SceML parameter value; {kept}",
            distribution.where(spec.source_line or spec.line),
        )
        return
    if declared is None:
        report.add(
            "not represented", f"{name} is distributed but the scenario does not declare it", where
        )
        return
    mine = [use for use in uses if use.parameter == name]
    if not mine:
        report.add(
            "not represented", f"{name} is distributed but the scenario never uses it", where
        )
        return
    filled = {(line, attribute) for line, attribute in placed}
    for use in mine:
        if (use.line, use.attribute) in filled:
            continue
        why = (
            "it is used in an expression"
            if use.expression
            else "the number fills no SceML parameter there"
        )
        report.add(
            "not represented",
            f"${name} at <{use.element} {use.attribute}> keeps its declared value "
            f"{report.parameters[name]} ({why})",
            (use.file, use.line),
        )
    if len(placed) > 1:
        report.add(
            "not represented",
            f"{name} fills {len(placed)} places: SceML samples each on its own, OpenSCENARIO "
            "draws one value for all",
            where,
        )

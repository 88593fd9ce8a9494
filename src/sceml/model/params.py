"""Parameter values: make them, describe them, and read the single value a concrete scenario uses."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeAlias

from pyecore.ecore import EObject

import scemlmodel as scm

from . import catalog
from .copying import detached

Number: TypeAlias = float | int
ParameterInput: TypeAlias = Number | scm.ParameterValue | scm.ModuleParameter


def value(number: Number) -> scm.Value:
    """A single concrete value."""
    return scm.Value(value=float(number))


def span(minimum: Number, maximum: Number, step: Number | None = None) -> scm.Range:
    """A range [minimum, maximum], optionally with a step for grid sampling."""
    return scm.Range(
        min=float(minimum), max=float(maximum), step=None if step is None else float(step)
    )


def uniform(minimum: Number, maximum: Number) -> scm.UniformDistribution:
    """A uniform distribution over [minimum, maximum]."""
    return scm.UniformDistribution(min=float(minimum), max=float(maximum))


def normal(
    mean: Number, sd: Number, lower: Number | None = None, upper: Number | None = None
) -> scm.NormalDistribution:
    """A normal distribution, truncated to [lower, upper] where given."""
    return scm.NormalDistribution(
        mean=float(mean),
        standardDeviation=float(sd),
        lowerBound=None if lower is None else float(lower),
        upperBound=None if upper is None else float(upper),
    )


def discrete(
    values: Sequence[Number], weights: Sequence[Number] | None = None
) -> scm.DiscreteDistribution:
    """A discrete set of values with optional weights."""
    if weights is not None and len(weights) != len(values):
        raise ValueError("give one weight per value")
    distribution = scm.DiscreteDistribution()
    for index, number in enumerate(values):
        weight = None if weights is None else float(weights[index])
        distribution.options.append(scm.WeightedValue(value=float(number), weight=weight))
    return distribution


def as_parameter(given: ParameterInput) -> scm.ParameterValue:
    """A number becomes a Value, a module parameter a reference to it; values already placed are copied."""
    if isinstance(given, scm.ModuleParameter):
        return scm.ParameterRef(parameter=given)
    if isinstance(given, scm.ParameterValue):
        return detached(given)
    if isinstance(given, bool) or not isinstance(given, int | float):
        raise TypeError(f"expected a number or a parameter value, got {type(given).__name__}")
    return value(given)


def _number(number: float | None) -> str:
    if number is None:
        return "?"
    return f"{number:g}"


def describe_number(number: float | None, unit: str = "") -> str:
    """One number as `describe` writes a single value: `8 m/s`."""
    return _number(number) + (f" {unit}" if unit else "")


def describe(parameter: scm.ParameterValue | None, unit: str = "") -> str:
    """A short human reading: `8 m/s`, `[5, 10] step 1 m/s`, `N(8, 1) in [6, 10] m/s`, `{1, 2}`,
    `{1, 2} weights {3, 1}`, `$speed`.

    This is SceML's one compact value notation: the CLI, the review page, the canvas's boxes and
    the editor's panel (sent as display text with the view, sceml.editor.values) all read it. The
    page's coordinate inputs read and write the same notation with every digit kept
    (web/src/lib/values.ts); web/src/lib/__tests__/value-notation.json holds the cases both sides
    are tested against.
    """
    suffix = f" {unit}" if unit else ""
    if parameter is None:
        return "default"
    if isinstance(parameter, scm.Value):
        return describe_number(parameter.value, unit)
    if isinstance(parameter, scm.Range):
        step = f" step {_number(parameter.step)}" if parameter.step is not None else ""
        return f"[{_number(parameter.min)}, {_number(parameter.max)}]{step}{suffix}"
    if isinstance(parameter, scm.UniformDistribution):
        return f"U({_number(parameter.min)}, {_number(parameter.max)}){suffix}"
    if isinstance(parameter, scm.NormalDistribution):
        bounds = ""
        if parameter.lowerBound is not None or parameter.upperBound is not None:
            bounds = f" in [{_number(parameter.lowerBound)}, {_number(parameter.upperBound)}]"
        mean, sd = _number(parameter.mean), _number(parameter.standardDeviation)
        return f"N({mean}, {sd}){bounds}{suffix}"
    if isinstance(parameter, scm.DiscreteDistribution):
        items = ", ".join(_number(option.value) for option in parameter.options)
        weights = [option.weight for option in parameter.options]
        weighted = ""
        if any(weight is not None for weight in weights):
            weighted = " weights {" + ", ".join(_number(weight) for weight in weights) + "}"
        return "{" + items + "}" + weighted + suffix
    if isinstance(parameter, scm.ParameterRef):
        name = parameter.parameter.name if parameter.parameter is not None else "?"
        return f"${name}"
    return type(parameter).__name__


def is_single_value(parameter: scm.ParameterValue | None) -> bool:
    """Unset or a Value: what a concrete scenario may hold."""
    return parameter is None or isinstance(parameter, scm.Value)


def concrete(owner: EObject, name: str) -> float:
    """The value a concrete scenario uses for a parameter: its Value, or else the language default.

    Raises ValueError when the parameter holds a range or distribution, or is unset with no default.
    """
    spec = catalog.parameter(owner, name)
    held = owner.eGet(name)
    if isinstance(held, scm.Value):
        return float(held.value)
    if held is not None:
        raise ValueError(f"{name} holds {describe(held)}, not a single value")
    if spec.per_actor_default:
        return catalog.actor_dimensions(owner)[name]
    if spec.default is None:
        raise ValueError(f"{name} is not set and has no language default")
    return spec.default

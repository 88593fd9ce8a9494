"""Reading an OpenSCENARIO ParameterValueDistribution (1.1+) into SceML parameter values.

Each single-parameter distribution becomes the SceML value that means the same, or the reason
SceML cannot hold it:

- DistributionRange -> Range with step; DistributionSet -> DiscreteDistribution;
- ValueSetDistribution -> one DiscreteDistribution per parameter (its values over the sets;
  weighted by how often each occurs when that differs); the joint combination is not kept;
- UniformDistribution -> UniformDistribution; NormalDistribution -> NormalDistribution with
  sd = sqrt(variance) and its Range as bounds; ProbabilityDistributionSet -> DiscreteDistribution
  with the weights;
- LogNormalDistribution, PoissonDistribution, Histogram, UserDefinedDistribution, a value that is
  not a number: not representable (the parameter keeps its declared value; `logical.py` says so).
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

import scemlmodel as scm

from ..model import params
from ..xosc import schema
from .errors import XoscImportError
from .reading import check

#: Distributions SceML has no parameter value for, with what to say.
_UNREPRESENTABLE = {
    "LogNormalDistribution": "a log-normal distribution",
    "PoissonDistribution": "a Poisson distribution",
    "Histogram": "a histogram",
}


@dataclass(frozen=True)
class Spec:
    """What the distribution says about one parameter."""

    parameter: str
    #: The line that names the parameter.
    line: int | None
    #: The SceML value, or None when SceML cannot represent the distribution.
    value: scm.ParameterValue | None
    #: What it is (`Range [3, 7] step 1`) or why it cannot be represented.
    text: str
    #: The line of the distribution itself (where the reason is).
    source_line: int | None = None


@dataclass
class Distribution:
    """A ParameterValueDistribution file: the scenario it names and its parameters."""

    path: Path
    version: str
    #: ScenarioFile, resolved against the distribution's folder, and its line.
    scenario: Path
    scenario_line: int | None
    specs: dict[str, Spec] = field(default_factory=dict)
    #: Specs of a parameter the file distributes a second time (the first one counts).
    repeated: list[Spec] = field(default_factory=list)
    #: What the file says that no parameter value keeps: (message, line).
    notes: list[tuple[str, int | None]] = field(default_factory=list)

    def where(self, line: int | None) -> tuple[str, int | None]:
        """A place in this file, for the report."""
        return str(self.path), line


def read_distribution(path: Path, tree: etree._ElementTree, version: str) -> Distribution:
    """The distribution of a loaded ParameterValueDistribution document; XSD-checked first."""
    if version not in schema.DISTRIBUTION_VERSIONS:
        root = tree.getroot()
        raise XoscImportError(
            f"OpenSCENARIO {version} has no ParameterValueDistribution (it came with 1.1)",
            file=path,
            line=root.sourceline,
        )
    check(path, tree, version)
    element = tree.getroot().find("ParameterValueDistribution")
    assert element is not None  # the caller checked
    scenario_file = element.find("ScenarioFile")
    assert scenario_file is not None  # the XSD requires it
    found = Distribution(
        path,
        version,
        path.parent / str(scenario_file.get("filepath")),
        scenario_file.sourceline,
    )
    deterministic = element.find("Deterministic")
    if deterministic is not None:
        _deterministic(found, deterministic)
    stochastic = element.find("Stochastic")
    if stochastic is not None:
        _stochastic(found, stochastic)
    return found


def _add(found: Distribution, spec: Spec) -> None:
    if spec.parameter in found.specs:
        found.repeated.append(spec)
    else:
        found.specs[spec.parameter] = spec


def _deterministic(found: Distribution, element: etree._Element) -> None:
    for single in element.iterchildren("DeterministicSingleParameterDistribution"):
        name = str(single.get("parameterName"))
        kind = next(child for child in single if isinstance(child.tag, str))
        _add(found, _spec(name, single.sourceline, kind, _SINGLE))
    for multi in element.iterchildren("DeterministicMultiParameterDistribution"):
        for value_sets in multi.iterchildren("ValueSetDistribution"):
            _value_sets(found, value_sets)


def _stochastic(found: Distribution, element: etree._Element) -> None:
    found.notes.append(
        (
            f"numberOfTestRuns={element.get('numberOfTestRuns')} and randomSeed="
            f"{element.get('randomSeed', '(none)')} are not kept: `sceml sample` takes "
            "--n and --seed",
            element.sourceline,
        )
    )
    for holder in element.iterchildren("StochasticDistribution"):
        name = str(holder.get("parameterName"))
        kind = next(child for child in holder if isinstance(child.tag, str))
        _add(found, _spec(name, holder.sourceline, kind, _STOCHASTIC))


Reader = Callable[[etree._Element], scm.ParameterValue]


class _Unrepresentable(ValueError):
    """SceML has no parameter value for this distribution; the message says what it is."""


def _spec(name: str, line: int | None, kind: etree._Element, readers: dict[str, Reader]) -> Spec:
    reader = readers.get(str(kind.tag))
    try:
        if reader is None:
            raise _Unrepresentable(_unrepresentable(kind))
        value = reader(kind)
    except _Unrepresentable as error:
        return Spec(name, line, None, str(error), kind.sourceline)
    return Spec(name, line, value, f"{kind.tag} -> {params.describe(value)}", kind.sourceline)


def _unrepresentable(kind: etree._Element) -> str:
    if kind.tag == "UserDefinedDistribution":
        return f"a UserDefinedDistribution of type {kind.get('type')!r}"
    return _UNREPRESENTABLE.get(str(kind.tag), f"a {kind.tag}")


def _number(element: etree._Element, key: str) -> float:
    text = str(element.get(key))
    try:
        value = float(text)
    except ValueError:
        raise _Unrepresentable(f"<{element.tag} {key}={text!r}>: not a number") from None
    if not math.isfinite(value):
        raise _Unrepresentable(f"<{element.tag} {key}={text!r}>: not a finite number")
    return value


def _limits(holder: etree._Element) -> tuple[float, float]:
    limits = holder.find("Range")
    assert limits is not None  # the XSD requires it where this is called
    low, high = _number(limits, "lowerLimit"), _number(limits, "upperLimit")
    if low > high:
        raise _Unrepresentable(f"a range whose lower limit {low:g} is above its upper {high:g}")
    return low, high


def _range(kind: etree._Element) -> scm.ParameterValue:
    step = _number(kind, "stepWidth")
    if not step > 0:
        raise _Unrepresentable(f"a range with step {step:g} (SceML needs a step > 0)")
    return params.span(*_limits(kind), step)


#: The most options a discrete set may have: a model object is made per option, and a million
#: of them took over a minute and a gigabyte to build (issue 26); sampling needs far fewer.
MAX_OPTIONS = 10_000


def _options(kind: etree._Element) -> list[etree._Element]:
    elements = list(kind.iterchildren("Element"))
    if len(elements) > MAX_OPTIONS:
        raise _Unrepresentable(
            f"a {kind.tag} of {len(elements):,} values (SceML keeps at most {MAX_OPTIONS:,} "
            "options in a discrete set)"
        )
    return elements


def _set(kind: etree._Element) -> scm.ParameterValue:
    return params.discrete([_number(e, "value") for e in _options(kind)])


def _weighted(kind: etree._Element) -> scm.ParameterValue:
    elements = _options(kind)
    weights = [_number(e, "weight") for e in elements]
    if any(w < 0 for w in weights) or not sum(weights) > 0:
        raise _Unrepresentable("a set whose weights are negative or all 0")
    return params.discrete([_number(e, "value") for e in elements], weights)


def _uniform(kind: etree._Element) -> scm.ParameterValue:
    return params.uniform(*_limits(kind))


def _normal(kind: etree._Element) -> scm.ParameterValue:
    variance = _number(kind, "variance")
    if not variance > 0:
        raise _Unrepresentable(f"a normal distribution with variance {variance:g}")
    low, high = _limits(kind) if kind.find("Range") is not None else (None, None)
    return params.normal(_number(kind, "expectedValue"), math.sqrt(variance), low, high)


_SINGLE: dict[str, Reader] = {"DistributionRange": _range, "DistributionSet": _set}
_STOCHASTIC: dict[str, Reader] = {
    "ProbabilityDistributionSet": _weighted,
    "UniformDistribution": _uniform,
    "NormalDistribution": _normal,
}


def _value_sets(found: Distribution, element: etree._Element) -> None:
    """One discrete set per parameter; the combinations themselves are lost (noted)."""
    sets = list(element.iterchildren("ParameterValueSet"))
    values: dict[str, list[etree._Element]] = {}
    for value_set in sets:
        for assignment in value_set.iterchildren("ParameterAssignment"):
            values.setdefault(str(assignment.get("parameterRef")), []).append(assignment)
    for name, assignments in values.items():
        _add(found, _marginal(name, assignments, len(sets), element.sourceline))
    found.notes.append(
        (
            f"ValueSetDistribution of {', '.join(values)}: each parameter becomes the discrete "
            f"set of its values; the {len(sets)} joint combinations are not kept (SceML samples "
            "each parameter on its own)",
            element.sourceline,
        )
    )


def _marginal(name: str, assignments: list[etree._Element], sets: int, line: int | None) -> Spec:
    try:
        numbers = [_number(a, "value") for a in assignments]
    except _Unrepresentable as error:
        return Spec(name, line, None, str(error))
    if len(numbers) != sets:
        why = f"a ValueSetDistribution that sets {name} in {len(numbers)} of its {sets} sets"
        return Spec(name, line, None, why)
    counts = Counter(numbers)
    levels = list(counts)
    if len(levels) > MAX_OPTIONS:
        why = (
            f"a ValueSetDistribution giving {name} {len(levels):,} different values (SceML keeps "
            f"at most {MAX_OPTIONS:,} options in a discrete set)"
        )
        return Spec(name, line, None, why)
    weights = [float(counts[v]) for v in levels] if len(set(counts.values())) > 1 else None
    value = params.discrete(levels, weights)
    return Spec(name, line, value, f"ValueSetDistribution -> {params.describe(value)}")

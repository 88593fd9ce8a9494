"""Export a logical scenario as OpenSCENARIO parameters: a parameterized .xosc plus a
ParameterValueDistribution (1.1 and later) that refers to it.

The .xosc is the export of the scenario at its nominal values, with every varied number
written as `$name` and declared in the top-level ParameterDeclarations. The parameter name is
the SceML path with every character other than letters, digits and `_` replaced by `_`
(`CrossingManeuver_1.crossingSpeed` -> `CrossingManeuver_1_crossingSpeed`); a module parameter
that fills several places in the flattened scenario is one parameter used in all of them.

The distribution file is one of OpenSCENARIO's two kinds (the schema allows one per file):

- Deterministic, when every varied parameter is a range with a step (DistributionRange) or an
  unweighted discrete set (DistributionSet): a player runs the full factorial, like
  `sceml sample --strategy grid`;
- Stochastic otherwise, with numberOfTestRuns and randomSeed: uniform ranges and
  distributions become UniformDistribution, a normal becomes NormalDistribution (variance =
  sd squared, its bounds a Range; a one-sided bound is closed at 10 sd from the mean), and
  sets become a ProbabilityDistributionSet (ranges with a step: equal weights), like
  `sceml sample --strategy random`.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

import scemlmodel as scm

from ..files.writing import write_atomically
from ..model.graph import root_node
from ..model.loading import load_scenario
from ..model.locating import model_path
from ..xosc import schema
from ..xosc.profiles import DEFAULT_VERSION
from .apply import FlatTemplate
from .paths import LevelArgumentError, LevelError
from .space import Dimension, ParameterSpace, parameter_space

MODES = ("auto", "deterministic", "stochastic")
_UNBOUNDED_SDS = 10.0


@dataclass(frozen=True)
class DistributionFiles:
    """The two files written, and which kind of distribution the second one holds."""

    scenario: Path
    distribution: Path
    kind: str


def parameter_name(path: str) -> str:
    """The OpenSCENARIO parameter name of a SceML parameter path."""
    return re.sub(r"[^A-Za-z0-9_]", "_", path)


def export_distribution(
    logical: Path,
    out_dir: Path,
    *,
    version: str = DEFAULT_VERSION,
    mode: str = "auto",
    runs: int = 100,
    seed: int = 0,
    date: str | None = None,
    allow: Iterable[str | Path] = (),
) -> DistributionFiles:
    """Write `<stem>.xosc` (parameterized) and `<stem>.pvd.xosc` (its distribution) to out_dir.

    Files the scenario refers to are read from `sceml.files.safefiles.reading_roots(logical, allow)`.
    """
    if version not in schema.DISTRIBUTION_VERSIONS:
        raise LevelArgumentError(
            f"OpenSCENARIO {version} has no ParameterValueDistribution; use version "
            f"{', '.join(schema.DISTRIBUTION_VERSIONS)}"
        )
    if date is not None:
        from ..export.writer import header_date  # Jinja2 is loaded only when exporting

        date = header_date(date)
    scenario = load_scenario(logical, allow=allow).root
    space = parameter_space(scenario)
    kind = distribution_kind(space, mode)
    stem = logical.stem.removesuffix("-logical")
    scenario_path = out_dir / f"{stem}.xosc"
    distribution_path = out_dir / f"{stem}.pvd.xosc"
    tree = parameterized_tree(scenario, space, logical, scenario_path, version, date)
    _check(tree, version, scenario_path)
    file_date = date or _date_of(scenario)
    distribution = distribution_tree(
        space, kind, version, scenario_path.name, runs=runs, seed=seed, date=file_date
    )
    _check(distribution, version, distribution_path)
    write_atomically(scenario_path, _bytes(tree))
    write_atomically(distribution_path, _bytes(distribution))
    return DistributionFiles(scenario_path, distribution_path, kind)


def distribution_kind(space: ParameterSpace, mode: str) -> str:
    """`deterministic` or `stochastic` for this space; LevelError when `mode` cannot be met."""
    if mode not in MODES:
        raise LevelError(f"unknown distribution mode {mode!r}; use one of {', '.join(MODES)}")
    open_ = [d.path for d in space.dimensions if not _is_deterministic(d)]
    if mode == "deterministic" and open_:
        raise LevelError(
            "a deterministic distribution needs ranges with steps or unweighted sets; "
            f"these are distributions: {', '.join(open_)}"
        )
    if mode == "stochastic" and not space.dimensions:
        raise LevelError("a stochastic distribution needs at least one varied parameter")
    if mode == "auto":
        return "stochastic" if open_ else "deterministic"
    return mode


def _is_deterministic(dim: Dimension) -> bool:
    return dim.is_set and len(set(dim.weights)) == 1


def parameterized_tree(
    scenario: scm.Scenario,
    space: ParameterSpace,
    source: Path,
    target: Path,
    version: str,
    date: str | None,
) -> etree._ElementTree:
    """The export of the scenario at nominal values with each varied number as a `$parameter`."""
    from ..export import export
    from ..export.values import ParameterDeclarationSpec, number

    template = FlatTemplate(scenario, space.paths)
    nominal = [d.nominal() for d in space.dimensions]
    flat = template.fill(nominal)
    hook = {}
    for index, (path, value) in enumerate(zip(space.paths, nominal, strict=True)):
        spec = ParameterDeclarationSpec(parameter_name(path), number(value))
        for target_value in template.slots_of(index):
            owner = target_value.eContainer()
            hook[(model_path(owner), target_value.eContainmentFeature().name)] = spec
    return export(
        flat, version=version, date=date, source_path=source, output_path=target, parameters=hook
    )


def distribution_tree(
    space: ParameterSpace,
    kind: str,
    version: str,
    scenario_file: str,
    *,
    runs: int,
    seed: int,
    date: str,
) -> etree._ElementTree:
    """The ParameterValueDistribution document for `space`."""
    major, minor = version.split(".")
    root = etree.Element("OpenSCENARIO")
    etree.SubElement(
        root,
        "FileHeader",
        author="SceML",
        date=date,
        description=f"Parameter value distribution of {scenario_file}",
        revMajor=major,
        revMinor=minor,
    )
    distribution = etree.SubElement(root, "ParameterValueDistribution")
    etree.SubElement(distribution, "ScenarioFile", filepath=scenario_file)
    if kind == "deterministic":
        _deterministic(etree.SubElement(distribution, "Deterministic"), space.dimensions)
    else:
        stochastic = etree.SubElement(
            distribution, "Stochastic", numberOfTestRuns=str(runs), randomSeed=_text(seed)
        )
        _stochastic(stochastic, space.dimensions)
    return etree.ElementTree(root)


def _deterministic(parent: etree._Element, dimensions: Sequence[Dimension]) -> None:
    for dim in dimensions:
        single = etree.SubElement(
            parent,
            "DeterministicSingleParameterDistribution",
            parameterName=parameter_name(dim.path),
        )
        if dim.step is not None:
            distribution = etree.SubElement(single, "DistributionRange", stepWidth=_text(dim.step))
            etree.SubElement(
                distribution, "Range", lowerLimit=_text(dim.low), upperLimit=_text(dim.high)
            )
        else:
            distribution = etree.SubElement(single, "DistributionSet")
            for level in dim.levels:
                etree.SubElement(distribution, "Element", value=_text(level))


def _stochastic(parent: etree._Element, dimensions: Sequence[Dimension]) -> None:
    for dim in dimensions:
        holder = etree.SubElement(
            parent, "StochasticDistribution", parameterName=parameter_name(dim.path)
        )
        if dim.is_set:
            distribution = etree.SubElement(holder, "ProbabilityDistributionSet")
            for level, weight in zip(dim.levels, dim.weights, strict=True):
                etree.SubElement(distribution, "Element", value=_text(level), weight=_text(weight))
        elif dim.kind == "uniform":
            distribution = etree.SubElement(holder, "UniformDistribution")
            etree.SubElement(
                distribution, "Range", lowerLimit=_text(dim.low), upperLimit=_text(dim.high)
            )
        else:
            distribution = etree.SubElement(
                holder,
                "NormalDistribution",
                expectedValue=_text(dim.mean),
                variance=_text(dim.sd**2),
            )
            if dim.low != float("-inf") or dim.high != float("inf"):
                low = max(dim.low, dim.mean - _UNBOUNDED_SDS * dim.sd)
                high = min(dim.high, dim.mean + _UNBOUNDED_SDS * dim.sd)
                etree.SubElement(
                    distribution, "Range", lowerLimit=_text(low), upperLimit=_text(high)
                )


def _text(number: float) -> str:
    return repr(float(number))


def _date_of(scenario: scm.Scenario) -> str:
    root = root_node(scenario)
    return str(root.date) if root is not None and root.date else "1970-01-01T00:00:00"


def _check(tree: etree._ElementTree, version: str, target: Path) -> None:
    issues = schema.validate_tree(tree, version)
    if issues:
        raise LevelError(
            f"the document does not pass the OpenSCENARIO {version} XSD: {issues[0]}", file=target
        )


def _bytes(tree: etree._ElementTree) -> bytes:
    data: bytes = etree.tostring(tree, xml_declaration=True, encoding="UTF-8", pretty_print=True)
    return data

"""Refusals before mapping: wrong level, invalid model, or something a version cannot express.

The model checks are the validation registry's rules (those registered with `export=True`, run on
the flattened scenario); only the level and the profile request are the export's own.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from functools import cache

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model import graph
from ..model.locating import model_path, uri_fragment
from ..modules.flatten import Flattened
from ..validation import REGISTRY, Registry, iter_diagnostics, validate

LEVEL = "SCEML-X001"
PROFILE = "SCEML-X005"


def error(code: str, message: str, element: EObject | None = None) -> Diagnostic:
    """An error diagnostic located at `element`."""
    if element is None:
        return Diagnostic(Severity.ERROR, code, message)
    return Diagnostic(
        Severity.ERROR,
        code,
        message,
        fragment=_fragment(element),
        path=model_path(element),
        element=element,
    )


def _fragment(element: EObject) -> str | None:
    try:
        return uri_fragment(element)
    except Exception:  # pyecore cannot always build a fragment for detached copies
        return None


@cache
def export_rules() -> Registry:
    """The validation rules an export checks on the flattened scenario: what a mapping needs
    beyond a valid graph (a map, start positions, actors, destinations and positions, and node
    kinds the version and profile can express), as each rule declares (`export=True`)."""
    return REGISTRY.subset(export=True, severity=Severity.ERROR)


def level_problems(scenario: scm.Scenario) -> list[Diagnostic]:
    """Only concrete scenarios can be exported (SPEC §5)."""
    root = graph.root_node(scenario)
    if root is None:
        return [error(LEVEL, "the scenario has no root node, so no abstraction level")]
    level = graph.scenario_level(scenario)
    if level != "concrete":
        return [
            error(
                LEVEL,
                f"a {level} scenario cannot be exported; refine it to concrete first"
                + (" (sample it with `sceml sample`)" if level == "logical" else ""),
                root,
            )
        ]
    return []


def model_problems(scenario: scm.Scenario) -> list[Diagnostic]:
    """The validation errors of a model; an export refuses a model that has any."""
    return [d for d in validate(scenario) if d.severity == Severity.ERROR]


#: The plausibility rules' codes (paper rule 5, `sceml.validation.plausibility`): a speed or rate
#: above what its actor kind can plausibly reach. The values are the model's own statement.
PLAUSIBILITY_PREFIX = "SCEML-L"


def split_implausible(problems: Iterable[Diagnostic]) -> tuple[list[Diagnostic], list[Diagnostic]]:
    """The problems that still refuse an export allowed to be implausible, and the plausibility
    limits it writes anyway, each turned into a warning that says so."""
    refusing, allowed = [], []
    for problem in problems:
        if problem.code.startswith(PLAUSIBILITY_PREFIX):
            note = f"{problem.message} (written anyway: --allow-implausible)"
            allowed.append(replace(problem, severity=Severity.WARNING, message=note))
        else:
            refusing.append(problem)
    return refusing, allowed


def expressibility_problems(flat: scm.Scenario, version: str, profile: str) -> list[Diagnostic]:
    """What the mapping needs of a (flattened) scenario: the registry's export rules, run with the
    chosen version and profile (see `export_rules`)."""
    found = iter_diagnostics(
        flat, registry=export_rules(), osc_version=version, osc_profile=profile
    )
    return [d for d in found if d.severity is Severity.ERROR]


def traced(problems: Iterable[Diagnostic], flattened: Flattened | None) -> list[Diagnostic]:
    """Problems found on a flattened copy, placed at the input's element each copy stands for
    (itself, or the outermost module use it was expanded from); the path keeps the copy's name."""
    if flattened is None:
        return list(problems)
    return [_at_origin(problem, flattened) for problem in problems]


def _at_origin(problem: Diagnostic, flattened: Flattened) -> Diagnostic:
    origin = flattened.origin(problem.element) if problem.element is not None else None
    if origin is None:
        return problem
    element = origin.in_scenario
    return replace(problem, element=element, fragment=_fragment(element))

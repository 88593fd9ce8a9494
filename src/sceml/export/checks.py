"""Refusals before mapping: wrong level, invalid model, or something a version cannot express."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import replace

from pyecore.ecore import EObject

import scemlmodel as scm

from .. import catalog, graph
from ..diagnostics import Diagnostic, Severity
from ..io import model_path, uri_fragment
from ..modules.flatten import Flattened
from ..validation import validate
from .support import unsupported_reason

LEVEL = "SCEML-X001"
UNSUPPORTED = "SCEML-X002"
MISSING = "SCEML-X003"
NOT_SINGLE = "SCEML-X004"
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


def level_problems(scenario: scm.Scenario) -> list[Diagnostic]:
    """Only concrete scenarios can be exported (SPEC §5)."""
    root = graph.root_node(scenario)
    if root is None:
        return [error(MISSING, "the scenario has no root node")]
    level = root.level.name if root.level is not None else "functional"
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


def expressibility_problems(flat: scm.Scenario, version: str, profile: str) -> Iterator[Diagnostic]:
    """Node kinds the version/profile cannot express, and data the mapping needs but lacks."""
    root = graph.root_node(flat)
    if root is not None and not root.map:
        yield error(MISSING, "the root node names no map", root)
    for actor in graph.actors(flat):
        if actor.startPosition is None:
            yield error(MISSING, f"actor {actor.name!r} has no start position", actor)
    for node in flat.nodes:
        kind = node.eClass.name
        reason = unsupported_reason(kind, version, profile)
        if reason is not None:
            yield error(
                UNSUPPORTED,
                f"{node.name}: {reason} (OpenSCENARIO {version}, {profile} profile)",
                node,
            )
            continue
        if isinstance(node, scm.ActionNode):
            yield from _actors_of(node)
            yield from _positions_of(node)


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


def _actors_of(node: scm.ActionNode) -> Iterator[Diagnostic]:
    if not isinstance(node.referenceActor, scm.Actor):
        yield error(MISSING, f"{node.name} has no reference actor", node)
    if catalog.needs_target(node) and not isinstance(node.targetActor, scm.Actor):
        yield error(MISSING, f"{node.name} needs a target actor", node)


def _positions_of(node: scm.ActionNode) -> Iterator[Diagnostic]:
    if isinstance(node, scm.RoutedManeuver) and node.destination is None:
        yield error(MISSING, f"{node.name} has no destination", node)
    if isinstance(node, scm.InLocationRadius) and node.position is None:
        yield error(MISSING, f"{node.name} has no position", node)
    if isinstance(node, scm.FollowTrajectory) and not node.waypoints:
        yield error(MISSING, f"{node.name} has no waypoints", node)

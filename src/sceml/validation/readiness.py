"""Export readiness: what OpenSCENARIO needs beyond a valid graph.

Missing destinations, positions and required values are level rules (SCEML-P002); here are the
map, start positions, well-formed environment values, and whether each node kind used has a
mapping for the chosen version. Map and start positions are required from the logical level on:
sampling only changes numbers, so each sample of a clean logical scenario must be a valid
concrete one (SPEC §5).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from datetime import datetime

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..model.towing import is_towed
from ..xosc.support import (
    default_version,
    unsupported_profile_setting,
    unsupported_reason,
    unsupported_setting,
)
from .context import Context
from .reads import EXPANSION, LEVEL, SELF, Aspect, Reads
from .registry import Finding, constraint

ERROR = Severity.ERROR
#: The levels whose scenarios are, or are sampled into, executable ones.
_EXECUTABLE = ("logical", "concrete")
#: OpenSCENARIO's time of day (the time part of xsd:dateTime, to the second): HH:MM:SS.
TIME_OF_DAY = re.compile(r"([01]\d|2[0-3]):[0-5]\d:[0-5]\d")


def is_time_of_day(text: str) -> bool:
    """Whether `text` is a time of day OpenSCENARIO takes, 00:00:00 to 23:59:59."""
    return TIME_OF_DAY.fullmatch(text) is not None


@constraint(
    "SCEML-E001",
    ERROR,
    "RootNode",
    "a logical or concrete scenario names its map",
    reads=Reads(SELF, LEVEL),
    export=True,
)
def map_is_set(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    level = context.level_of(root)
    if level in _EXECUTABLE and not (root.map or "").strip():
        yield root, f"a {level} scenario needs a map (an OpenDRIVE file or a simulator town)"


@constraint(
    "SCEML-E002",
    ERROR,
    "Actor",
    "in a logical or concrete scenario every actor has a start position, but one another actor "
    "tows (it starts at its tower's hitch)",
    # the other actors' trailers (which actor is towed)
    reads=Reads(SELF, LEVEL | Aspect.CAST),
    export=True,
)
def actor_has_start(actor: scm.Actor, context: Context) -> Iterator[Finding]:
    level = context.level_of(actor)
    if level in _EXECUTABLE and actor.startPosition is None and not is_towed(actor):
        yield actor, f"actor {actor.name!r} has no start position ({level} scenario)"


@constraint(
    "SCEML-E004",
    ERROR,
    "Environment",
    "the time of day is HH:MM:SS, from 00:00:00 to 23:59:59",
    reads=Reads(SELF),
)
def time_of_day_is_valid(environment: scm.Environment, context: Context) -> Iterator[Finding]:
    text = environment.timeOfDay
    if text is not None and not is_time_of_day(text):
        yield environment, f"time of day {text!r} is not HH:MM:SS (00:00:00 to 23:59:59)"


def is_iso_date(text: str) -> bool:
    """Whether `text` is an ISO 8601 date (and time) that the export can write as xsd:dateTime."""
    try:
        datetime.fromisoformat(text)
    except ValueError:
        return False
    return True


@constraint(
    "SCEML-E005",
    ERROR,
    "RootNode",
    "the root node's date, when given, is an ISO 8601 date and time (e.g. 2026-01-01T12:00:00)",
    reads=Reads(SELF),
)
def date_is_iso(root: scm.RootNode, context: Context) -> Iterator[Finding]:
    text = root.date
    if text is not None and text.strip() and not is_iso_date(text):
        yield root, f"date {text!r} is not an ISO 8601 date, e.g. 2026-01-01T12:00:00"


def _used_kinds(scenario: scm.Scenario, context: Context) -> dict[str, EObject]:
    """The first node of each ModuleElement kind, module internals included (via the flat view)."""
    flat = context.flat()
    nodes = flat.nodes if flat is not None else scenario.nodes
    first: dict[str, EObject] = {}
    for node in nodes:
        if isinstance(node, scm.ModuleElement):
            first.setdefault(node.eClass.name, flat.origin(node) if flat is not None else node)
    return first


@constraint(
    "SCEML-E003",
    ERROR,
    "Scenario",
    "with a target OpenSCENARIO version or export profile given, every node kind used can be "
    "exported to it",
    reads=Reads(aspects=EXPANSION | LEVEL),
    export=True,
)
def kinds_exportable(scenario: scm.Scenario, context: Context) -> Iterator[Finding]:
    if context.osc_version is None and context.osc_profile is None:
        return
    if context.level_of(scenario) != "concrete":
        return
    profile = context.osc_profile or "generic"
    version = context.osc_version or default_version(profile)
    for kind, node in _used_kinds(scenario, context).items():
        reason = unsupported_reason(kind, version, profile)
        if reason:
            target = f"OpenSCENARIO {version} ({profile} profile)"
            yield node, f"{kind} cannot be exported to {target}: {reason}"


@constraint(
    "SCEML-E008",
    ERROR,
    (
        "TimeToCollision",
        "TimeHeadway",
        "InVehicleRadius",
        "SpeedCondition",
        "ParameterCondition",
        "VariableCondition",
        "ActivateController",
        "AssignController",
        "AccelerationCondition",
        "Follow",
        "Approach",
        "Actor",
        "LaneChange",
    ),
    "with a target OpenSCENARIO version or export profile given, every node's and actor's "
    "settings can be said in it (the carla profile has no lane change given in time; "
    "1.0 has no coordinateSystem, no relativeDistanceType but "
    "a RelativeDistanceCondition's, no greaterOrEqual or lessOrEqual rule, no "
    "assignment that activates, no gap kept but behind the target; before 1.2 no lighting or "
    "animation domain, no controllerType, no acceleration direction, no jerk limits of a Follow "
    "or Approach; before 1.3 no trailer)",
    # The node's own measure or controller settings, or the actor's controller, against the
    # target version.
    reads=Reads(SELF),
    export=True,
)
def settings_exportable(node: EObject, context: Context) -> Iterator[Finding]:
    if context.osc_version is None and context.osc_profile is None:
        return
    profile = context.osc_profile or "generic"
    version = context.osc_version or default_version(profile)
    reason = unsupported_setting(node, version)
    if reason:
        yield node, f"{node.name!r} cannot be exported to OpenSCENARIO {version}: {reason}"
    reason = unsupported_profile_setting(node, profile)
    if reason:
        yield node, f"{node.name!r} cannot be exported with the {profile} profile: {reason}"

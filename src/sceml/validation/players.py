"""What real players can honour: combinations whose meaning no OpenSCENARIO encoding keeps.

The meaning of each maneuver is `sceml.xosc.meaning`; the export writes it so that players
(esmini 3.6) do it. Where no encoding does, these rules say so with a code, never a silent
change of meaning (issue 25).
"""

from __future__ import annotations

from collections.abc import Iterator

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Severity
from ..maps.resolve import is_relative
from ..model.departure import latest_placing, place_after
from ..model.graph import reachable
from ..model.params import is_single_value
from .context import Context
from .reads import ACTORS, SELF, SHAPE, VALUE, Aspect, Reads
from .registry import Finding, constraint

_ROUTED = ("TurnLeft", "TurnRight", "Cross", "FollowTrajectory")
_SOURCE = "issue 25 (xosc.meaning)"


def _single(value: scm.ParameterValue | None) -> float | None:
    if value is None or not is_single_value(value):
        return None
    number = getattr(value, "value", None)
    return float(number) if number is not None else None


def _earlier_of_same_actor(node: scm.ActionNode) -> Iterator[scm.ActionNode]:
    """The nodes of the node's actor that come before it on some path from the root."""
    actor = node.referenceActor
    for before in reachable([node], backwards=True) - {node}:
        if isinstance(before, scm.ActionNode) and before.referenceActor is actor:
            yield before


@constraint(
    "SCEML-Y001",
    Severity.ERROR,
    "DriveDistance",
    "a DriveDistance drives faster than 0 m/s: players finish it distance / speed seconds after "
    "it starts, which never comes at 0 m/s (use Stop, or a condition, to wait)",
    source=_SOURCE,
    through_modules=True,
    # the node's speed
    reads=Reads(VALUE),
)
def drive_distance_moves(node: scm.DriveDistance, context: Context) -> Iterator[Finding]:
    if _single(node.speed) == 0.0:
        yield node, f"{node.name!r} drives at 0 m/s: its distance is never driven"


@constraint(
    "SCEML-Y002",
    Severity.WARNING,
    ("TurnLeft", "TurnRight"),
    "a turn after another routed or trajectory maneuver of its actor starts where that one leaves "
    "the actor: the exported route starts there, unless that place is relative to an entity "
    "(players resolve a route's waypoints when they load the file, so the route then starts at "
    "the actor's start position, where the actor may no longer be)",
    source=_SOURCE,
    through_modules=True,
    # the earlier nodes of its actor along the flows (their names and places in the message)
    reads=Reads(SELF | ACTORS, SHAPE | Aspect.ROLES | Aspect.POSITIONS),
)
def turn_starts_from_the_start(node: scm.RoutedManeuver, context: Context) -> Iterator[Finding]:
    mine = list(_earlier_of_same_actor(node))
    latest = latest_placing(mine, lambda other: reachable([other], backwards=True) - {other})
    if not latest or not is_relative(place_after(latest[0])):
        return
    routed = sorted(str(before.name) for before in mine if before.eClass.name in _ROUTED)
    if routed:
        yield (
            node,
            f"{node.name!r} comes after {', '.join(map(repr, routed))} of the same actor, and "
            f"{latest[0].name!r} leaves it at a place relative to an entity: players route it "
            "from the actor's start position",
        )


@constraint(
    "SCEML-Y003",
    Severity.WARNING,
    "DriveDistance",
    "for the carla profile, a DriveDistance's actor has not moved before it: scenario_runner "
    "counts the distance from the act's start, so what was driven before counts too",
    source=_SOURCE,
    # the earlier nodes of its actor along the flows, and the actor's initial speed
    reads=Reads(SELF | ACTORS, SHAPE | Aspect.ROLES | Aspect.PARAMETERS),
)
def carla_drive_distance_from_rest(node: scm.DriveDistance, context: Context) -> Iterator[Finding]:
    if context.osc_profile != "carla":
        return
    actor = node.referenceActor
    moving = isinstance(actor, scm.Actor) and (_single(actor.initialSpeed) or 0.0) > 0.0
    moved_by: list[EObject] = [
        before for before in _earlier_of_same_actor(node) if isinstance(before, scm.Maneuver)
    ]
    if moving or moved_by:
        why = "starts moving" if moving else f"moves in {moved_by[0].name!r} first"
        yield node, f"{node.name!r}: its actor {why}; scenario_runner counts that distance too"


@constraint(
    "SCEML-Y004",
    Severity.ERROR,
    "TimeElapsed",
    "a TimeElapsed has no edge: players wait for it as a delay on its successors' triggers, "
    "which has no test for an edge to change, so the export cannot keep one",
    source="issue 24 (Condition.edge, release 1.3)",
    through_modules=True,
    # the node's own edge
    reads=Reads(SELF),
)
def wait_without_edge(node: scm.TimeElapsed, context: Context) -> Iterator[Finding]:
    if node.edge.name != "none":
        yield node, f"{node.name!r} has the edge {node.edge.name}: a wait is a delay, set none"

"""Where an actor is when one of its nodes starts, as far as the graph says: at the destination of
its latest earlier routed maneuver, the last point of its latest trajectory, or within its latest
InLocationRadius; else at its start. Read by the map rules (SCEML-R006, R007) and by the export,
whose route for a turn starts there (`routing-test` turns at road 197, where its Init route has
brought it, far from its start)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from pyecore.ecore import EObject

import scemlmodel as scm


def places_its_actor(node: EObject) -> bool:
    """Whether the actor is at a known place when `node` is done: at a routed maneuver's
    destination, a trajectory's last point, or within an InLocationRadius (one that holds as the
    actor leaves the place says nothing of where it goes)."""
    if isinstance(node, scm.RoutedManeuver | scm.FollowTrajectory):
        return True
    return isinstance(node, scm.InLocationRadius) and node.edge.name in ("none", "rising")


def latest_placing(
    earlier: Sequence[EObject], ancestors: Callable[[EObject], set[EObject]]
) -> list[EObject]:
    """Of the actor's nodes `earlier` (in the graph's order), those that place it and that no
    other such node follows: the last places it can have come to."""
    placing = [n for n in earlier if places_its_actor(n)]
    before_others: set[EObject] = set().union(*(ancestors(n) for n in placing))
    return [n for n in placing if n not in before_others]


def place_after(node: EObject) -> scm.Position | None:
    """Where a placing node leaves its actor."""
    if isinstance(node, scm.FollowTrajectory):
        return node.waypoints[-1] if node.waypoints else None
    if isinstance(node, scm.InLocationRadius):
        return node.position
    return node.destination if isinstance(node, scm.RoutedManeuver) else None


def departure(
    node: scm.ActionNode,
    earlier: Sequence[EObject],
    ancestors: Callable[[EObject], set[EObject]],
) -> scm.Position | None:
    """Where `node`'s actor is when it starts, from its nodes `earlier` (graph order): the place
    its first latest placing node leaves it at, else its start position."""
    latest = latest_placing(earlier, ancestors)
    if latest:
        return place_after(latest[0])
    actor = node.referenceActor
    return actor.startPosition if isinstance(actor, scm.Actor) else None

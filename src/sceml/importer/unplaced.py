"""Entities the file gives no start, read as esmini reads them: a SUMO controller's template
vehicle, which esmini never places, and an actor whose first act at t = 0 is a trajectory,
which esmini places where the trajectory begins."""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from ..model import graph
from .context import Build

#: The esminiController property value of esmini's SUMO co-simulation controller.
SUMO = "SumoController"


def is_sumo_template(item: etree._Element) -> bool:
    """A ScenarioObject whose ObjectController is esmini's SumoController.

    esmini does not add such an entity to the scenario: it is the template of the vehicles
    SUMO departs from its own configuration (ScenarioReader: "SUMO template vehicles"; built
    without SUMO, esmini adds it deactivated). Nothing places it, so it has no start.
    """
    return any(_esmini_type(controller) == SUMO for controller in item.iter("Controller"))


def _esmini_type(controller: etree._Element) -> str:
    """The controller type esmini picks: the esminiController property, else (esmini warns)
    the controller's name."""
    for prop in controller.iterfind("Properties/Property"):
        if prop.get("name") == "esminiController":
            return str(prop.get("value"))
    return str(controller.get("name"))


def is_referenced(build: Build, name: str) -> bool:
    """Whether the storyboard refers to the entity (then it must stay an actor)."""
    storyboard = build.source.root.find("Storyboard")
    return storyboard is not None and any(
        str(element.get("entityRef")).split("::")[-1] == name
        for element in storyboard.iter()
        if isinstance(element.tag, str) and element.get("entityRef") is not None
    )


def start_on_first_trajectory(build: Build) -> None:
    """An actor with no start whose trajectory the root starts (at t = 0) starts at the
    trajectory's first point: esmini puts an entity where a FollowTrajectoryAction begins
    when it starts (its initialDistanceOffset, 0), so that point is where the actor is from
    the first step. The point leaves the trajectory, which the export then draws from where
    the actor stands, as for an Init trajectory."""
    for actor in build.root.actors:
        if actor.startPosition is not None:
            continue
        follow = _first_trajectory(build, actor)
        if follow is None or len(follow.waypoints) < 2:
            continue
        first = follow.waypoints[0]
        follow.waypoints.remove(first)
        follow.fromFirstWaypoint = False  # it begins where the actor starts: that point
        actor.startPosition = first
        build.report.add(
            "mapped",
            f"{actor.name}: start position at the first point of {follow.name}, which starts "
            "at t = 0 (the file gives no start; esmini places the actor there)",
        )


def _first_trajectory(build: Build, actor: scm.Actor) -> scm.FollowTrajectory | None:
    """The actor's one FollowTrajectory right after the root (none when there are two: which
    one places the actor would be a guess)."""
    at_start = [
        node
        for node in graph.successors(build.root)
        if isinstance(node, scm.ActionNode) and node.referenceActor is actor
    ]
    follows = [node for node in at_start if isinstance(node, scm.FollowTrajectory)]
    return follows[0] if len(follows) == 1 else None

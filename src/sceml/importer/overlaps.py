"""One maneuver of a kind at a time per actor (SPEC §6, simultaneity), as SceML requires.

In OpenSCENARIO a later longitudinal (or lateral) action of an actor overrides the one running;
SceML has no overriding, and two maneuvers of one actor and category must not be able to run
together. So when a maneuver could start while an earlier one of the same actor and category
may still run, it also waits for that one to finish (a JoinAllFinished before it); the report
says so, because the original would have cut the earlier one short.
"""

from __future__ import annotations

import scemlmodel as scm

from .. import catalog
from .context import Build

_AXES = {
    "longitudinal": {"longitudinal"},
    "lateral": {"lateral"},
    "composite": {"longitudinal", "lateral"},
}


def separate(build: Build) -> None:
    """Make every pair of same-actor, same-category maneuvers run one after the other."""
    maneuvers = [n for n in build.scenario.nodes if isinstance(n, scm.Maneuver)]
    for index, later in enumerate(maneuvers):
        for earlier in maneuvers[:index]:
            if _conflict(earlier, later):
                _wait(build, earlier, later)


def _axes(node: scm.Maneuver) -> set[str]:
    return _AXES.get(catalog.category(node) or "", set())


def _conflict(earlier: scm.Maneuver, later: scm.Maneuver) -> bool:
    if earlier.referenceActor is not later.referenceActor or not _axes(earlier) & _axes(later):
        return False
    return not _reaches(earlier, later) and not _reaches(later, earlier)


def _reaches(start: scm.GraphElement, goal: scm.GraphElement) -> bool:
    seen, todo = set(), [start]
    while todo:
        node = todo.pop()
        if node is goal:
            return True
        for flow in node.outgoing:
            if flow.target is not None and id(flow.target) not in seen:
                seen.add(id(flow.target))
                todo.append(flow.target)
    return False


def _wait(build: Build, earlier: scm.Maneuver, later: scm.Maneuver) -> None:
    join = build.add(scm.JoinAllFinished(), f"{later.name}_after_{earlier.name}")
    for flow in list(later.incoming):
        flow.target = join
    build.flow(earlier, join)
    build.flow(join, later)
    build.report.add(
        "guessed",
        f"{later.name} also waits for {earlier.name} to finish (in OpenSCENARIO it would cut "
        f"{earlier.name} short; SceML runs one maneuver of an actor and kind at a time)",
        node=str(later.name),
    )

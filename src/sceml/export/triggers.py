"""Conditions and trigger structure: when a node is activated and when it counts as finished.

A node is activated when its predecessors have finished (SPEC §3). Each predecessor's finish is
the completeState of one event (its *finish event*), so an activation is a list of
ConditionGroups (OR) of StoryboardElementStateConditions (AND): one group holding every
predecessor for ordinary nodes and join-all, one group per predecessor for join-one.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

#: The state every "has finished" reference waits for; CARLA accepts it (with start, end, stop).
COMPLETE = "completeState"


@dataclass(frozen=True)
class Condition:
    """One OpenSCENARIO Condition. `kind` selects the template branch; `data` its attributes."""

    name: str
    kind: str
    data: dict[str, Any] = field(default_factory=dict)
    delay: str = "0.0"
    #: Set on "has finished" references so readers (and tests) can find the predecessor.
    ref: str | None = None


Group = list[Condition]


def finished(event: str, by: str) -> Condition:
    """`event` has completed (reference to a predecessor's finish event)."""
    return Condition(
        name=f"{by}_after_{event}",
        kind="state",
        data={"type": "event", "state": COMPLETE},
        ref=event,
    )


def simulation_started(by: str) -> Condition:
    """The simulation has begun: what "the root node has finished" means."""
    return Condition(
        name=f"{by}_at_start", kind="simulation_time", data={"value": "0.0", "rule": "greaterThan"}
    )


def simulation_time_over(value: str, by: str) -> Condition:
    """Simulation time beyond `value` seconds."""
    return Condition(
        name=f"{by}_time_over", kind="simulation_time", data={"value": value, "rule": "greaterThan"}
    )


def activation(finishes: list[str | None], one: bool, by: str) -> list[Group]:
    """Groups that hold when the predecessors have finished: all of them, or `one` of them.

    A `None` finish stands for the root node.
    """
    conditions = [
        simulation_started(by) if finish is None else finished(finish, by) for finish in finishes
    ]
    if one:
        return [[condition] for condition in conditions]
    return [conditions]


def with_extra(groups: list[Group], extra: Condition) -> list[Group]:
    """Each group AND `extra`: "activated, and then `extra` holds"."""
    return [[*group, extra] for group in groups]


def delayed(groups: list[Group], delay: str) -> list[Group]:
    """The same groups with every condition delayed; exact because they stay true once true."""
    return [[replace(condition, delay=delay) for condition in group] for group in groups]

"""Conditions and trigger structure: when a node is activated and when it counts as finished.

A node is activated when its predecessors have finished (SPEC §3). A predecessor's finish is
the completeState of one event (its *finish event*), or, for a node the export writes into its
successor's trigger (`xosc.flows.inlined`), the ConditionGroups that hold when it has
finished. An activation is a list of ConditionGroups (OR) of Conditions (AND): every
predecessor's finish ANDed for ordinary nodes and join-all, ORed for join-one.
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
    #: Named after its (inlined) condition node, whose name is already taken: kept as it is,
    #: so that `sceml import` gives the node its name back.
    own: bool = False
    #: OpenSCENARIO's conditionEdge: a condition node's `edge` (an opaque one keeps its own).
    edge: str = "none"


Group = list[Condition]
#: What a predecessor's finish is: its finish event, None for the root node, or the groups of
#: an inlined node.
Finish = str | None | list[Group]


def finished(event: str, by: str) -> Condition:
    """`event` has completed (reference to a predecessor's finish event)."""
    return Condition(
        name=f"{by}_after_{event}",
        kind="state",
        data={"type": "event", "state": COMPLETE},
        ref=event,
    )


def has_started(event: str, by: str, profile: str) -> list[Group]:
    """Groups that hold from the step `event` starts on, and stay true: esmini's runningState
    or completeState (its startTransition holds for one step only); scenario_runner keeps a
    startTransition once seen and reads no runningState, so the carla profile writes that.
    What a node's finish marker waits for instead of repeating the node's activation: a
    condition before the node may then stand in the node's StartTrigger as it holds now
    (`xosc.flows`), and need not hold again when the node arrives."""
    states = ["startTransition"] if profile == "carla" else ["runningState", COMPLETE]
    return [
        [
            Condition(
                f"{by}_{state.removesuffix('State')}_{event}",
                "state",
                {"type": "event", "state": state},
                ref=event,
            )
        ]
        for state in states
    ]


def simulation_started(by: str) -> Condition:
    """The simulation has begun: what "the root node has finished" means. It holds at t = 0
    itself (`SimulationTime >= 0`; 1.0, which has no `greaterOrEqual`, `> -1`: the
    version's `Traits.started`), so the root's successors start at t = 0 (SPEC §3), in the
    instant an original's Init actions and `>= 0` triggers act, not a step later
    (`xosc.flows.flow_steps`)."""
    return Condition(name=f"{by}_at_start", kind="simulation_started")


def simulation_time_over(value: str, by: str) -> Condition:
    """Simulation time beyond `value` seconds."""
    return Condition(
        name=f"{by}_time_over", kind="simulation_time", data={"value": value, "rule": "greaterThan"}
    )


def activation(finishes: list[Finish], one: bool, by: str) -> list[Group]:
    """Groups that hold when the predecessors have finished: all of them, or `one` of them.

    A `None` finish stands for the root node; a list of groups for an inlined node, whose
    conditions are named after `by` here (so that the names do not depend on the inlined
    node's, which the file does not keep).
    """
    alternatives = [_groups_of(finish, by) for finish in finishes]
    if one:
        return _absorbed([group for groups in alternatives for group in groups])
    combined: list[Group] = [[]]
    for groups in alternatives:
        combined = [[*before, *group] for before in combined for group in groups]
    return _absorbed(combined)


def _absorbed(groups: list[Group]) -> list[Group]:
    """The groups without those that test all another group tests and more: the other holds
    whenever they do, so the OR means the same without them (an imported StopTrigger joins the
    branches it does not name with its own condition, which alone decides)."""
    tests = [{_test(condition) for condition in group} for group in groups]
    return [
        group
        for i, group in enumerate(groups)
        if not any(j != i and other < tests[i] for j, other in enumerate(tests))
    ]


def _test(condition: Condition) -> tuple[object, ...]:
    """What a condition tests, whatever its name."""
    values = tuple(sorted((key, str(value)) for key, value in condition.data.items()))
    return (condition.kind, condition.ref, condition.delay, values)


def _groups_of(finish: Finish, by: str) -> list[Group]:
    if finish is None:
        return [[simulation_started(by)]]
    if isinstance(finish, str):
        return [[finished(finish, by)]]
    return [[_named_by(condition, by) for condition in group] for group in finish]


def _named_by(condition: Condition, by: str) -> Condition:
    """An inlined node's condition as `by` waits for it."""
    if condition.ref is not None:
        return replace(condition, name=f"{by}_after_{condition.ref}")
    if condition.kind == "simulation_started":
        return replace(condition, name=f"{by}_at_start")
    return condition


def with_extra(groups: list[Group], extra: Condition) -> list[Group]:
    """Each group AND `extra`: "activated, and then `extra` holds"."""
    return [[*group, extra] for group in groups]


def delayed(groups: list[Group], delay: str, expressions: bool = True) -> list[Group]:
    """The same groups with every condition delayed by `delay` more; exact because they stay
    true once true (a wait written into its successor's trigger may already carry one).
    Without `expressions` (OpenSCENARIO 1.0) two delays of which one is a parameter cannot be
    added up: ValueError."""
    return [
        [replace(condition, delay=_sum(condition.delay, delay, expressions)) for condition in group]
        for group in groups
    ]


def _sum(first: str, second: str, expressions: bool) -> str:
    """Two delays as one: a number, or an expression where either is a parameter (1.1+)."""
    try:
        return repr(float(first) + float(second))
    except ValueError:
        pass
    if _is_zero(first):
        return second
    if _is_zero(second):
        return first
    if not expressions:
        raise ValueError(
            f"waits of {first} and {second} s in a row are one delay in the trigger after them, "
            "and OpenSCENARIO 1.0 has no expressions to add up parameters; export 1.1 or later"
        )
    return f"${{{_inner(first)} + {_inner(second)}}}"


def _is_zero(text: str) -> bool:
    try:
        return float(text) == 0.0
    except ValueError:
        return False


def _inner(text: str) -> str:
    """The content of an expression `${...}`; a parameter or number as it is."""
    return f"({text[2:-1]})" if text.startswith("${") and text.endswith("}") else text

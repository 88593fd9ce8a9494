"""Follow and Approach: a LongitudinalDistanceAction to the target, and its finish marker.

The gap is a `distance` or (release 1.5) a `timeGap`, measured between the reference points or
the boxes (`freespace`); the DynamicConstraints are the node's where it states them, else the
actor's own performance within the gap-keeping limits of `xosc.meaning` (what the export wrote
before release 1.5). `support.unsupported_setting` refuses, before any of this runs, what a
version cannot say (1.0: a leading or any-side gap; before 1.2: jerks).
"""

from __future__ import annotations

from dataclasses import replace

import scemlmodel as scm

from ..xosc import meaning
from .actions import Plan, planner, started_marker
from .context import Action, Context, Event
from .entities import own_performance
from .triggers import Condition, Group, finished
from .values import number

#: LongitudinalDisplacement literal -> OpenSCENARIO 1.1's value.
DISPLACEMENTS = {
    "trailing": "trailingReferencedEntity",
    "leading": "leadingReferencedEntity",
    "any": "any",
}


@planner("Follow", "Approach")
def plan_distance_keeping(ctx: Context, node: scm.DistanceKeeping, groups: list[Group]) -> Plan:
    """LongitudinalDistanceAction to the target; Follow keeps it (continuous) and finishes when
    the gap is first reached, Approach ends when the gap is held (the player's own end of a
    non-continuous action)."""
    name = ctx.event_names[node]
    follow = isinstance(node, scm.Follow)
    timed = node.timeGap is not None
    data = {
        "target": ctx.entity(node.targetActor),
        "gap_key": "timeGap" if timed else "distance",
        "gap": ctx.values.text(node, "timeGap" if timed else "distance"),
        "freespace": "true" if node.freespace else "false",
        "continuous": "true" if follow else "false",
        "displacement": _displacement(ctx, node),
        "limits": _limits(ctx, node),
    }
    event = Event(
        name,
        ctx.entity(node.referenceActor),
        [Action(ctx.action_name(name), "long_distance", data)],
        groups,
    )
    checks = _gap_reached(ctx, node, name, follow)
    # The marker waits for the node's own event to have started, not for its activation again:
    # a condition before the node then stands in the event's StartTrigger as it holds now
    # (`xosc.flows`) and need not hold again when the gap is reached (the condition kept a
    # marker event of its own, a step earlier: `long_dist_action_with_jerk`'s events at 1.05 s).
    done = started_marker(ctx, node, "gap_reached", name, checks[0])
    done = replace(done, groups=[[*group, *checks[1:]] for group in done.groups])
    if _may_be_interrupted(node):
        # Interrupted, the node has finished (Maneuver.interrupts): the player ends its action
        # and the event completes, with the gap perhaps never reached. Only then does a
        # Follow's event complete; an Approach's completes after its gap is held anyway.
        done = replace(done, groups=[*done.groups, [finished(name, done.name)]])
    return [event, done], done.name


def _may_be_interrupted(node: scm.Maneuver) -> bool:
    """Whether another maneuver of the node's actor that takes a part of it interrupts."""
    parts = set(meaning.controls(node.eClass.name))
    return any(
        isinstance(other, scm.Maneuver)
        and other is not node
        and other.interrupts
        and other.referenceActor is node.referenceActor
        and parts & set(meaning.controls(other.eClass.name))
        for other in node.eContainer().nodes
    )


def _displacement(ctx: Context, node: scm.DistanceKeeping) -> str | None:
    """The displacement attribute (1.1+), written only where it is not behind the target, the
    side players take when it is absent, so that earlier exports stay as they were."""
    side = node.displacement.name
    if side == "trailing" or ctx.traits.rev_minor < 1:
        return None
    return DISPLACEMENTS[side]


def _limits(ctx: Context, node: scm.DistanceKeeping) -> dict[str, str]:
    """The DynamicConstraints: the node's own, else the actor's within the gap-keeping limits.
    Without limits esmini does not drive to the gap: it moves the actor there in one step."""
    fallback = meaning.gap_limits(*own_performance(node.referenceActor))
    limits = {
        "maxAcceleration": fallback.acceleration,
        "maxDeceleration": fallback.deceleration,
        "maxSpeed": fallback.max_speed,
    }
    written = {key: number(value) for key, value in limits.items()}
    for key in (*limits, "maxAccelerationRate", "maxDecelerationRate"):
        if node.eGet(key) is not None:
            written[key] = ctx.values.text(node, key)
    return written


def _gap_reached(
    ctx: Context, node: scm.DistanceKeeping, name: str, follow: bool
) -> list[Condition]:
    """When the node has finished. A controller closes in on the gap and holds it: "less than
    the gap" may never hold, so the gap counts as reached within a slack (Follow: from above;
    Approach: either side), measured as the action measures it. A time gap is a headway."""
    timed = node.timeGap is not None
    gap = ctx.values.raw(node, "timeGap" if timed else "distance")
    if follow:
        slack = meaning.follow_time_slack(gap) if timed else meaning.follow_slack(gap)
        bounds = [("lessThan", gap + slack)]
    else:
        slack = meaning.APPROACH_REACHED_TIME if timed else meaning.APPROACH_REACHED
        bounds = [("lessThan", gap + slack), ("greaterThan", max(gap - slack, 0.0))]
    data = {
        "entity": ctx.entity(node.referenceActor),
        "target": ctx.entity(node.targetActor),
        "freespace": "true" if node.freespace else "false",
    }
    if timed:
        return [
            Condition(
                f"{name}_gap_reached", "headway", {**data, "value": number(value), "rule": rule}
            )
            for rule, value in bounds
        ]
    return [
        Condition(
            f"{name}_gap_reached",
            "relative_distance",
            {**data, "value": number(value), "rule": rule, "type": "longitudinal"},
        )
        for rule, value in bounds
    ]

"""MatchSpeed: a SpeedAction to a RelativeTargetSpeed of the target actor.

Players end a relative speed action once the speed is reached, and a continuous one never (a
later speed action of the actor overrides it). The node finishes when the speed is first
reached in both cases, so a continuous one (always a step: `sceml import` maps no other) has a
marker event that completes once its event has started: the step sets the speed at once.
"""

from __future__ import annotations

import scemlmodel as scm

from .actions import Plan, finish_marker, planner
from .context import Action, Context, Event
from .triggers import Condition, Group


@planner("MatchSpeed")
def plan_match_speed(ctx: Context, node: scm.MatchSpeed, groups: list[Group]) -> Plan:
    """The relative speed in every version and profile: a step (time 0) when the node has no
    rate, else linear at its rate; a continuous one with its finish marker."""
    name = ctx.event_names[node]
    factor = node.relation.name == "factor"
    dynamics = (
        {"shape": "step", "dimension": "time", "dynamics_value": "0"}
        if node.rate is None
        else {
            "shape": "linear",
            "dimension": "rate",
            "dynamics_value": ctx.values.text(node, "rate"),
        }
    )
    data = {
        **dynamics,
        "entity": ctx.entity(node.targetActor),
        "value_type": node.relation.name,
        "target_value": ctx.values.text(node, "speedFactor" if factor else "speedDelta"),
        "continuous": "true" if node.continuous else "false",
    }
    action = Action(ctx.action_name(name), "match_speed", data)
    event = Event(name, ctx.entity(node.referenceActor), [action], groups)
    if not node.continuous:
        return [event], name
    started = Condition(
        f"{name}_set", "state", {"type": "event", "state": "startTransition"}, ref=name
    )
    done = finish_marker(ctx, node, "set", [[]], started)
    return [event, done], done.name

"""StandStill and AccelerationCondition: a marker event on the actor's StandStillCondition or
AccelerationCondition, as the other measuring conditions are written."""

from __future__ import annotations

import scemlmodel as scm

from .actions import Plan, marker_plan, planner
from .context import Context
from .triggers import Condition, Group


@planner("StandStill")
def plan_stand_still(ctx: Context, node: scm.StandStill, groups: list[Group]) -> Plan:
    """A marker on StandStillCondition (every version and profile)."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    data = {"entity": entity, "duration": ctx.values.text(node, "duration")}
    check = Condition(f"{name}_stand_still", "stand_still", data)
    return marker_plan(ctx, node, groups, entity, check)


@planner("AccelerationCondition")
def plan_acceleration(ctx: Context, node: scm.AccelerationCondition, groups: list[Group]) -> Plan:
    """A marker on AccelerationCondition; the direction only when not the magnitude (1.2+,
    refused before by `xosc.support.unsupported_setting`)."""
    name = ctx.event_names[node]
    entity = ctx.entity(node.referenceActor)
    direction = node.direction.name
    data = {
        "entity": entity,
        "value": ctx.values.text(node, "acceleration"),
        "rule": node.rule.name,
        "direction": None if direction == "total" else direction,
    }
    check = Condition(f"{name}_acceleration", "acceleration", data)
    return marker_plan(ctx, node, groups, entity, check)

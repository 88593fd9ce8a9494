"""LaneOffset: a LaneOffsetAction to an absolute offset, or one relative to the target actor."""

from __future__ import annotations

import scemlmodel as scm

from .actions import Plan, action_plan, planner
from .context import Context
from .triggers import Group


@planner("LaneOffset", one_event=True)
def plan_lane_offset(ctx: Context, node: scm.LaneOffset, groups: list[Group]) -> Plan:
    """The action (every version and profile); the event completes when the offset is reached,
    which esmini 3.6 also does for a continuous one (`xosc.meaning.lane_offset_duration`)."""
    data = {
        "continuous": "true" if node.continuous else "false",
        "shape": node.shape.name,
        "max_lateral_acc": ctx.values.text(node, "maxLateralAcc"),
        "value": ctx.values.text(node, "offset"),
        "entity": None if node.targetActor is None else ctx.entity(node.targetActor),
    }
    return action_plan(ctx, node, groups, "lane_offset", data)

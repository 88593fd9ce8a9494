"""ConnectTrailer and DisconnectTrailer: one TrailerAction each (OpenSCENARIO 1.3; other
versions are refused by `xosc.support.SINCE`), its event the node's finish.

Players complete trailer actions in the step they start them, as the nodes complete at once.
"""

from __future__ import annotations

import scemlmodel as scm

from .actions import Plan, action_plan, planner
from .context import Context
from .triggers import Group


@planner("ConnectTrailer", one_event=True)
def plan_connect(ctx: Context, node: scm.ConnectTrailer, groups: list[Group]) -> Plan:
    """A ConnectTrailerAction naming the target actor as the trailer."""
    return action_plan(
        ctx, node, groups, "connect_trailer", {"trailer": ctx.entity(node.targetActor)}
    )


@planner("DisconnectTrailer", one_event=True)
def plan_disconnect(ctx: Context, node: scm.DisconnectTrailer, groups: list[Group]) -> Plan:
    """A DisconnectTrailerAction of whatever the reference actor tows."""
    return action_plan(ctx, node, groups, "disconnect_trailer", {})

"""The controller nodes' planners: one event each, finished when its action completes.

Players complete controller actions in the step they start them
(`xosc.meaning.completes_at_once`), so the event is the node's finish event.
"""

from __future__ import annotations

import scemlmodel as scm

from ..xosc.meaning import OVERRIDE_ELEMENTS
from .actions import Plan, action_plan, planner
from .context import Context
from .controllers import activation, controller, override, released
from .triggers import Group


@planner("ActivateController", one_event=True)
def plan_activate(ctx: Context, node: scm.ActivateController, groups: list[Group]) -> Plan:
    """An ActivateControllerAction switching the domains the node sets."""
    data = {"domains": activation(node), "wrapped": ctx.traits.controller_action}
    return action_plan(ctx, node, groups, "controller_activate", data)


@planner("AssignController", one_event=True)
def plan_assign(ctx: Context, node: scm.AssignController, groups: list[Group]) -> Plan:
    """An AssignControllerAction; in 1.0 with the six released inputs the schema requires."""
    held = node.controller if node.controller is not None else scm.Controller()
    domains = activation(node.activation)
    data = {
        "controller": controller(ctx, held),
        "activate": {f"activate{d[0].upper()}{d[1:]}": text for d, text in domains.items()},
        "released": [] if ctx.traits.controller_action else released(),
    }
    return action_plan(ctx, node, groups, "controller_assign", data)


@planner("OverrideController", one_event=True)
def planoverride(ctx: Context, node: scm.OverrideController, groups: list[Group]) -> Plan:
    """An OverrideControllerValueAction with the node's inputs, in the schema's order."""
    order = list(OVERRIDE_ELEMENTS)
    chosen = sorted(node.overrides, key=lambda o: order.index(o.kind.name))
    data = {
        "overrides": [
            override(o.kind.name, active=bool(o.active), value=float(o.value or 0.0))
            for o in chosen
        ]
    }
    return action_plan(ctx, node, groups, "controller_override", data)

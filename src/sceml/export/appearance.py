"""LightState: one LightStateAction (1.3: 1.2's schema cannot say one), its event the node's
finish.

Players end the action once the transition is over, and never while the light flashes, which
is what the node means (`scemlmodel.LightState`), so the event's end is the node's finish.
"""

from __future__ import annotations

import scemlmodel as scm

from .actions import Plan, action_plan, planner
from .context import Context
from .triggers import Group

#: The LightState's optional numbers, written only when set: (feature, template key).
_OPTIONAL = (
    ("luminousIntensity", "luminous_intensity"),
    ("flashingOnDuration", "flashing_on"),
    ("flashingOffDuration", "flashing_off"),
)


@planner("LightState", one_event=True)
def plan_light_state(ctx: Context, node: scm.LightState, groups: list[Group]) -> Plan:
    """A LightStateAction of the node's vehicle light (versions before 1.3 refused by
    `xosc.support.SINCE`)."""
    data: dict[str, str | None] = {
        "light": node.lightType.name,
        "mode": node.mode.name,
        "transition_time": ctx.values.text(node, "transitionTime"),
    }
    for feature, key in _OPTIONAL:
        data[key] = None if node.eGet(feature) is None else ctx.values.text(node, feature)
    return action_plan(ctx, node, groups, "light_state", data)

"""OpenSCENARIO 1.2's LightStateAction of a vehicle light to a LightState node.

A user-defined light or a light colour has no SceML form and keeps the action opaque (its box
says which light and mode).
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from .actions import Motion, Request, add_node, maps
from .context import Build
from .positions import number


@maps("PrivateAction/AppearanceAction/LightStateAction")
def _light_state(
    build: Build, request: Request, action: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    light = action.find("LightType/VehicleLight")
    state = action.find("LightState")
    if light is None or state is None:
        return "a user-defined light has no SceML form"
    if state.find("Color") is not None:
        return "a light colour has no SceML form"
    light_type = str(light.get("vehicleLightType"))
    mode = str(state.get("mode"))
    if scm.VehicleLightType.getEEnumLiteral(light_type) is None:
        return f"the light {light_type} has no SceML form"
    if scm.LightMode.getEEnumLiteral(mode) is None:
        return f"the light mode {mode} has no SceML form"
    return add_node(
        build,
        request,
        "LightState",
        lightType=light_type,
        mode=mode,
        transitionTime=_optional(action, "transitionTime"),
        luminousIntensity=_optional(state, "luminousIntensity"),
        flashingOnDuration=_optional(state, "flashingOnDuration"),
        flashingOffDuration=_optional(state, "flashingOffDuration"),
    )


def _optional(element: etree._Element, key: str) -> float | None:
    """The attribute's number, None when absent (the language default or the player's)."""
    return None if element.get(key) is None else number(element, key)

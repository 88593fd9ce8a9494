"""OpenSCENARIO 1.3's trailer actions to the coupling kinds (release 1.5): ConnectTrailerAction
to ConnectTrailer (the trailer named as its target actor), DisconnectTrailerAction to
DisconnectTrailer.

A trailer given as a catalog reference or a whole ScenarioObject inside the action (1.3 allows
either besides `trailerRef`) has no SceML form and keeps the action opaque.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from .actions import Motion, Request, add_node, maps
from .context import Build


@maps("PrivateAction/TrailerAction/ConnectTrailerAction")
def _connect(
    build: Build, request: Request, action: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    reference = action.get("trailerRef")
    if reference is None:
        return "a trailer given inline or from a catalog has no SceML form"
    trailer = build.actor(reference, action)
    node = add_node(build, request, "ConnectTrailer")
    node.targetActor = trailer
    return node


@maps("PrivateAction/TrailerAction/DisconnectTrailerAction")
def _disconnect(
    build: Build, request: Request, action: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return add_node(build, request, "DisconnectTrailer")

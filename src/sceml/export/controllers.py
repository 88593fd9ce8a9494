"""Controllers as the template writes them: Controller elements, activations, overrides.

The actor's ObjectController and Init activation (`entities.py`) and the controller nodes'
actions (`controller_actions.py`) are built from these. What differs between versions is
decided here and handed to the template as flags: 1.0 has no ControllerAction around
ActivateControllerAction and requires an OverrideControllerValueAction with all six inputs
beside every AssignControllerAction; 1.2 added lighting, animation and controllerType, which
`support.unsupported_setting` refuses for older versions before any of this runs.
"""

from __future__ import annotations

from typing import Any

import scemlmodel as scm

from ..players.meaning import CONTROLLER_DOMAINS as DOMAINS
from ..players.meaning import OVERRIDE_ELEMENTS
from .context import Context
from .values import number


def _flag(value: bool | None) -> str | None:
    return None if value is None else ("true" if value else "false")


def activation(holder: Any) -> dict[str, str]:
    """The set domains of an ActivateController or a ControllerActivation, as attribute text."""
    if holder is None:
        return {}
    found = {domain: _flag(getattr(holder, domain)) for domain in DOMAINS}
    return {domain: text for domain, text in found.items() if text is not None}


def controller(ctx: Context, held: scm.Controller) -> dict[str, Any]:
    """A Controller element's data: name, type (written from 1.2 on) and properties."""
    return {
        "name": str(held.name or "controller"),
        "type": held.controllerType if ctx.traits.controller_type else None,
        "properties": [(str(p.name or ""), str(p.value or "")) for p in held.properties],
        "file": held.file,
    }


def object_controller(ctx: Context, actor: scm.Actor) -> dict[str, Any] | None:
    """The ScenarioObject's ObjectController, or None for the player's default."""
    return None if actor.controller is None else controller(ctx, actor.controller)


def init_activation(ctx: Context, actor: scm.Actor) -> dict[str, Any] | None:
    """The Init ActivateControllerAction of an actor, or None when it switches no domain."""
    domains = activation(actor.controllerActivation)
    if not domains:
        return None
    return {"domains": domains, "wrapped": ctx.traits.controller_action}


def released() -> list[dict[str, str]]:
    """Every input released: what OpenSCENARIO 1.0 writes beside an assignment."""
    return [override(kind, active=False, value=0.0) for kind in OVERRIDE_ELEMENTS]


def override(kind: str, *, active: bool, value: float) -> dict[str, str]:
    """One input of an OverrideControllerValueAction (a ControllerOverrideKind's element)."""
    # A gear is a number of its own; the other inputs are values (pedals 0..1, wheel in rad).
    return {
        "tag": OVERRIDE_ELEMENTS[kind],
        "active": "true" if active else "false",
        "attribute": "number" if kind == "gear" else "value",
        "value": number(value),
    }

"""The palette (what can be added) and the choices of the panels' selects."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

import scemlmodel as scm

from .. import catalog
from ..render import style
from ..schema import SUPPORTED_VERSIONS
from .fields import actor_kind_names, enum_options
from .node_ops import JOIN_KINDS


def _item(kind: str, module: str | None = None, library: str | None = None) -> dict[str, Any]:
    return {"kind": kind, "label": module or kind, "module": module, "library": library}


@cache
def node_groups() -> tuple[dict[str, Any], ...]:
    """One group per action-node category (catalog order), then the joins.

    The metamodel fixes them, so they are built once, not for every view; nobody changes them.
    """
    groups = []
    for category in catalog.CATEGORIES:
        kinds = [c.__name__ for c in catalog.action_node_kinds() if catalog.category(c) == category]
        groups.append(
            {
                "group": category,
                # The legend's caption, made plural: "Longitudinal maneuver" -> "...maneuvers".
                "label": style.CATEGORY_LOOKS[category].legend + "s",
                "look": category,
                "items": [_item(kind) for kind in kinds],
            }
        )
    groups.append(
        {
            "group": "join",
            "label": "Joins",
            "look": "joinAll",
            "items": [_item(k) for k in JOIN_KINDS],
        }
    )
    return tuple(groups)


def library_group(library: scm.Library, shown_path: str) -> dict[str, Any]:
    """The modules of one library, each item naming the library as ops name it."""
    return {
        "group": f"library:{shown_path}",
        "label": str(library.name or Path(shown_path).name),
        "look": "module",
        "items": [
            {**_item("ModuleUse", str(d.name), shown_path), "roles": _roles(d)}
            for d in library.modules
        ],
    }


def _roles(definition: scm.ModuleDefinition) -> list[dict[str, Any]]:
    """What the "Use <module>" dialog binds: each role and the actor kinds it accepts."""
    return [
        {
            "role": str(role.name),
            "allowedKinds": [str(k.kind.name) for k in role.allowedKinds if k.kind is not None],
        }
        for role in definition.roles
    ]


@cache
def choices() -> dict[str, list[str]]:
    """The options of every select the panels show (fixed by the metamodel; built once)."""
    return {
        "actorKinds": actor_kind_names(),
        "levels": enum_options(scm.AbstractionLevel),
        "cloudStates": enum_options(scm.CloudState),
        "precipitationTypes": enum_options(scm.PrecipitationType),
        "oscVersions": list(SUPPORTED_VERSIONS),
    }


def value_types(level: str, in_module: bool) -> list[str]:
    """Which ParamValue types the level allows (docs/editor-protocol.md)."""
    if level == "concrete" and not in_module:
        return ["value"]
    found = ["value", "range", "uniform", "normal", "discrete"]
    return [*found, "ref"] if in_module else found

"""The palette (what can be added) and the choices of the panels' selects."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import Any

import scemlmodel as scm

from ..model import catalog
from ..render import style
from ..validation.context import is_kind
from ..validation.parameters import refused_value_kinds
from ..xosc.profiles import PROFILES
from ..xosc.schema import SUPPORTED_VERSIONS
from .fields import actor_kind_names, enum_options
from .node_ops import JOIN_KINDS


def _item(kind: str, module: str | None = None, library: str | None = None) -> dict[str, Any]:
    return {"kind": kind, "label": module or kind, "module": module, "library": library}


def _plural(legend: str) -> str:
    """The legend's caption made plural for a palette group: "Longitudinal maneuver" ->
    "Longitudinal maneuvers"; one with a note in brackets stays as it is ("Global (no actor)",
    "Appearance (lights)": a group of kinds, not a count of things)."""
    return legend if legend.endswith(")") else legend + "s"


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
                "label": _plural(style.CATEGORY_LOOKS[category].legend),
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


def library_group(
    library: scm.Library,
    shown_path: str,
    participants: dict[str, scm.Participant],
    editing: scm.ModuleDefinition | None = None,
) -> dict[str, Any]:
    """The modules of one library, each item naming the library as ops name it.

    The module being edited is left out: a module cannot be used inside itself.
    """
    return {
        "group": f"library:{shown_path}",
        "label": str(library.name or Path(shown_path).name),
        "look": "module",
        "items": [
            {**_item("ModuleUse", str(d.name), shown_path), "roles": _roles(d, participants)}
            for d in library.modules
            if d is not editing
        ],
    }


def allowed_kinds(role: scm.ActorRole) -> list[str]:
    """The actor kinds a role accepts (empty: any)."""
    return [str(k.kind.name) for k in role.allowedKinds if k.kind is not None]


def fitting(role: scm.ActorRole, participants: dict[str, scm.Participant]) -> list[str]:
    """The names of the actors (or outer roles) a role may be bound to, as SCEML-M004 judges."""
    allowed = allowed_kinds(role)
    names = []
    for name, participant in participants.items():
        if isinstance(participant, scm.ActorRole):
            kinds = allowed_kinds(participant) or ["Actor"]
        else:
            kinds = [participant.eClass.name]
        if not allowed or all(any(is_kind(kind, a) for a in allowed) for kind in kinds):
            names.append(name)
    return names


def _roles(
    definition: scm.ModuleDefinition, participants: dict[str, scm.Participant]
) -> list[dict[str, Any]]:
    """What the "Use <module>" dialog binds: each role, the kinds it accepts, who fits it."""
    return [
        {
            "role": str(role.name),
            "allowedKinds": allowed_kinds(role),
            "actors": fitting(role, participants),
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
        "profiles": list(PROFILES),
    }


#: The model class of each ParamValue type of the protocol (docs/editor-protocol.md).
_VALUE_CLASSES = {
    "value": "Value",
    "range": "Range",
    "uniform": "UniformDistribution",
    "normal": "NormalDistribution",
    "discrete": "DiscreteDistribution",
    "ref": "ParameterRef",
}


def value_types(level: str, in_module: bool) -> list[str]:
    """Which ParamValue types the level allows: those the parameter rules accept there."""
    refused = refused_value_kinds(level, in_module)
    return [
        name
        for name, kind in _VALUE_CLASSES.items()
        if not any(is_kind(kind, other) for other in refused)
    ]

"""What the properties panel edits: Fields derived from the EClass features and the catalog."""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from pyecore.ecore import EAttribute, EEnum, EObject, EReference, EStructuralFeature

import scemlmodel as scm

from ..model import catalog
from ..model.traversal import features
from .nested import attributes_of, is_nested, shown
from .values import default_text, position_text, position_to_json, value_text, value_to_json

#: Features no panel edits: graph structure, notation, and what other fields already show.
_HIDDEN = {"incoming", "outgoing", "actors", "environment", "bindings", *catalog.NOTATION_FEATURES}
#: Fields every panel shows first, in this order.
_FIRST = {"name": 0, "referenceActor": 1, "targetActor": 2}
_HIDDEN_BY_CLASS = {"ModuleUse": {"definition", "overrides"}}
#: Where a feature name reads badly as words: `isEgo` is shown as "Ego".
_LABELS = {
    "isEgo": "Ego",
    "h": "Heading",
    "roadId": "Road",
    "laneId": "Lane",
    "controllerType": "Type",
    "boxCenterX": "Box centre x",
    "hitchX": "Hitch x",
    "couplerX": "Coupler x",
    "trailer": "Tows",
    "maxSpeed": "Top speed",
    "maxAcceleration": "Max acceleration",
    "maxDeceleration": "Max deceleration",
    # What the flag does (release 1.5): when the node starts, the actor's running maneuver
    # of the same category ends.
    "interrupts": "Interrupts a running one",
}
_SPEED_UNIT = "m/s"


def label(name: str) -> str:
    """`targetSpeed` -> `Target speed`, `referenceActor` -> `Reference actor`."""
    if name in _LABELS:
        return _LABELS[name]
    words = re.sub(r"(?<!^)(?=[A-Z])", " ", name).lower()
    return words[:1].upper() + words[1:]


def actor_kind_names() -> list[str]:
    """The concrete actor kinds, in metamodel order (Pedestrian, Bicycle, ... Bus)."""
    return [cls.__name__ for cls in catalog.actor_kinds()]


def enum_options(eenum: EEnum) -> list[str]:
    """The literal names of an enum, in metamodel order."""
    return [str(literal.name) for literal in eenum.eLiterals]


def _enum_value(held: object) -> str | None:
    return None if held is None else str(getattr(held, "name", held))


def _participant(held: object) -> str | None:
    return None if held is None else str(getattr(held, "name", None) or "")


def type_name(feature: EStructuralFeature) -> str:
    """The name of a feature's type (generated classes stand for their EClass)."""
    kind = feature.eType
    name = getattr(kind, "name", None)
    return name if isinstance(name, str) else str(kind.eClass.name)


def feature_field(
    owner: EObject, feature: EStructuralFeature, prefix: str = ""
) -> dict[str, Any] | None:
    """The Field of one feature of `owner`, or None when no panel edits it."""
    name = str(feature.name)
    held = owner.eGet(feature)
    base: dict[str, Any] = {"name": prefix + name, "label": label(name)}
    if isinstance(feature, EAttribute):
        return {**base, **_attribute_field(feature, held)}
    if not isinstance(feature, EReference):
        return None
    kind = type_name(feature)
    if kind == "Participant":
        # An optional target (a LaneChange's) may stay empty.
        required = name != "targetActor" or catalog.needs_target(owner)
        return {**base, "type": "actor", "value": _participant(held), "required": required}
    if kind == "Actor" and not feature.containment:
        # The actor an actor tows (release 1.4's Actor.trailer): none is a meaning of its own.
        return {**base, "type": "actor", "value": _participant(held), "required": False}
    if kind == "ParameterValue":
        return {**base, **parameter_field(owner, name, held)}
    if kind == "Position" and feature.many:
        return {
            **base,
            "type": "positions",
            "value": [position_to_json(p) for p in held],
            "texts": [position_text(p) for p in held],
        }
    if kind == "Position":
        # Every single position of a node (destination, position) is needed to run it.
        required = isinstance(owner, scm.ActionNode)
        return {
            **base,
            "type": "position",
            "required": required,
            "value": position_to_json(held),
            "text": position_text(held),
        }
    return None


def _attribute_field(feature: EAttribute, held: object) -> dict[str, Any]:
    if isinstance(feature.eType, EEnum):
        return {"type": "enum", "options": enum_options(feature.eType), "value": _enum_value(held)}
    if type_name(feature) == "EBooleanObject":
        # Unset (null) has a meaning of its own: a controller domain left as it is.
        return {"type": "bool", "value": None if held is None else bool(held)}
    if type_name(feature) == "EBoolean":
        return {"type": "bool", "value": bool(held)}
    return {"type": "text", "value": held}


def parameter_field(owner: EObject, name: str, held: object) -> dict[str, Any]:
    """A numeric parameter: unit, language default, whether required, km/h for speeds."""
    spec = catalog.parameter(owner, name)
    default = spec.default
    if spec.per_actor_default:
        default = catalog.actor_dimensions(owner).get(name)
    return {
        "type": "parameter",
        "unit": spec.unit,
        "default": default,
        "required": spec.required,
        "kmh": spec.unit == _SPEED_UNIT,
        "value": value_to_json(held),
        "text": value_text(held if isinstance(held, scm.ParameterValue) else None, spec.unit),
        "defaultText": default_text(default, spec.unit),
    }


def _features(owner: EObject) -> Iterator[EStructuralFeature]:
    hidden = _HIDDEN | _HIDDEN_BY_CLASS.get(owner.eClass.name, set())
    for feature in features(owner.eClass):
        if feature.name not in hidden:
            yield feature


def node_fields(node: EObject) -> list[dict[str, Any]]:
    """The Fields of a graph element: name, actors, then its own features in metamodel order."""
    fields = []
    # The name first, as every panel shows it, then who performs the node; the rest in
    # metamodel order (a stable sort keeps it).
    ordered = sorted(_features(node), key=lambda feature: _FIRST.get(feature.name, len(_FIRST)))
    performed = not isinstance(node, scm.ActionNode) or catalog.performed_by_actor(node)
    for feature in ordered:
        if feature.name == "targetActor" and not catalog.allows_target(node):
            continue
        if feature.name == "referenceActor" and not performed:
            continue  # a global kind (SetParameter, ...): no actor performs it
        if isinstance(feature, EReference) and is_nested(feature):
            fields.extend(nested_fields(node, feature))
            continue
        made = feature_field(node, feature)
        if made is not None:
            fields.append(made)
    return fields


def nested_fields(owner: EObject, feature: EReference) -> list[dict[str, Any]]:
    """A contained controller's or activation's attributes as `<feature>.<attribute>` fields."""
    held = shown(owner, feature)
    prefix, title = f"{feature.name}.", label(str(feature.name))
    fields = []
    for attribute in attributes_of(held):
        made = feature_field(held, attribute, prefix)
        if made is not None:
            # "Controller name", not a second "Name" beside the actor's own.
            made["label"] = f"{title} {label(str(attribute.name)).lower()}"
            fields.append(made)
    return fields


def root_fields(root: scm.RootNode) -> list[dict[str, Any]]:
    """The root's fields, then its environment's as `environment.<name>`."""
    fields = [f for f in node_fields(root) if f["name"] != "name"]
    environment = root.environment if root.environment is not None else scm.Environment()
    for feature in _features(environment):
        made = feature_field(environment, feature, "environment.")
        if made is not None:
            fields.append(made)
    return fields


def actor_fields(actor: scm.Actor) -> list[dict[str, Any]]:
    """An actor's fields: name, kind, then its features (isEgo, model, start, speed, size)."""
    fields = node_fields(actor)
    kind = {
        "name": "kind",
        "label": "Kind",
        "type": "enum",
        "options": actor_kind_names(),
        "value": actor.eClass.name,
    }
    return [fields[0], kind, *fields[1:]]

"""Fields of a small contained object shown flat in its owner's panel: `controller.name`.

A controller (an actor's, an AssignController's) and a controller activation are single
contained objects of attributes. The panel shows their attributes as the owner's fields with
the feature's name as a prefix, as the root shows its environment's; the object is made when a
field of it is first set, and emptying a controller's name removes the controller (the player's
default drives the actor again).
"""

from __future__ import annotations

from pyecore.ecore import EAttribute, EObject, EReference

import scemlmodel as scm

#: Contained single objects whose attributes are edited as `<feature>.<attribute>`.
NESTED_TYPES = ("Controller", "ControllerActivation")


def nested_feature(owner: EObject, field: str) -> tuple[EReference, str] | None:
    """The containment `field` names a part of (`controller.name` -> controller, `name`)."""
    prefix, dot, rest = field.partition(".")
    if not dot:
        return None
    feature = owner.eClass.findEStructuralFeature(prefix)
    if not isinstance(feature, EReference) or not is_nested(feature):
        return None
    return feature, rest


def is_nested(feature: EReference) -> bool:
    """Whether a feature holds one object the panel edits as prefixed fields."""
    return bool(feature.containment and not feature.many and _type(feature) in NESTED_TYPES)


def _type(feature: EReference) -> str:
    # A generated class stands for its EClass as the feature's type.
    kind = feature.eType
    name = getattr(kind, "name", None)
    return name if isinstance(name, str) else str(kind.eClass.name)


def blank(feature: EReference) -> EObject:
    """A new, empty object of the feature's type."""
    made: EObject = getattr(scm, _type(feature))()
    return made


def shown(owner: EObject, feature: EReference) -> EObject:
    """The contained object, or a blank one of its type to show its unset fields."""
    held = owner.eGet(feature)
    return held if held is not None else blank(feature)


def attributes_of(held: EObject) -> list[EAttribute]:
    """The attributes of a nested object, in metamodel order."""
    return [f for f in held.eClass.eAllStructuralFeatures() if isinstance(f, EAttribute)]


def removes(feature: EReference, attribute: str, value: object) -> bool:
    """Whether setting `value` means no object at all: a controller without a name."""
    return feature.name == "controller" and attribute == "name" and not value

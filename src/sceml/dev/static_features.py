"""EAttributes and EReferences of generated classes, built as pyecore's constructors build them
but without their cost: copied into generated/<package>/_static_features.py by `sceml dev
generate`, and called by the generated module instead of `EAttribute(...)`/`EReference(...)`.

pyecore's constructor sets each of a feature's fourteen-odd properties through its notifying
setter (a value holder, a type check, a notification to the feature itself), which is 12 ms of
every start for the metamodel's 240 features. Most of them keep their defaults, so a feature is
made here as a copy of one built once by the constructor itself (the same holders and set
flags, in the same order, each holder its own), and only the qualifiers that differ from the
defaults go through the setters, in the constructor's order, with the constructor's side
effects (the type's inverse references, the feature's cached name, type and multiplicity).
Qualifiers this module does not know, or a reference typed at construction, fall back to the
constructor. tests/core/test_static_features.py compares every feature of the generated package
with one built by pyecoregen's own templates.
"""

from __future__ import annotations

from typing import Any

from pyecore.ecore import EAttribute, EDataType, EObject, EReference
from pyecore.valuecontainer import EValue

#: What each kind's constructor takes that is made here, in the order it sets them.
_QUALIFIERS = {
    EAttribute: ("name", "eType", "lower", "upper", "ordered", "unique", "changeable")
    + ("transient", "derived", "iD", "default_value"),
    EReference: ("name", "lower", "upper", "ordered", "unique", "changeable", "transient")
    + ("derived", "containment"),
}
#: Constructor arguments that set a property of another name.
_PROPERTY = {"lower": "lowerBound", "upper": "upperBound"}

#: Kind -> the feature its constructor made with no arguments (pyecore is untyped: Any).
_prototypes: dict[Any, Any] = {}


def attribute(**qualifiers: Any) -> EAttribute:
    """The same as `EAttribute(**qualifiers)`."""
    if not set(qualifiers) <= set(_QUALIFIERS[EAttribute]):
        return EAttribute(**qualifiers)
    feature = _copy_of_prototype(EAttribute)
    _set_qualifiers(feature, qualifiers, EAttribute)
    # The constructor's plain attribute: the given default, else the data type's.
    default = qualifiers.get("default_value")
    if default is None and isinstance(qualifiers.get("eType"), EDataType):
        default = qualifiers["eType"].default_value
    feature.default_value = default
    return feature


def reference(**qualifiers: Any) -> EReference:
    """The same as `EReference(**qualifiers)`."""
    if not set(qualifiers) <= set(_QUALIFIERS[EReference]):
        return EReference(**qualifiers)
    feature = _copy_of_prototype(EReference)
    _set_qualifiers(feature, qualifiers, EReference)
    return feature


def _copy_of_prototype(kind: Any) -> Any:
    """A new feature in the state the constructor leaves one in when given no arguments."""
    prototype = _prototypes.get(kind)
    if prototype is None:
        prototype = _prototypes[kind] = kind()
        # Kept only as a pattern: not one of the model's objects (EObject.allInstances).
        EObject._instances.discard(prototype)
    feature = kind.__new__(kind)  # EObject.__new__: its own listeners, flags and holders
    own = feature.__dict__
    for key, value in prototype.__dict__.items():
        if key in own:
            continue
        if type(value) is EValue:
            holder = object.__new__(EValue)  # a holder without its __init__: filled below
            holder.__dict__.update(value.__dict__)
            holder.owner = feature
            value = holder
        own[key] = value
    feature._isset.update(prototype._isset)
    feature._eternal_listener.append(feature)  # as ETypedElement.__init__ does
    return feature


def _set_qualifiers(feature: Any, qualifiers: dict[str, Any], kind: Any) -> None:
    """Each qualifier that differs from the prototype's, through pyecore's setter."""
    prototype = _prototypes[kind]
    for argument in _QUALIFIERS[kind]:
        if argument not in qualifiers or argument == "default_value":
            continue
        name = _PROPERTY.get(argument, argument)
        value = qualifiers[argument]
        if name in ("lowerBound", "upperBound"):
            value = int(value)
        current = getattr(prototype, name)
        if type(current) is type(value) and current == value:
            continue
        setattr(feature, name, value)

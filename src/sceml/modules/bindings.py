"""What a module use's copies are made of, as a key: two uses with the same key expand to
copies that hold the same values and name the same actors, and differ only in their names and
in where they sit in the scenario's graph.

Validation uses it to check a definition's nodes once per distinct binding rather than once per
use (`sceml.validation.engine.through_modules`). The key is conservative: actors and the objects
values refer to count by identity, and a value that is a proxy makes its use's key unique, so
two uses share a key only when their copies are certainly alike.
"""

from __future__ import annotations

from collections.abc import Hashable
from functools import cache

from pyecore.ecore import EAttribute, EClass, EObject, EProxy, EStructuralFeature

import scemlmodel as scm


def binding_key(uses: tuple[scm.ModuleUse, ...]) -> Hashable:
    """The key of the copies made by expanding `uses` (outermost first, the original objects, as
    `expansion.Origin.uses`): each use's role -> actor map and parameter -> value map, as the
    expansion reads them.

    The definition of each use need not be part of it: every use but the outermost lies inside
    the definition of the one before, and the copies' own originals (which callers key on too)
    lie inside the definition of the innermost.
    """
    return tuple(_use_key(use) for use in uses)


def _use_key(use: scm.ModuleUse) -> Hashable:
    # As `expansion._bound_actors` and `_bind_parameters` read them: by name, the last one wins.
    actors = {binding.role: binding.actor for binding in use.bindings}
    values = {override.parameter: override.value for override in use.overrides}
    return (
        tuple((role, _identity(actor)) for role, actor in actors.items()),
        tuple((name, value_key(value)) for name, value in values.items()),
    )


def _identity(target: EObject | None) -> Hashable:
    """A referenced object by identity (the objects live as long as the validation run)."""
    if target is None:
        return None
    return id(target)


def value_key(value: EObject | None) -> Hashable:
    """A value (and everything it contains) by its class, the attributes it sets and the objects
    it refers to: two values with equal keys copy to equal copies."""
    if value is None:
        return None
    if isinstance(value, EProxy):
        return object()  # equal to nothing else: a proxy is not compared
    parts: list[Hashable] = [value.eClass.name]
    for feature, kind in _features(value.eClass):
        held = value.eGet(feature)
        items = list(held) if feature.many else [held]
        if kind is _ATTRIBUTE:
            # repr tells 0.0 from -0.0, which == does not; set or not, as the copier copies.
            parts.append((feature.name, value.eIsSet(feature), tuple(map(repr, items))))
        elif kind is _CHILD:
            parts.append((feature.name, tuple(value_key(item) for item in items)))
        else:
            parts.append((feature.name, tuple(_identity(item) for item in items)))
    return tuple(parts)


_ATTRIBUTE, _CHILD, _REFERENCE = "attribute", "child", "reference"


@cache
def _features(eclass: EClass) -> tuple[tuple[EStructuralFeature, str], ...]:
    """The features a value's key reads, and what each is; its container is left out (where a
    value is, not what it is), as are derived and transient features (not copied)."""
    found = []
    for feature in eclass.eAllStructuralFeatures():
        if feature.derived or feature.transient:
            continue
        if isinstance(feature, EAttribute):
            found.append((feature, _ATTRIBUTE))
        elif feature.containment:
            found.append((feature, _CHILD))
        elif feature.eOpposite is None or not feature.eOpposite.containment:
            found.append((feature, _REFERENCE))
    return tuple(found)

"""Fast walks over models: feature lists cached per metaclass, and containment traversal.

pyecore recomputes `eAllStructuralFeatures()` and `eAllReferences()` through generators on every
call, and its `eAllContents()` does so for every object visited; on a 10,000-node scenario that is
most of the time spent copying, flattening or validating. SceML's metaclasses never change at
run time, so their feature lists are computed once.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache
from typing import Any

from pyecore.ecore import EAttribute, EClass, EObject, EProxy, EReference, EStructuralFeature
from pyecore.valuecontainer import EOrderedSet, EValue

from .lightobjects import Held


@cache
def features(eclass: EClass) -> tuple[EStructuralFeature, ...]:
    """Every structural feature of a metaclass, inherited ones included, that is stored."""
    return tuple(f for f in eclass.eAllStructuralFeatures() if not f.derived and not f.transient)


@cache
def attributes(eclass: EClass) -> tuple[EAttribute, ...]:
    """The stored attributes of a metaclass."""
    return tuple(f for f in features(eclass) if isinstance(f, EAttribute))


@cache
def containments(eclass: EClass) -> tuple[EReference, ...]:
    """The containment references of a metaclass."""
    return tuple(f for f in features(eclass) if isinstance(f, EReference) and f.containment)


@cache
def cross_references(eclass: EClass) -> tuple[EReference, ...]:
    """The stored non-containment references, without the link back to the container."""
    return tuple(
        f
        for f in features(eclass)
        if isinstance(f, EReference)
        and not f.containment
        and not (f.eOpposite is not None and f.eOpposite.containment)
    )


def stored(obj: EObject, name: str) -> Any:
    """The value of feature `name` as `obj` holds it (a collection for a many-valued one), or
    None if it was never set.

    pyecore keeps each feature's value in a holder in the instance's __dict__, made on first
    access; reading the holder directly skips the descriptor and eGet's checks (most of a walk's
    time) and does not create holders for features that were never set.
    """
    holder = obj.__dict__.get(name)
    return holder._get() if hasattr(holder, "_get") else holder


def single_value(obj: EObject, name: str) -> Any:
    """What `obj.<name>` reads for a single-valued feature, without the holder pyecore makes when
    a feature that was never set is first read.

    Validation reads features most objects leave unset (every node's `maxRuns` and
    `targetActor`, each kind's optional parameters); making a holder for each was about 4 % of
    a 10k-node validation in a sampling profile, and kept memory for nothing.
    """
    if type(obj) is EProxy:
        return getattr(obj, name)
    holder = obj.__dict__.get(name)
    if holder is None:
        key = (type(obj), name)
        found = _DEFAULTS.get(key, _DEFAULTS)
        if found is _DEFAULTS:
            found = _DEFAULTS[key] = _default(*key)
        return found
    kind = type(holder)
    if kind is EValue or kind is Held:
        return holder._value
    return getattr(obj, name)


#: Each class's default of each feature read unset, worked out once.
_DEFAULTS: dict[tuple[type, str], Any] = {}


def _default(cls: type, name: str) -> Any:
    feature = getattr(cls, name)
    if not isinstance(feature, EStructuralFeature) or feature.many:
        raise TypeError(f"{cls.__name__}.{name} is not a single-valued feature")
    return feature.get_default_value()


@cache
def _containment_names(eclass: EClass) -> tuple[tuple[str, bool], ...]:
    return tuple((f.name, bool(f.many)) for f in containments(eclass))


def contents(obj: EObject) -> Iterator[EObject]:
    """The objects `obj` directly contains, in feature order."""
    for name, many in _containment_names(obj.eClass):
        held = stored(obj, name)
        if held is None:
            continue
        if many:
            yield from held
        else:
            yield held


@cache
def _single_reference_names(eclass: EClass) -> tuple[tuple[EReference, str], ...]:
    return tuple((f, f.name) for f in cross_references(eclass) if not f.many)


def single_references(obj: EObject) -> Iterator[tuple[EReference, EObject]]:
    """(feature, target) of each single-valued cross-reference `obj` has set, in feature order."""
    for feature, name in _single_reference_names(obj.eClass):
        target = stored(obj, name)
        if target is not None:
            yield feature, target


def root_of(obj: EObject) -> EObject:
    """The object at the top of `obj`'s containment (itself when it has no container): what
    pyecore's `eRoot` gives, in a loop, at half its cost (module expansion asks for every
    reference it copies)."""
    while (container := obj.eContainer()) is not None:
        obj = container
    return obj


def all_contents(obj: EObject) -> Iterator[EObject]:
    """Everything below `obj` in containment order (depth first), `obj` itself excluded."""
    pending = children(obj)
    pending.reverse()
    while pending:
        current = pending.pop()
        yield current
        below = children(current)
        if below:
            below.reverse()
            pending.extend(below)


def children(obj: EObject) -> list[EObject]:
    """The objects `obj` directly contains, as `list(contents(obj))`, reading the usual holders directly: a walk of a large model calls
    this for every object, most of which (values, positions) contain nothing or one thing."""
    found: list[EObject] = []
    state = obj.__dict__
    for name, many in _containment_names(obj.eClass):
        holder = state.get(name)
        if holder is None:
            continue
        kind = type(holder)
        if kind is EOrderedSet:
            found.extend(holder.items)
        elif kind is EValue or kind is Held:
            if holder._value is not None:
                found.append(holder._value)
        else:
            held = stored(obj, name)
            if held is None:
                continue
            if many:
                found.extend(held)
            else:
                found.append(held)
    return found

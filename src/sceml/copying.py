"""Deep copies of containment subtrees: a contained object can have only one container."""

from __future__ import annotations

from typing import TypeVar

from pyecore.ecore import EAttribute, EObject, EReference

T = TypeVar("T", bound=EObject)


def copy_tree(obj: T) -> T:
    """Copy `obj` and everything it contains; non-containment references keep their targets."""
    duplicate = obj.eClass.python_class()
    for feature in obj.eClass.eAllStructuralFeatures():
        if feature.derived or feature.transient or not obj.eIsSet(feature):
            continue
        held = obj.eGet(feature)
        if isinstance(feature, EAttribute):
            if feature.many:
                duplicate.eGet(feature).extend(held)
            else:
                duplicate.eSet(feature, held)
        elif isinstance(feature, EReference) and feature.containment:
            if feature.many:
                duplicate.eGet(feature).extend(copy_tree(child) for child in held)
            elif held is not None:
                duplicate.eSet(feature, copy_tree(held))
        elif feature.many:
            duplicate.eGet(feature).extend(held)
        else:
            duplicate.eSet(feature, held)
    return duplicate


def detached(obj: T) -> T:
    """`obj` itself if it has no container yet, else a copy that can be placed elsewhere."""
    return obj if obj.eContainer() is None else copy_tree(obj)

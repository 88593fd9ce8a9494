"""Deep copies of model subtrees, with references inside the copy pointing into the copy."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TypeVar

from pyecore.ecore import EObject

from .traversal import attributes, containments, cross_references

T = TypeVar("T", bound=EObject)


class Copier:
    """Copies containment trees like EMF's EcoreUtil.Copier.

    `copy` duplicates objects and everything they contain; `copy_references` then points the
    copies' non-containment references at the copies of their targets, or at the original target
    when it was not copied (e.g. an actor outside a copied node).
    """

    def __init__(self) -> None:
        self.copies: dict[EObject, EObject] = {}

    def copy(self, obj: T) -> T:
        """Copy `obj` and its containment tree (references are set by `copy_references`)."""
        eclass = obj.eClass
        duplicate: T = eclass.python_class()
        self.copies[obj] = duplicate
        for feature in attributes(eclass):
            if not obj.eIsSet(feature):
                continue
            if feature.many:
                duplicate.eGet(feature).extend(obj.eGet(feature))
            else:
                duplicate.eSet(feature, obj.eGet(feature))
        for feature in containments(eclass):
            held = obj.eGet(feature)
            if feature.many:
                if held:
                    duplicate.eGet(feature).extend(self.copy(child) for child in held)
            elif held is not None:
                duplicate.eSet(feature, self.copy(held))
        return duplicate

    def copy_all(self, objects: Iterable[T]) -> list[T]:
        """Copy several objects."""
        return [self.copy(obj) for obj in objects]

    def copy_references(self) -> None:
        """Set every non-containment reference of the copies, mapped into the copies."""
        for original, duplicate in list(self.copies.items()):
            for feature in cross_references(original.eClass):
                held = original.eGet(feature)
                if held is None or (feature.many and not held):
                    continue
                if feature.many:
                    duplicate.eGet(feature).extend(self.copies.get(t, t) for t in held)
                elif held is not None:
                    duplicate.eSet(feature, self.copies.get(held, held))


def copy_tree(obj: T) -> T:
    """Copy `obj` and everything it contains; references leaving the tree keep their targets."""
    copier = Copier()
    duplicate = copier.copy(obj)
    copier.copy_references()
    return duplicate


def detached(obj: T) -> T:
    """`obj` itself if it has no container yet, else a copy that can be placed elsewhere."""
    return obj if obj.eContainer() is None else copy_tree(obj)

"""Deep copies of model subtrees, with references inside the copy pointing into the copy."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any, TypeVar

from pyecore.ecore import EObject, EProxy

from .fastobjects import (
    Slot,
    add_child,
    attribute_supported,
    child_supported,
    new,
    reference_supported,
    set_reference,
    set_value,
    slot,
)
from .traversal import attributes, containments, cross_references

T = TypeVar("T", bound=EObject)


class _Shape:
    """The features a copy of one class goes through, and whether the direct writes cover them."""

    __slots__ = ("attributes", "containments", "direct", "direct_references", "references")

    def __init__(self, cls: type[EObject]) -> None:
        eclass = cls.eClass
        self.attributes = tuple(slot(f) for f in attributes(eclass))
        self.containments = tuple(slot(f) for f in containments(eclass))
        self.references = tuple(slot(f) for f in cross_references(eclass))
        # A class of another shape (a many-valued attribute, say) is copied through pyecore.
        self.direct = (
            eclass.python_class is cls
            and all(attribute_supported(s.feature) for s in self.attributes)
            and all(child_supported(s.feature) for s in self.containments)
        )
        self.direct_references = eclass.python_class is cls and all(
            s.many or reference_supported(s.feature) for s in self.references
        )


_SHAPES: dict[type[EObject], _Shape] = {}


def _shape(cls: type[EObject]) -> _Shape:
    shape = _SHAPES.get(cls)
    if shape is None:
        shape = _SHAPES[cls] = _Shape(cls)
    return shape


class Copier:
    """Copies containment trees like EMF's EcoreUtil.Copier.

    `copy` duplicates objects and everything they contain; `copy_references` then points the
    copies' non-containment references at the copies of their targets, or at the original target
    when it was not copied (e.g. an actor outside a copied node).

    Copies are built with `sceml.model.fastobjects`, which leaves the state pyecore's setters would;
    what it does not cover (a proxy being copied, a reference set before `copy_references`, the
    opposite end of a reference to an object that was not copied) goes through those setters.
    With `direct = False` everything does, as `SetterCopier` below.
    """

    direct = True

    def __init__(self, stand_ins: Mapping[EObject, EObject] | None = None) -> None:
        self.copies: dict[EObject, EObject] = {}
        # Single-valued references to these objects point at their stand-ins in the copies (a
        # module use binds its definition's roles to actors while the definition is copied).
        self.stand_ins: Mapping[EObject, EObject] = stand_ins or {}

    def copy(self, obj: T) -> T:
        """Copy `obj` and its containment tree (references are set by `copy_references`)."""
        cls = type(obj)
        shape = _shape(cls) if self.direct and cls is not EProxy else None
        if shape is None or not shape.direct:
            return self._copy_with_setters(obj)
        duplicate: Any = new(cls)
        self.copies[obj] = duplicate
        state = obj.__dict__
        isset = state["_isset"]
        for feature in shape.attributes:
            if feature.feature in isset:
                held = state.get(feature.name)
                value = held._value if held is not None else obj.eGet(feature.feature)
                set_value(duplicate, feature, value)
        for feature in shape.containments:
            held = state.get(feature.name)
            if held is None:
                continue
            if feature.many:
                for child in held.items:
                    add_child(duplicate, feature, self.copy(child))
            elif held._value is not None:
                add_child(duplicate, feature, self.copy(held._value))
        return duplicate  # type: ignore[no-any-return]

    def _copy_with_setters(self, obj: T) -> T:
        # pyecore's setters, feature by feature; the contained objects go through `copy`.
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
        copies = self.copies
        for original, duplicate in list(copies.items()):
            cls = type(original)
            shape = _shape(cls) if self.direct and cls is not EProxy else None
            if shape is None or not shape.direct_references or type(duplicate) is not cls:
                self._references_with_setters(original, duplicate)
                continue
            state = original.__dict__
            set_before = duplicate.__dict__
            for feature in shape.references:
                held = state.get(feature.name)
                if held is None:
                    continue
                if feature.many:
                    if held:
                        self._reference_with_setters(feature, held, duplicate)
                    continue
                held = held._value
                if held is None:
                    continue
                target = copies.get(held, held)
                if target is held and held in self.stand_ins:
                    target = self.stand_ins[held]
                # Through pyecore when the reference was set before (its setter also undoes
                # what was there), or when the opposite end would change an original (the
                # target or its stand-in), which may be watched or be a proxy; a copy made here
                # has no listeners yet.
                if feature.name in set_before or (
                    feature.opposite is not None and held not in copies
                ):
                    duplicate.eSet(feature.feature, target)
                else:
                    set_reference(duplicate, feature, target)

    def _references_with_setters(self, original: EObject, duplicate: EObject) -> None:
        for feature in cross_references(original.eClass):
            held = original.eGet(feature)
            if held is None or (feature.many and not held):
                continue
            if feature.many:
                duplicate.eGet(feature).extend(self.copies.get(t, t) for t in held)
            else:
                target = self.copies.get(held, held)
                duplicate.eSet(feature, self.stand_ins.get(target, target))

    def _reference_with_setters(self, feature: Slot, held: Any, duplicate: EObject) -> None:
        duplicate.eGet(feature.feature).extend(self.copies.get(t, t) for t in held)


class SetterCopier(Copier):
    """The same copies through pyecore's setters only: the yardstick tests and benchmarks
    compare the direct copies with."""

    direct = False


def copy_tree(obj: T) -> T:
    """Copy `obj` and everything it contains; references leaving the tree keep their targets."""
    copier = Copier()
    duplicate = copier.copy(obj)
    copier.copy_references()
    return duplicate


def detached(obj: T) -> T:
    """`obj` itself if it has no container yet, else a copy that can be placed elsewhere."""
    return obj if obj.eContainer() is None else copy_tree(obj)

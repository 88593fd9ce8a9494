"""Reversible model changes: every edit is a list of small set/insert/remove steps that undo.

Operations change the model only through a `Recorder`, so any operation, however composed, can
be undone and redone with the very same pyecore objects at their original places, and a failed
request can be rolled back. Two pyecore 0.15.2 habits are handled here, once:

- reassigning `Flow.source/target` does not remove the flow from the old node's transient
  `outgoing/incoming`; a flow end is therefore always cleared before it is set;
- attaching an object that another container holds moves it silently; the move away is recorded
  first, so undo puts the object back where it was.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..validation.edits import Change

_FLOW_ENDS = ("source", "target")


@dataclass
class _Set:
    owner: EObject
    feature: str
    old: Any
    new: Any
    was_set: bool = False

    def do(self) -> None:
        _assign(self.owner, self.feature, self.new, self.new is not None)

    def undo(self) -> None:
        _assign(self.owner, self.feature, self.old, self.was_set)

    def described(self) -> Change:
        return Change(self.owner, self.feature, self.old, self.new)


@dataclass
class _Insert:
    owner: EObject
    feature: str
    item: Any
    index: int

    def do(self) -> None:
        self.owner.eGet(self.feature).insert(self.index, self.item)

    def undo(self) -> None:
        self.owner.eGet(self.feature).remove(self.item)

    def described(self) -> Change:
        return Change(self.owner, self.feature, None, self.item)


@dataclass
class _Remove:
    owner: EObject
    feature: str
    item: Any
    index: int

    def do(self) -> None:
        self.owner.eGet(self.feature).remove(self.item)

    def undo(self) -> None:
        self.owner.eGet(self.feature).insert(self.index, self.item)

    def described(self) -> Change:
        return Change(self.owner, self.feature, self.item, None)


@dataclass
class _Outside:
    """A change outside the edited model (a module written into its library file)."""

    owner: EObject
    apply: Callable[[], None]
    revert: Callable[[], None]

    def do(self) -> None:
        self.apply()

    def undo(self) -> None:
        self.revert()

    def described(self) -> Change:
        return Change(self.owner, "modules", None, None)


def _assign(owner: EObject, feature: str, value: Any, is_set: bool) -> None:
    if isinstance(owner, scm.Flow) and feature in _FLOW_ENDS:
        # Clearing first updates the old end's opposite list, which a plain reassignment does not.
        owner.eSet(feature, None)
    owner.eSet(feature, value)
    if not is_set:
        # pyecore has no eUnset: a feature set to None stays "set" and is saved as xsi:nil,
        # which the file never had. Null means unset (the language default applies).
        owner._isset.pop(owner.eClass.findEStructuralFeature(feature), None)


Step = _Set | _Insert | _Remove | _Outside


@dataclass
class _Ordered:
    """A change that also puts back the order in which its owner's features were set.

    pyecore writes an element's attributes in that order, so without this an undone change
    would save the same model with its attributes reordered.
    """

    change: Step
    order: list[Any] | None = None

    def do(self) -> None:
        self.order = list(self.change.owner._isset)
        self.change.do()

    def undo(self) -> None:
        self.change.undo()
        held = self.change.owner._isset
        if self.order is not None and list(held) != self.order:
            keys = [key for key in self.order if key in held]
            keys += [key for key in held if key not in keys]
            values = {key: held[key] for key in keys}
            held.clear()
            held.update(values)


@dataclass
class Footprint:
    """Ids of what a step touched: (object, feature) pairs it set, objects it set on or pointed
    to, and objects it added or removed."""

    features: set[tuple[int, str]]
    touched: set[int]
    lives: set[int]


def _is_object(value: object) -> bool:
    return isinstance(value, EObject)


class Recorder:
    """Applies small changes to the model and remembers them, in order, to undo or redo."""

    def __init__(self) -> None:
        self.steps: list[_Ordered] = []

    def _apply(self, change: Step) -> None:
        step = _Ordered(change)
        step.do()
        self.steps.append(step)

    def set(self, owner: EObject, feature: str, value: Any) -> None:
        """Set a single-valued feature (a containment moves `value` here, recorded)."""
        old = owner.eGet(feature)
        if old is value:
            return
        if isinstance(value, EObject) and _is_containment(owner, feature):
            self.detach(value)
        was_set = owner.eIsSet(owner.eClass.findEStructuralFeature(feature))
        self._apply(_Set(owner, feature, old, value, was_set))

    def insert(self, owner: EObject, feature: str, item: EObject, index: int | None = None) -> None:
        """Insert into a many-valued feature, at `index` or at the end."""
        if _is_containment(owner, feature):
            self.detach(item)
        size = len(owner.eGet(feature))
        self._apply(_Insert(owner, feature, item, size if index is None else index))

    def remove(self, owner: EObject, feature: str, item: EObject) -> None:
        """Remove from a many-valued feature, remembering the index for undo."""
        index = list(owner.eGet(feature)).index(item)
        self._apply(_Remove(owner, feature, item, index))

    def outside(
        self, owner: EObject, apply: Callable[[], None], revert: Callable[[], None]
    ) -> None:
        """Run `apply` (a change of another file, owned by `owner`) now; undo runs `revert`."""
        self._apply(_Outside(owner, apply, revert))

    @property
    def reaches_outside(self) -> bool:
        """Whether these changes include one outside the model (validate everything again)."""
        return any(isinstance(step.change, _Outside) for step in self.steps)

    def detach(self, obj: EObject) -> None:
        """Take an object out of its container, if it has one."""
        container, feature = obj.eContainer(), obj.eContainmentFeature()
        if container is None or feature is None:
            return
        if feature.many:
            self.remove(container, feature.name, obj)
        else:
            self._apply(_Set(container, feature.name, obj, None, True))

    def undo(self) -> None:
        """Revert every recorded change, last first."""
        for step in reversed(self.steps):
            step.undo()

    def redo(self) -> None:
        """Apply every recorded change again, first first."""
        for step in self.steps:
            step.do()

    def footprint(self) -> Footprint:
        """What the recorded steps touch, to tell whether another step's undo can pass them."""
        found = Footprint(set(), set(), set())
        for step in self.steps:
            change = step.change
            if isinstance(change, _Outside):
                found.lives.add(id(change.owner))
            elif isinstance(change, _Set):
                found.features.add((id(change.owner), change.feature))
                found.touched.add(id(change.owner))
                found.touched.update(id(v) for v in (change.old, change.new) if _is_object(v))
            else:
                # Insertions and removals in one list commute (undo removes the very item, or
                # puts it back near its index); what matters is the item coming and going.
                found.lives.add(id(change.item))
        return found

    def overlaps(self, other: Recorder) -> bool:
        """Whether undoing these changes would disturb `other`'s (made after them), or back."""
        mine, theirs = self.footprint(), other.footprint()
        return bool(
            mine.features & theirs.features
            or mine.lives & (theirs.lives | theirs.touched)
            or theirs.lives & mine.touched
        )

    def removed(self, obj: object) -> bool:
        """Whether these changes took `obj` out of a list it was in."""
        return any(
            isinstance(step.change, _Remove) and step.change.item is obj for step in self.steps
        )

    def changes(self) -> list[Change]:
        """What the recorded steps change, for incremental validation; undo and redo change the
        same objects and features, so the list serves after either."""
        return [step.change.described() for step in self.steps]


def _is_containment(owner: EObject, feature: str) -> bool:
    found = owner.eClass.findEStructuralFeature(feature)
    return bool(getattr(found, "containment", False))

"""Read-only model objects for loads nothing will edit or save (`sceml validate`).

A pyecore object carries bookkeeping for editing: `EObject.__new__` registers it for
`allInstances()` (a WeakSet entry), gives it two listener lists and an `_inverse_rels` set, and
each set feature gets a value holder (`EValue`) of six fields. `benchmarks/object_memory.py`
measured about 1,950 B of Python objects per model object at 10k nodes (these: about 770 B), and
at 208k nodes that, not the parse, set the process's peak. Objects made here are instances of the same generated
classes, read the same through pyecore's descriptors and `sceml.model.traversal`, and leave out
what only an edit would use:

- no `allInstances()` registration (SceML never asks for it);
- one shared, empty object for both listener lists (nothing attaches listeners to a model being
  validated);
- `_inverse_rels`: a real set only for objects a reference without an opposite can point at
  (participants, module parameters and definitions: module expansion records its copies'
  references in them and removes them again), one shared empty stand-in for the rest; the link
  of a child to its container, which pyecore also records there, is not recorded (only
  `EObject.delete` reads it, an edit);
- single-valued features held by `Held`, one field, instead of `EValue`;
- `_isset` read off the holders (`SetFeatures`) instead of a dict per object;
- the class's shared attribute-key table filled first, as `fastobjects.new` does.

Writing into such an object fails loudly instead of going unnoticed: every pyecore change
notifies the object's listeners, which refuse to be gone through here; every pyecore setter and
`sceml.model.fastobjects` write marks the feature in `_isset`, a `SetFeatures` here; `Held` has
no setter; the shared stand-in for `_inverse_rels` refuses to record anything.
`tests/core/test_light_objects.py` runs the validation corpus through both loads and compares
the diagnostics, so a write that a validation path attempts shows up there.
"""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache
from typing import Any, NoReturn, TypeVar

from pyecore.ecore import EObject, EReference
from pyecore.valuecontainer import EOrderedSet

import scemlmodel as scm

from .fastobjects import Slot, _set_holder, share_keys

T = TypeVar("T", bound=EObject)

_object_new = object.__new__


class ReadOnlyModelError(TypeError):
    """Code tried to change an object of a read-only (validate-only) load."""


def _refuse(*_args: object, **_kwargs: object) -> NoReturn:
    raise ReadOnlyModelError(
        "this model was loaded read-only (for validation); load it with "
        "sceml.model.loading.load(..., read_only=False) to change it"
    )


class _Unlistened:
    """The listener lists of every read-only object: empty, and impossible to go through.

    Every pyecore change (a setter, an append, a remove, a pop, a clear) notifies the object's
    listeners, so it fails here, where a read-only model is changed by mistake.
    """

    __slots__ = ()
    __iter__ = append = extend = insert = remove = _refuse

    def __len__(self) -> int:
        return 0


_NO_LISTENERS = _Unlistened()


class _Unlinked:
    """`_inverse_rels` of the read-only objects no reference without an opposite can point at:
    always empty, and refusing to record anything."""

    __slots__ = ()
    add = remove = discard = update = _refuse

    def __contains__(self, _item: object) -> bool:
        return False

    def __iter__(self) -> Iterator[Any]:
        return iter(())

    def __len__(self) -> int:
        return 0


_NO_LINKS = _Unlinked()


class SetFeatures:
    """`_isset` of a read-only object: the features the file set, in the order it set them,
    read off the object's holders instead of kept in a dict of its own (about 150 B an object).

    The reader makes a holder exactly when it sets a feature (a `Held`, or an `EOrderedSet`
    with the first item); pyecore makes an empty `EValue` or collection when a feature never set
    is read, which does not count. pyecore's setters and `sceml.model.fastobjects`' writes all
    mark their feature here, so each of them fails on a read-only object.
    """

    __slots__ = ("owner",)

    def __init__(self, owner: EObject) -> None:
        self.owner = owner

    def __contains__(self, feature: object) -> bool:
        name = getattr(feature, "_name", None)
        owner = self.owner
        if name is None or getattr(type(owner), name, None) is not feature:
            return False  # not a feature of this object's class (pyecore's keys are features)
        holder = owner.__dict__.get(name)
        kind = type(holder)
        return kind is Held or (kind is EOrderedSet and bool(holder.items))

    def __iter__(self) -> Iterator[Any]:
        cls = type(self.owner)
        for name, holder in list(self.owner.__dict__.items()):
            kind = type(holder)
            if kind is Held or (kind is EOrderedSet and holder.items):
                yield getattr(cls, name)

    def __len__(self) -> int:
        return sum(1 for _ in self)

    __setitem__ = __delitem__ = pop = popitem = clear = update = setdefault = _refuse


class Held:
    """The holder of a single-valued feature's value: what pyecore's descriptor and
    `sceml.model.traversal` read of an `EValue` (`_get()`, `_value`), and nothing else."""

    __slots__ = ("_value",)

    def __init__(self, value: object) -> None:
        self._value = value

    def _get(self) -> object:
        return self._value

    _set = remove_or_unset = check = _refuse


_LINKS_KEPT: dict[type, bool] = {}  # by class: whether its objects get a real `_inverse_rels`


def _links_kept(cls: type) -> bool:
    """Whether a reference without an opposite may point at an instance of `cls`."""
    kept = _LINKS_KEPT.get(cls)
    if kept is None:
        kept = _LINKS_KEPT[cls] = any(issubclass(cls, kind) for kind in _reference_targets())
        share_keys(cls, new_object)  # before the first real one: see fastobjects.share_keys
    return kept


@cache
def _reference_targets() -> tuple[type[EObject], ...]:
    found: list[type[EObject]] = []
    for classifier in scm.eClass.eClassifiers:
        for feature in getattr(classifier, "eStructuralFeatures", ()):
            if (
                isinstance(feature, EReference)
                and not feature.containment
                and feature.eOpposite is None
                and isinstance(feature._eType, type)
            ):
                found.append(feature._eType)
    return tuple(found)


def new(cls: type[T]) -> T:
    """A new, empty, read-only object of a generated class."""
    links = _LINKS_KEPT.get(cls)
    if links is None:
        links = _links_kept(cls)
    obj = new_object(cls)
    obj._inverse_rels = set() if links else _NO_LINKS
    return obj


def new_object(cls: type[T]) -> T:
    """`new` without `_inverse_rels`."""
    obj = _object_new(cls)
    # The attributes EObject.__new__ sets, in its order (objects of a class then share keys).
    obj._internal_id = None
    obj._isset = SetFeatures(obj)
    obj._container = None
    obj._containment_feature = None
    obj._eresource = None
    obj.listeners = _NO_LISTENERS
    obj._eternal_listener = _NO_LISTENERS
    obj._inverse_rels = _NO_LINKS
    obj._staticEClass = False
    obj.dyn_inst = obj
    return obj


def set_value(obj: EObject, slot: Slot, value: object) -> None:
    """As `fastobjects.set_value`, into a read-only object."""
    state = obj.__dict__
    state[slot.name] = Held(value)


def add_child(parent: EObject, slot: Slot, child: EObject) -> None:
    """As `fastobjects.add_child`, without recording the link in the child's `_inverse_rels`."""
    state = parent.__dict__
    feature = slot.feature
    if slot.many:
        held = state.get(slot.name)
        if held is None:
            held = state[slot.name] = _set_holder(parent, feature, True)
        items = held.items
        held.map[child] = len(items)
        items.append(child)
    else:
        state[slot.name] = Held(child)
    child_state = child.__dict__
    child_state["_container"] = parent
    child_state["_containment_feature"] = feature


def set_reference(obj: EObject, slot: Slot, target: EObject) -> None:
    """As `fastobjects.set_reference`, into read-only objects."""
    state = obj.__dict__
    state[slot.name] = Held(target)
    opposite = slot.opposite
    if opposite is None:
        target._inverse_rels.add((obj, slot.feature))  # a participant, parameter or definition
        return
    target_state = target.__dict__
    held = target_state.get(slot.reverse)
    if held is None:
        held = target_state[slot.reverse] = _set_holder(target, opposite, False)
    index = held.map
    if obj not in index:
        items = held.items
        index[obj] = len(items)
        items.append(obj)


def is_read_only(obj: EObject) -> bool:
    """Whether `obj` was made by a read-only load."""
    return type(obj.__dict__.get("_isset")) is SetFeatures


__all__ = [
    "Held",
    "SetFeatures",
    "ReadOnlyModelError",
    "add_child",
    "is_read_only",
    "new",
    "set_reference",
    "set_value",
]

"""Build pyecore objects by writing the state pyecore's own setters would leave, without them.

pyecore sets every feature through a descriptor (`EStructuralFeature.__set__` -> `EValue._set`):
a type check, a `Notification` whose delivery walks the container chain up to the resource, the
`_isset` mark, container bookkeeping, `_inverse_rels` and the opposite end. Reading a file or
copying a model does that for every attribute of every object, which is most of the time spent.

The functions here write the end state directly, for the shapes of feature SceML's metamodel
has: single-valued attributes, containments (single or an ordered unique set) without an
opposite, and single-valued cross references with no opposite or a many-valued one
(Flow.source/target <-> GraphElement.outgoing/incoming). Callers ask `*_supported` first and use
pyecore's setters for anything else.

What they leave out, on purpose:

- Notifications. They are only delivered to listeners, and nothing listens to objects that are
  being made (a file being read, a copy being made): a new object's `listeners` and
  `_eternal_listener` lists are empty, and a resource that is still loading has none either
  (ResourceSet.get_resource creates it and loads it at once). A reference without an opposite
  notifies only its holder; the copier sets the opposite end of an original through pyecore.
  (SceML attaches no pyecore listeners anywhere.)
- Type checks. The callers have checked already: the reader checks each value and each
  object's class against the feature, the copier copies values that were checked when set.

Preconditions the callers keep (pyecore's setters would otherwise also undo a previous state):
a feature is set at most once per object, a child has no container yet, and objects given here are
never `EProxy`s, except the target of a reference without an opposite (whose only bookkeeping,
`_inverse_rels`, pyecore itself reads through the proxy without resolving it).
"""

from __future__ import annotations

from functools import cache
from typing import Any, TypeVar

from pyecore.ecore import EAttribute, EObject, EReference, EStructuralFeature
from pyecore.valuecontainer import EOrderedSet, EValue

T = TypeVar("T", bound=EObject)

_object_new = object.__new__
_eobject_new = EObject.__new__


def new(cls: type[T]) -> T:
    """A new, empty object of a generated class: `cls()` without the constructor's call chain.

    `EObject.__new__` sets up pyecore's bookkeeping (and registers the object for
    `allInstances()`); the generated constructors, given no arguments, add nothing to it
    (tests/core/test_fast_objects.py checks that for every SceML class), but their chain of
    keyword-only `__init__`s costs four times as much as the rest.
    """
    if cls not in _KEYS_SHARED:
        share_keys(cls, _eobject_new)
    return _eobject_new(cls)  # type: ignore[no-any-return]


_KEYS_SHARED: set[type] = set()


def share_keys(cls: type, make: Any) -> None:
    """Fill the table of attribute names `cls`'s instances share, with one throwaway object
    `make(cls)` given every feature's name, before the real ones are made.

    CPython keeps an instance's `__dict__` small by sharing one table of keys among a class's
    instances, but a key written through `__dict__` (as the holders are, here and by pyecore's
    descriptors) joins that table only while one instance uses it; otherwise each instance's dict
    becomes a table of its own, about 650 B more (a flow read from a file: 1,150 B instead of
    500 B, since thousands exist before their references are set). Transient features count:
    the opposite ends `incoming` and `outgoing` are.
    """
    _KEYS_SHARED.add(cls)
    first = make(cls)
    state = first.__dict__
    for feature in cls.eClass.eAllStructuralFeatures():  # type: ignore[attr-defined]
        state.setdefault(feature.name, None)
    state.clear()  # no cycle through dyn_inst: freed at once (and gone from allInstances())


class Slot:
    """What the direct writes need to know of one feature, read once from the metamodel.

    pyecore's `many`, `containment` and `eOpposite` are properties and descriptors, each a
    Python call; a file or a copy asks them hundreds of thousands of times.
    """

    __slots__ = ("feature", "is_cont", "is_ref", "kind", "many", "name", "opposite", "reverse")

    def __init__(self, feature: EStructuralFeature) -> None:
        self.feature = feature
        self.name: str = feature._name
        self.many: bool = feature.many
        self.is_ref = isinstance(feature, EReference)
        self.is_cont: bool = self.is_ref and feature.containment
        opposite = feature.eOpposite if self.is_ref else None
        self.opposite: EReference | None = opposite
        self.reverse: str | None = opposite._name if opposite is not None else None
        # The Python class a value must be an instance of (generated classes' features name it).
        kind = feature._eType
        self.kind: Any = kind if isinstance(kind, type) else None


@cache
def slot(feature: EStructuralFeature) -> Slot:
    """The facts of `feature`, computed once."""
    return Slot(feature)


def _value_holder(owner: EObject, slot: Slot, value: object) -> EValue:
    # The fields EValue.__init__ sets, in its order, set as it sets them (as attributes: no
    # separate dict object is made); `_value` is what `_set` leaves.
    holder = _object_new(EValue)
    holder.owner = owner
    holder.feature = slot.feature
    holder.is_ref = slot.is_ref
    holder.is_cont = slot.is_cont
    holder.generic_type = None
    holder._value = value
    return holder


def _set_holder(owner: EObject, feature: EReference, is_cont: bool) -> EOrderedSet:
    # The fields EOrderedSet.__init__ sets (through ECollection and OrderedSet), in its order.
    holder = _object_new(EOrderedSet)
    holder.items = []
    holder.map = {}
    holder.owner = owner
    holder.feature = feature
    holder.is_ref = True
    holder.is_cont = is_cont
    holder.generic_type = None
    holder._orderedset_update = False
    return holder


def set_value(obj: EObject, slot: Slot, value: object) -> None:
    """`obj.<feature> = value` for a single-valued attribute not set before, or `None` for any
    single-valued feature not set before (SceML writes that as nil: it counts as set)."""
    # _value_holder written out: this runs for most attributes of every object read or copied.
    holder = _object_new(EValue)
    holder.owner = obj
    holder.feature = feature = slot.feature
    holder.is_ref = slot.is_ref
    holder.is_cont = slot.is_cont
    holder.generic_type = None
    holder._value = value
    state = obj.__dict__
    state["_isset"][feature] = None  # first: a read-only object refuses here, unchanged
    state[slot.name] = holder


def add_child(parent: EObject, slot: Slot, child: EObject) -> None:
    """Put a new `child` into `parent`'s containment (appended if it is many-valued)."""
    state = parent.__dict__
    feature = slot.feature
    state["_isset"][feature] = None  # first: a read-only object refuses here, unchanged
    if slot.many:
        held = state.get(slot.name)
        if held is None:
            held = state[slot.name] = _set_holder(parent, feature, True)
        items = held.items
        held.map[child] = len(items)
        items.append(child)
    else:
        state[slot.name] = _value_holder(parent, slot, child)
    child_state = child.__dict__
    child_state["_container"] = parent
    child_state["_containment_feature"] = feature
    # pyecore records the link to the container like any reference without an opposite.
    child_state["_inverse_rels"].add((parent, feature))


def replace_child(parent: EObject, slot: Slot, child: EObject | None) -> bool:
    """`parent.<feature> = child` for a single-valued containment that holds a value already,
    where `child` is new (no container, no resource): what pyecore's setter leaves, the old
    value let go. Returns False, having done nothing, for any other case (the caller then uses
    pyecore's setter).

    Module expansion replaces every parameter reference of a use's copies by a copy of its
    chosen value this way: thousands per large scenario, each a notification walk through
    pyecore's setter.
    """
    holder = parent.__dict__.get(slot.name)
    if type(holder) is not EValue or not slot.is_cont or slot.many or slot.opposite is not None:
        return False
    if child is not None and (child._container is not None or child._eresource is not None):
        return False
    holder.check(child)  # pyecore's type check, with its error
    previous = holder._value
    holder._value = child
    feature = slot.feature
    parent._isset[feature] = None
    couple = (parent, feature)
    if child:
        child._container = parent
        child._containment_feature = feature
    if previous:
        previous._container = None
        previous._containment_feature = None
    # The link to the container, recorded as pyecore records a reference without an opposite.
    if child is not None and hasattr(child, "_inverse_rels"):
        if hasattr(previous, "_inverse_rels"):
            previous._inverse_rels.remove(couple)
        child._inverse_rels.add(couple)
    elif child is None and hasattr(previous, "_inverse_rels"):
        previous._inverse_rels.remove(couple)
    return True


def set_reference(obj: EObject, slot: Slot, target: EObject) -> None:
    """`obj.<feature> = target` for a single-valued cross reference not set before, and the
    opposite end: `target.<opposite>` gains `obj`."""
    holder = _object_new(EValue)  # _value_holder written out, as in set_value
    holder.owner = obj
    holder.feature = feature = slot.feature
    holder.is_ref = True
    holder.is_cont = False
    holder.generic_type = None
    holder._value = target
    state = obj.__dict__
    state["_isset"][feature] = None  # first: a read-only object refuses here, unchanged
    state[slot.name] = holder
    opposite = slot.opposite
    if opposite is None:
        # Through the attribute, which an EProxy answers from itself without resolving.
        target._inverse_rels.add((obj, feature))
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
    target_state["_isset"][opposite] = None


@cache
def attribute_supported(feature: EStructuralFeature) -> bool:
    """Whether `set_value` can set this feature to a value."""
    return isinstance(feature, EAttribute) and not feature.many and _stored(feature)


@cache
def none_supported(feature: EStructuralFeature) -> bool:
    """Whether `set_value` can set this feature to None (pyecore's unset has nothing else to
    undo when the feature held nothing before)."""
    return not feature.many and _stored(feature)


@cache
def child_supported(feature: EStructuralFeature) -> bool:
    """Whether `add_child` can fill this feature."""
    return (
        isinstance(feature, EReference)
        and feature.containment
        and feature.eOpposite is None
        and _stored(feature)
        and (not feature.many or _is_ordered_set(feature))
    )


@cache
def reference_supported(feature: EStructuralFeature) -> bool:
    """Whether `set_reference` can set this feature."""
    if not isinstance(feature, EReference) or feature.containment or feature.many:
        return False
    opposite = feature.eOpposite
    if not _stored(feature):
        return False
    if opposite is None:
        return True
    return bool(
        opposite.many
        and not opposite.containment
        and not opposite.derived
        and _is_ordered_set(opposite)
    )


def _stored(feature: EStructuralFeature) -> bool:
    return not feature.derived and not feature.transient


def _is_ordered_set(feature: EStructuralFeature) -> bool:
    # ECollection.create picks the holder class from these flags; EOrderedSet is the one built here.
    return bool(feature.ordered and feature.unique and not feature.derived)

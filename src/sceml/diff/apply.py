"""Carry one leaf of one version onto the same element of another, by its path (`destination.x`).

A merge takes the other side's change of one leaf and nothing around it: in `destination.x`
only x is copied, so that the own side's change of `destination.y` stays. Where the two sides
hold different kinds of object on the way (a world position against a lane position), the
whole object is copied. Copied objects are re-pointed at the receiving model's actors by name.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from pyecore.ecore import EAttribute, EObject, EReference

import scemlmodel as scm

from ..model.copying import copy_tree
from ..model.traversal import all_contents, single_references
from .snapshot import ITEM_KEYS

#: The receiving model's actor of a given name (None when it has none).
ActorLookup = Callable[[str], EObject | None]

_SEGMENT = re.compile(r"(\w+)(?:\[([^\]]*)\])?")


def segments(path: str) -> list[tuple[str, str | None]]:
    """`waypoints[1].x` -> [("waypoints", "1"), ("x", None)]."""
    found = []
    for part in _split(path):
        match = _SEGMENT.fullmatch(part)
        if match is None:
            raise ValueError(f"not a leaf path: {path!r}")
        found.append((match.group(1), match.group(2)))
    return found


def _split(path: str) -> list[str]:
    """Split on dots outside brackets (a binding's role name may hold none, but be safe)."""
    parts, depth, current = [], 0, ""
    for char in path:
        depth += {"[": 1, "]": -1}.get(char, 0)
        if char == "." and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += char
    parts.append(current)
    return parts


def copy_leaf(target: EObject, source: EObject, path: str, actors: ActorLookup) -> None:
    """Make `target` hold at `path` what `source` holds there."""
    steps = segments(path)
    for index, (name, key) in enumerate(steps):
        last = index == len(steps) - 1
        if key is not None:
            source_item, target_item = _item(source, name, key), _item(target, name, key)
            if (
                last
                or source_item is None
                or target_item is None
                or _kinds_differ(source_item, target_item)
            ):
                _replace_item(target, name, key, source_item, actors)
                return
            target, source = target_item, source_item
            continue
        feature = target.eClass.findEStructuralFeature(name)
        if feature is None:
            # The object on the way was replaced whole by theirs' of another kind (a lane
            # position for a world one), which has no such leaf: nothing is left to carry.
            return
        if isinstance(feature, EAttribute):
            target.eSet(feature, source.eGet(name))
            return
        assert isinstance(feature, EReference)
        held = source.eGet(name)
        if not feature.containment:
            target.eSet(feature, _retarget(held, actors))
            return
        own = target.eGet(name)
        if last or held is None or own is None or _kinds_differ(held, own):
            target.eSet(feature, copied(held, actors) if held is not None else None)
            return
        target, source = own, held


def set_layout(target: EObject, source: EObject) -> None:
    """Give `target` the diagram position `source` has (or none)."""
    held = source.eGet("diagramPosition")
    target.diagramPosition = copy_tree(held) if held is not None else None


def copied(obj: EObject, actors: ActorLookup) -> EObject:
    """A copy of `obj` whose actor references name the receiving model's actors."""
    duplicate = copy_tree(obj)
    for inner in [duplicate, *all_contents(duplicate)]:
        for feature, held in list(single_references(inner)):
            if isinstance(held, scm.Participant):
                inner.eSet(feature, _retarget(held, actors))
    return duplicate


def _retarget(held: object, actors: ActorLookup) -> object:
    if isinstance(held, scm.Participant):
        return actors(str(held.name))
    return held


def _kinds_differ(one: EObject, other: EObject) -> bool:
    return bool(one.eClass is not other.eClass)


def _item(owner: EObject, name: str, key: str) -> EObject | None:
    items = list(owner.eGet(name))
    attribute = ITEM_KEYS.get(name)
    if attribute is None:
        position = int(key)
        return items[position] if position < len(items) else None
    return next((item for item in items if str(item.eGet(attribute)) == key), None)


def _replace_item(
    owner: EObject, name: str, key: str, item: EObject | None, actors: ActorLookup
) -> None:
    items = owner.eGet(name)
    own = _item(owner, name, key)
    if ITEM_KEYS.get(name) is None:
        # Positions in a list (waypoints): replace in place, append, or drop the tail item.
        position = int(key)
        if own is not None and item is not None:
            items[position] = copied(item, actors)
        elif item is not None:
            items.append(copied(item, actors))
        elif own is not None:
            items.remove(own)
        return
    if own is not None:
        items.remove(own)
    if item is not None:
        items.append(copied(item, actors))

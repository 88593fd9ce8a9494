"""Stable, opaque ids for the nodes, flows and actors of a session (`n3`, `f4`, `a2`)."""

from __future__ import annotations

from pyecore.ecore import EObject


class Ids:
    """Hands out one id per object for the whole session and finds the object again.

    Objects are held strongly: undo re-attaches the very same pyecore objects, so an id must
    never be given to another object, even after its object left the model.
    """

    def __init__(self) -> None:
        self._ids: dict[EObject, str] = {}
        self._objects: dict[str, EObject] = {}
        self._counter = 0

    def of(self, obj: EObject, prefix: str) -> str:
        """The id of `obj`, made on first use with `prefix` (`n` node, `f` flow, `a` actor)."""
        known = self._ids.get(obj)
        if known is not None:
            return known
        self._counter += 1
        made = f"{prefix}{self._counter}"
        self._ids[obj] = made
        self._objects[made] = obj
        return made

    def find(self, identifier: object) -> EObject | None:
        """The object with this id, or None."""
        return self._objects.get(identifier) if isinstance(identifier, str) else None

    def known(self, obj: EObject) -> str | None:
        """The id of `obj` if it has one already."""
        return self._ids.get(obj)

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
        self._heirs: dict[str, list[EObject]] = {}
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
        """The object with this id, or None (of objects sharing an id, the one in the model)."""
        if not isinstance(identifier, str) or identifier not in self._objects:
            return None
        found = self._objects[identifier]
        for heir in self._heirs.get(identifier, ()):
            if heir.eContainer() is not None:
                return heir
        return found

    def inherit(self, heir: EObject, ancestor: EObject) -> None:
        """Give `heir` the id of `ancestor`, which it replaces in the model (an actor's new kind).

        Only one of them is in the model at a time (undo swaps them back), so the browser keeps
        one id, and the panel the user is typing in is not re-created under the cursor.
        """
        identifier = self._ids[ancestor]
        self._ids[heir] = identifier
        self._heirs.setdefault(identifier, []).append(heir)

    def known(self, obj: EObject) -> str | None:
        """The id of `obj` if it has one already."""
        return self._ids.get(obj)

    @property
    def counter(self) -> int:
        """How many ids were handed out (the next one is one more)."""
        return self._counter

    def in_resource(self, resource: object) -> dict[str, str]:
        """Each id of an object stored in `resource`, with the object's place in it (its URI
        fragment), so that a later run can give the same objects the same ids."""
        found: dict[str, str] = {}
        for identifier in self._objects:
            current = self.find(identifier)
            if current is not None and current.eResource is resource:
                found[identifier] = current.eURIFragment()
        return found

    def restore(self, places: dict[str, str], resource: object, counter: int) -> None:
        """Give the objects at `places` in `resource` the ids an earlier run gave them."""
        for identifier, fragment in places.items():
            try:
                obj = resource.resolve_object(fragment)  # type: ignore[attr-defined]
            except (ValueError, IndexError, AttributeError):
                continue  # not in this base: the replay names what then cannot be found
            if obj is not None and obj not in self._ids:
                self._ids[obj] = identifier
                self._objects[identifier] = obj
        self._counter = max(self._counter, counter)

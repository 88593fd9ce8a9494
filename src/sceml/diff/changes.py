"""What changed between two versions of a scenario, as a list of changes in the model's terms."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass, field

from .matching import Matching, match, translate
from .snapshot import Element, Leaf, Snapshot

#: The parts of a scenario a change can touch, in the order reports list them.
PARTS = ("root", "actors", "nodes", "modules", "flows", "layout")


@dataclass(frozen=True)
class Change:
    """One change: which part, what happened, to which element, at which path, from what to what.

    `action` is added, removed, changed, renamed or moved (layout). `element` is the element's
    name in the new version (in the old one when it was removed); `was` its old name when it
    was renamed. `path` is the readable place: `TurnLeft_1.destination.x`, `ego`, `A -> B`.
    """

    part: str
    action: str
    element: str
    path: str
    kind: str = ""
    old: Leaf = None
    new: Leaf = None
    unit: str = ""
    was: str | None = None

    def touches(self, name: str) -> bool:
        """Whether this change is in part `name`, or of an element (old or new) called `name`."""
        if name in (self.part, self.element, self.was):
            return True
        return self.part == "flows" and name in self.path.split(" -> ")


@dataclass
class Diff:
    """The changes from `old` to `new`, and the two readings they were found in."""

    old: Snapshot
    new: Snapshot
    matching: Matching
    changes: list[Change] = field(default_factory=list)

    @property
    def semantic(self) -> list[Change]:
        """The changes that change what the scenario means (all but layout)."""
        return [c for c in self.changes if c.part != "layout"]

    @property
    def layout(self) -> list[Change]:
        """Diagram positions only."""
        return [c for c in self.changes if c.part == "layout"]


def compare(old: Snapshot, new: Snapshot) -> Diff:
    """Every change from `old` to `new`, root first, then actors, nodes, flows and layout."""
    matching = match(old, new)
    found: list[Change] = []
    found += _elements(old.actors, new.actors, matching.actors, matching, "actors")
    found += _elements(old.nodes, new.nodes, matching.nodes, matching, "nodes")
    found += _flows(old, new, matching)
    found.sort(key=lambda change: PARTS.index(change.part))
    return Diff(old=old, new=new, matching=matching, changes=found)


def _part(element: Element, default: str) -> str:
    if element.kind == "RootNode":
        return "root"
    if element.kind == "ModuleUse":
        return "modules"
    return default


def _elements(
    old: dict[str, Element],
    new: dict[str, Element],
    pairs: dict[str, str],
    matching: Matching,
    part: str,
) -> Iterator[Change]:
    matched_new = set(pairs.values())
    for name, element in old.items():
        if name not in pairs:
            yield Change(_part(element, part), "removed", name, name, element.kind)
    for name, element in new.items():
        if name not in matched_new:
            yield Change(_part(element, part), "added", name, name, element.kind)
    renamed_from = {new_name: old_name for old_name, new_name in pairs.items()}
    for name, element in new.items():
        if name in renamed_from:
            yield from _element_changes(old[renamed_from[name]], element, name, matching, part)


def _element_changes(
    old: Element, new: Element, name: str, matching: Matching, part: str
) -> Iterator[Change]:
    where = _part(new, part)
    was = old.name if old.name != new.name else None
    if was is not None:
        yield Change(where, "renamed", name, name, new.kind, old.name, new.name, was=was)
    for path in _union(old.leaves, new.leaves):
        before = translate(old.leaves.get(path), matching.actors)
        after = new.leaves.get(path)
        if before != after:
            unit = new.units.get(path) or old.units.get(path, "")
            yield Change(
                where, "changed", name, f"{name}.{path}", new.kind, before, after, unit, was
            )
    if old.layout != new.layout:
        yield Change("layout", "moved", name, name, new.kind, old.layout, new.layout, was=was)


def _union(old: dict[str, Leaf], new: dict[str, Leaf]) -> list[str]:
    return list(dict.fromkeys([*old, *new]))


def _flows(old: Snapshot, new: Snapshot, matching: Matching) -> Iterator[Change]:
    before = Counter((matching.nodes.get(s, s), matching.nodes.get(t, t)) for s, t in old.flows)
    after = Counter(new.flows)
    for (source, target), count in (before - after).items():
        for _ in range(count):
            yield Change("flows", "removed", source, f"{source} -> {target}", "Flow")
    for (source, target), count in (after - before).items():
        for _ in range(count):
            yield Change("flows", "added", source, f"{source} -> {target}", "Flow")

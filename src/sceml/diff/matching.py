"""Which element of one version is which of the other: by name, then renames by identity signals.

A node renamed in the editor keeps its kind, its actor, its parameters and its neighbours; a node
deleted and another added rarely keep all of them. So leftovers of the same kind are paired by
how many of those signals they share (at least half), best pairs first. Actors are paired first,
so that a renamed actor does not make every node that refers to it look changed.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from .snapshot import Element, Leaf, Snapshot

#: At least this share of the signals must agree for two differently named elements to be one.
SIMILAR = 0.5

#: Above this many candidate pairs of one kind, only exact signatures are paired: a diff of
#: 10,000 renamed nodes must not compare 10^8 pairs.
MAX_PAIRS = 250_000


@dataclass
class Matching:
    """Old name -> new name for the actors and the nodes found in both versions."""

    actors: dict[str, str]
    nodes: dict[str, str]


def match(old: Snapshot, new: Snapshot) -> Matching:
    """Pair the actors, then the nodes, of two versions of a scenario."""
    actors = _pair(old.actors, new.actors, lambda name, element: _fields(element.leaves))
    old_next, old_previous = _neighbours(old.flows)
    new_next, new_previous = _neighbours(new.flows)
    nodes: dict[str, str] = {}

    def old_signals(name: str, element: Element) -> set[object]:
        leaves = _fields({k: translate(v, actors) for k, v in element.leaves.items()})
        after = {("next", nodes.get(n, n)) for n in old_next[name]}
        before = {("previous", nodes.get(n, n)) for n in old_previous[name]}
        return leaves | after | before

    def new_signals(name: str, element: Element) -> set[object]:
        after = {("next", n) for n in new_next[name]}
        before = {("previous", n) for n in new_previous[name]}
        return _fields(element.leaves) | after | before

    # Nodes of the same name first, so that their neighbours count as signals for the rest.
    nodes.update(_same_names(old.nodes, new.nodes))
    nodes.update(_pair(old.nodes, new.nodes, old_signals, new_signals, taken=nodes))
    return Matching(actors=actors, nodes=nodes)


def _fields(leaves: dict[str, Leaf]) -> set[object]:
    """One signal per field: a destination is one parameter of a node however many leaves it
    has (x, y, z, h), so a changed destination weighs as much as a changed speed."""
    grouped: dict[str, list[tuple[str, Leaf]]] = defaultdict(list)
    for path, leaf in leaves.items():
        grouped[re.split(r"[.\[]", path, maxsplit=1)[0]].append((path, leaf))
    return {(field, tuple(items)) for field, items in grouped.items()}


def translate(leaf: Leaf, actors: dict[str, str]) -> Leaf:
    """An old leaf in the new version's actor names (a renamed actor's references are unchanged)."""
    if isinstance(leaf, tuple) and len(leaf) == 2 and leaf[0] == "actor":
        return ("actor", actors.get(leaf[1], leaf[1]))
    return leaf


def _neighbours(
    flows: Iterable[tuple[str, str]],
) -> tuple[dict[str, set[str]], dict[str, set[str]]]:
    after: dict[str, set[str]] = defaultdict(set)
    before: dict[str, set[str]] = defaultdict(set)
    for source, target in flows:
        after[source].add(target)
        before[target].add(source)
    return after, before


def _same_names(old: dict[str, Element], new: dict[str, Element]) -> dict[str, str]:
    return {name: name for name, element in old.items() if _same_kind(element, new.get(name))}


def _same_kind(element: Element, other: Element | None) -> bool:
    return other is not None and other.kind == element.kind


Signals = Callable[[str, Element], set[object]]


def _pair(
    old: dict[str, Element],
    new: dict[str, Element],
    old_signals: Signals,
    new_signals: Signals | None = None,
    taken: dict[str, str] | None = None,
) -> dict[str, str]:
    """Same names first, then leftovers of one kind by shared signals, best pairs first."""
    paired = dict(taken) if taken is not None else _same_names(old, new)
    used = set(paired.values())
    left_old = [n for n in old if n not in paired]
    left_new = [n for n in new if n not in used]
    by_kind: dict[str, list[str]] = defaultdict(list)
    for name in left_new:
        by_kind[new[name].kind].append(name)
    read_new = new_signals or old_signals
    candidates: list[tuple[float, int, str, str]] = []
    for order, name in enumerate(left_old):
        others = by_kind.get(old[name].kind, [])
        if len(others) * len(left_old) > MAX_PAIRS:
            others = [o for o in others if new[o].leaves == old[name].leaves]
        mine = old_signals(name, old[name])
        for other in others:
            theirs = read_new(other, new[other])
            score = len(mine & theirs) / max(len(mine | theirs), 1)
            if score >= SIMILAR:
                candidates.append((-score, order, name, other))
    candidates.sort()
    found: dict[str, str] = {}
    for _score, _order, name, other in candidates:
        if name not in found and other not in used:
            found[name] = other
            used.add(other)
    if taken is None:
        return {**paired, **found}
    return found

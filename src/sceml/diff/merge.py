"""Three-way merge of scenarios: the other side's changes carried onto ours, conflicts reported.

Both sides are compared with the base (the same matching as `sceml diff`, so renames are
renames). Every leaf, name, diagram position, actor, node and flow is then decided on its own:
changed on one side only, that side wins; changed the same way on both, it is one change;
changed differently on both, it is a conflict. A node (or actor) deleted on one side and edited
on the other is a conflict; moved only, the deletion wins. After the merge, flows that make a
cycle, and validation errors that neither side had, are conflicts too. With any conflict the
result must not be written (`MergeResult.ok` is false).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model.collector import collector_paused
from ..model.graph import successors, topological_order
from .apply import copied, copy_leaf, set_layout
from .matching import Matching, match
from .snapshot import Element, Leaf, Snapshot, snapshot
from .words import leaf_text, position_text


@dataclass(frozen=True)
class Conflict:
    """Two sides that cannot both be had: where, why, and what each side holds."""

    element: str
    path: str
    reason: str
    ours: str
    theirs: str

    def __str__(self) -> str:
        return f"{self.path}: {self.reason} (ours: {self.ours}; theirs: {self.theirs})"


@dataclass
class MergeResult:
    """The merged scenario (ours, changed in place) and what kept it from being written."""

    scenario: scm.Scenario
    conflicts: list[Conflict] = field(default_factory=list)
    taken: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """Whether the merge may be written."""
        return not self.conflicts


def merge(
    base: scm.Scenario,
    ours: scm.Scenario,
    theirs: scm.Scenario,
    validate: bool = True,
) -> MergeResult:
    """Carry theirs' changes since base onto ours (changed in place); conflicts in the result.

    With `validate`, errors the merged scenario has and neither side had are conflicts.
    """
    # Ours is validated before the merge changes it in place.
    had = _errors(ours) | _errors(theirs) if validate else set()
    # Three readings of large models are built while all three are alive: see compare_models.
    with collector_paused():
        merger = _Merger(snapshot(base), snapshot(ours), snapshot(theirs), ours)
        merger.actors()
        merger.nodes()
        merger.flows()
        merger.check_cycles()
    if validate and not merger.result.conflicts:
        merger.check_rules(had)
    return merger.result


def _errors(scenario: scm.Scenario) -> set[str]:
    from ..validation import validate  # the rules load only when a merge validates

    return {_key(d) for d in validate(scenario) if d.severity is Severity.ERROR}


def _inverse(pairs: dict[str, str]) -> dict[str, str]:
    return {new: old for old, new in pairs.items()}


class _Merger:
    """One merge's state: the three readings, the matchings, and the merged model's objects."""

    def __init__(self, base: Snapshot, ours: Snapshot, theirs: Snapshot, model: scm.Scenario):
        self.base, self.ours, self.theirs = base, ours, theirs
        self.to_ours: Matching = match(base, ours)
        self.to_theirs: Matching = match(base, theirs)
        self.ours_actor_names = _inverse(self.to_ours.actors)
        self.theirs_actor_names = _inverse(self.to_theirs.actors)
        self.result = MergeResult(model)
        root = next((n for n in model.nodes if isinstance(n, scm.RootNode)), None)
        self.root = root
        # theirs' actor and node names -> the merged model's objects.
        self.actor_of: dict[str, EObject | None] = {}
        self.node_of: dict[str, EObject | None] = {}

    # Actors and nodes ------------------------------------------------------------------------

    def actors(self) -> None:
        self._elements("actors", self.to_ours.actors, self.to_theirs.actors)
        for name in self._added(self.theirs.actors, self.to_theirs.actors):
            self._add_actor(name)

    def nodes(self) -> None:
        self._elements("nodes", self.to_ours.nodes, self.to_theirs.nodes)
        for name in self._added(self.theirs.nodes, self.to_theirs.nodes):
            self._add_node(name)

    def _elements(self, part: str, to_ours: dict[str, str], to_theirs: dict[str, str]) -> None:
        base_map: dict[str, Element] = getattr(self.base, part)
        ours_map: dict[str, Element] = getattr(self.ours, part)
        theirs_map: dict[str, Element] = getattr(self.theirs, part)
        lookup = self.actor_of if part == "actors" else self.node_of
        for name, base in base_map.items():
            mine = ours_map.get(to_ours.get(name, "\0"))
            other = theirs_map.get(to_theirs.get(name, "\0"))
            if other is not None:
                lookup[other.name] = mine.obj if mine is not None else None
            if mine is None and other is None:
                continue
            if other is None:
                self._deleted_by_theirs(part, base, mine)
            elif mine is None:
                if self._edited(base, other, "theirs"):
                    self._conflict(
                        base.name,
                        base.name,
                        "deleted by ours, edited by theirs",
                        "deleted",
                        "edited",
                    )
            else:
                self._both_kept(base, mine, other)

    def _deleted_by_theirs(self, part: str, base: Element, mine: Element | None) -> None:
        assert mine is not None
        if self._edited(base, mine, "ours"):
            self._conflict(
                base.name, mine.name, "edited by ours, deleted by theirs", "edited", "deleted"
            )
            return
        self._delete(part, mine.obj)
        self.result.taken.append(f"- {base.name}")

    def _edited(self, base: Element, side: Element, which: str) -> bool:
        """Changed in meaning (a move alone is not an edit: the deletion wins over it)."""
        names = self._names_in(which)
        leaves = {k: _rename(v, names) for k, v in side.leaves.items()}
        return base.name != side.name or base.leaves != leaves

    def _names_in(self, which: str) -> dict[str, str]:
        """A side's actor names -> the base's (leaves compare in the base's names)."""
        return self.ours_actor_names if which == "ours" else self.theirs_actor_names

    def _both_kept(self, base: Element, mine: Element, other: Element) -> None:
        if other.name != base.name and other.name != mine.name:
            if mine.name != base.name:
                self._conflict(base.name, base.name, "renamed differently", mine.name, other.name)
            elif self._name_taken(mine, other.name):
                self._conflict(
                    base.name,
                    other.name,
                    "theirs' new name is taken by ours",
                    mine.name,
                    other.name,
                )
            else:
                mine.obj.name = other.name
                self.result.taken.append(f"~ {base.name} renamed to {other.name}")
        ours_names, theirs_names = self._names_in("ours"), self._names_in("theirs")
        for path in dict.fromkeys([*base.leaves, *mine.leaves, *other.leaves]):
            was = base.leaves.get(path)
            now_ours = _rename(mine.leaves.get(path), ours_names)
            now_theirs = _rename(other.leaves.get(path), theirs_names)
            self._leaf(base, mine, other, path, (was, now_ours, now_theirs))
        if other.layout != base.layout and other.layout != mine.layout:
            if mine.layout != base.layout:
                self._conflict(
                    base.name,
                    f"{mine.name} (position)",
                    "moved differently",
                    position_text(mine.layout),
                    position_text(other.layout),
                )
            else:
                set_layout(mine.obj, other.obj)

    def _leaf(
        self, base: Element, mine: Element, other: Element, path: str, held: tuple[Leaf, Leaf, Leaf]
    ) -> None:
        was, now_ours, now_theirs = held
        if now_theirs in (was, now_ours):
            return
        unit = other.units.get(path, "")
        if now_ours != was:
            self._conflict(
                base.name,
                f"{mine.name}.{path}",
                "changed differently",
                leaf_text(now_ours, unit),
                leaf_text(now_theirs, unit),
            )
            return
        copy_leaf(mine.obj, other.obj, path, self._actor)
        self.result.taken.append(
            f"~ {mine.name}.{path}: {leaf_text(was)} -> {leaf_text(now_theirs, unit)}"
        )

    def _name_taken(self, mine: Element, name: str) -> bool:
        container = mine.obj.eContainer()
        feature = mine.obj.eContainmentFeature()
        return any(o is not mine.obj and o.name == name for o in container.eGet(feature))

    def _added(self, elements: dict[str, Element], matched: dict[str, str]) -> list[str]:
        known = set(matched.values())
        return [name for name in elements if name not in known]

    def _same_addition(self, part: str, name: str) -> bool | None:
        """None: ours has no element of that name; else whether ours added the very same one."""
        mine: Element | None = getattr(self.ours, part).get(name)
        if mine is None:
            return None
        other: Element = getattr(self.theirs, part)[name]
        return mine.kind == other.kind and mine.leaves == other.leaves

    def _add_actor(self, name: str) -> None:
        other = self.theirs.actors[name]
        same = self._same_addition("actors", name)
        if same is not None:
            self.actor_of[name] = self.ours.actors[name].obj
            if not same:
                self._conflict(name, name, "added differently on both sides", "added", "added")
            return
        assert self.root is not None
        duplicate = copied(other.obj, self._actor)
        self.root.actors.append(duplicate)
        self.actor_of[name] = duplicate
        self.result.taken.append(f"+ actor {name}")

    def _add_node(self, name: str) -> None:
        other = self.theirs.nodes[name]
        same = self._same_addition("nodes", name)
        if same is not None:
            self.node_of[name] = self.ours.nodes[name].obj
            if not same:
                self._conflict(name, name, "added differently on both sides", "added", "added")
            return
        duplicate = copied(other.obj, self._actor)
        self.result.scenario.nodes.append(duplicate)
        self.node_of[name] = duplicate
        self.result.taken.append(f"+ {name}")

    def _actor(self, name: str) -> EObject | None:
        if name in self.actor_of:
            return self.actor_of[name]
        # An actor theirs did not touch, or added later in this merge: ours' of that name.
        known = self.ours.actors.get(name)
        return known.obj if known is not None else None

    def _delete(self, part: str, obj: EObject) -> None:
        if part == "nodes":
            scenario = self.result.scenario
            for flow in [f for f in scenario.flows if obj in (f.source, f.target)]:
                _unlink(scenario, flow)
        obj.eContainer().eGet(obj.eContainmentFeature()).remove(obj)

    # Flows -----------------------------------------------------------------------------------

    def flows(self) -> None:
        """theirs' added and removed flows, in base names, carried onto ours."""
        to_base_ours = _inverse(self.to_ours.nodes)
        to_base_theirs = _inverse(self.to_theirs.nodes)
        base = set(self.base.flows)
        mine = {_pair(f, to_base_ours) for f in self.ours.flows}
        other = {_pair(f, to_base_theirs) for f in self.theirs.flows}
        theirs_name = {b: t for t, b in to_base_theirs.items()}
        for source, target in sorted(other - base - mine):
            self._add_flow(theirs_name.get(source, source), theirs_name.get(target, target))
        for flow in sorted((base - other) & mine):
            self._remove_flow(flow)

    def _add_flow(self, source: str, target: str) -> None:
        ends = [self.node_of.get(source), self.node_of.get(target)]
        if source not in self.node_of:
            ends[0] = self._ours_node(source)
        if target not in self.node_of:
            ends[1] = self._ours_node(target)
        if (
            ends[0] is None
            or ends[1] is None
            or ends[0].eContainer() is None
            or ends[1].eContainer() is None
        ):
            self._conflict(
                source,
                f"{source} -> {target}",
                "flow added to a node ours deleted",
                "deleted",
                "connected",
            )
            return
        self.result.scenario.flows.append(scm.Flow(source=ends[0], target=ends[1]))
        self.result.taken.append(f"+ {source} -> {target}")

    def _ours_node(self, name: str) -> EObject | None:
        known = self.ours.nodes.get(name)
        return known.obj if known is not None else None

    def _remove_flow(self, flow: tuple[str, str]) -> None:
        ends = tuple(self._ours_node(self.to_ours.nodes.get(n, n)) for n in flow)
        scenario = self.result.scenario
        for held in list(scenario.flows):
            if (held.source, held.target) == ends:
                _unlink(scenario, held)
                self.result.taken.append(f"- {flow[0]} -> {flow[1]}")
                return

    # Checks of the result --------------------------------------------------------------------

    def check_cycles(self) -> None:
        _, after_cycles = topological_order(self.result.scenario)
        cyclic = _on_cycles(after_cycles)
        if cyclic:
            names = ", ".join(sorted(str(n.name) for n in cyclic))
            self._conflict(
                names,
                f"flows among {names}",
                "the two sides' flows together make a cycle",
                "acyclic",
                "acyclic",
            )

    def check_rules(self, had: set[str]) -> None:
        """Validation errors of the merge that neither side had (`had`) are conflicts."""
        from ..validation import validate

        for diagnostic in validate(self.result.scenario):
            if diagnostic.severity is Severity.ERROR and _key(diagnostic) not in had:
                self._conflict(
                    diagnostic.path or "",
                    diagnostic.path or "",
                    f"together the changes break a rule: {diagnostic.code} {diagnostic.message}",
                    "valid",
                    "valid",
                )

    def _conflict(self, element: str, path: str, reason: str, ours: str, theirs: str) -> None:
        self.result.conflicts.append(Conflict(element, path, reason, ours, theirs))


def _unlink(scenario: scm.Scenario, flow: scm.Flow) -> None:
    """Take a flow out, ends first: its nodes' `incoming`/`outgoing` (the transient opposites
    validation reads) would otherwise keep it."""
    flow.source = None
    flow.target = None
    scenario.flows.remove(flow)


def _on_cycles(unordered: set[scm.GraphElement]) -> set[scm.GraphElement]:
    """Of the nodes a topological order could not place, those on a cycle (what only follows
    one is peeled off, sinks first)."""
    remaining = set(unordered)
    while True:
        sinks = {n for n in remaining if not any(s in remaining for s in successors(n))}
        if not sinks:
            return remaining
        remaining -= sinks


def _key(diagnostic: Diagnostic) -> str:
    return f"{diagnostic.code} {diagnostic.path} {diagnostic.message}"


def _pair(flow: tuple[str, str], names: dict[str, str]) -> tuple[str, str]:
    return (names.get(flow[0], flow[0]), names.get(flow[1], flow[1]))


def _rename(leaf: Leaf, names: dict[str, str]) -> Leaf:
    if isinstance(leaf, tuple) and len(leaf) == 2 and leaf[0] == "actor":
        return ("actor", names.get(leaf[1], leaf[1]))
    return leaf

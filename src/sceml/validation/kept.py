"""The expansion of a scenario's module uses, kept from one incremental run for the next.

Expanding the uses of a large scenario is most of what a drop from the palette cost to validate
(docs/performance.md, issue 27): every node and flow of the scenario is wired, every copy named
and checked. A node placed alone (`edits.placed_alone`: no flow at it, not a use, referring only
to what the scenario holds) changes the expansion in two ways only: it is one more of the
expanded graph's nodes, in its place among the scenario's, and its name is taken, so the names
the expansion chose for unnamed uses and copies (the first free `stem_1`, `base~2`, ...) stay
the same unless the node's name is one of them. `_Kept` keeps the expansion while nothing else
changed and patches it in that case; any other change makes the next run expand again.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from pyecore.ecore import EObject

import scemlmodel as scm

from ..modules.expansion import Expansion
from .context import Context
from .edits import Aspect, Impact
from .reads import EXPANSION

__all__ = ["Kept"]

#: What can change how the module uses expand: the graph's nodes, flows and names, who is bound,
#: the cast, the modules, the scenario's settings. Values of the scenario's own nodes and actors
#: are read where they are (the expansion copies only module internals), so they do not count.
_EXPANDS = EXPANSION | Aspect.SETTINGS


@dataclass
class Kept:
    """An expansion kept from one run for the next; `flat` None means the model had no module
    uses to expand."""

    flat: Expansion | None

    @staticmethod
    def after(context: Context, kept: Kept | None, impact: Impact, full: bool) -> Kept | None:
        """What to keep after a run: the expansion it made or used, or the last one if the run
        changed nothing it reads; nothing when expanding failed (the next run tries again)."""
        if context.flat_computed():
            if context.flat_failure is not None:
                return None
            return Kept(context.flat())
        if kept is None or full or impact.aspects & _EXPANDS or impact.alone:
            return None
        return kept

    def still_holds(self, impact: Impact, model: EObject) -> bool:
        """Whether every change placed a node alone in this scenario, and no such node's name
        is one the expansion chose (the names it chooses avoid the scenario's)."""
        if not impact.only_alone or not impact.alone:
            return False
        if any(graph is not model for graph in impact.alone.values()):
            return False
        if self.flat is None:
            return True  # a node placed alone is not a module use: still nothing to expand
        chosen = _chosen_names(self.flat)
        return not any(str(node.name) in chosen for node in impact.alone)

    def patched(self, impact: Impact) -> Expansion | None:
        """The kept expansion with the nodes placed alone in their places."""
        if self.flat is not None:
            _place_alone(self.flat, impact.alone)
        return self.flat


def _chosen_names(flat: Expansion) -> set[str]:
    """The names the expansion gave: to unnamed uses, and to every copied node."""
    chosen = set(flat.expanded)
    chosen.update(str(copy.name) for copy in flat.origins if isinstance(copy, scm.GraphElement))
    return chosen


def _place_alone(flat: Expansion, alone: Mapping[EObject, EObject]) -> None:
    """Put the nodes placed alone among the expanded graph's nodes, in the scenario's order.

    The expansion lists the scenario's nodes in order, each use replaced by what it expands to
    (all of it together, where the use is); a node placed alone has no flow to wire.
    """
    # Always in the scenario's order now, even for a node the expansion already holds: an
    # insertion undone and redone may put the node back elsewhere (the end of the list).
    expanded: dict[EObject, list[scm.GraphElement]] = {}
    for node in flat.nodes:
        expanded.setdefault(flat.origin(node), []).append(node)
    nodes: list[scm.GraphElement] = []
    for node in flat.scenario.nodes:
        nodes.extend(expanded.get(node, [node] if node in alone else []))
    flat.nodes[:] = nodes

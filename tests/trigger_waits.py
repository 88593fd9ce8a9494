"""What a node's trigger must wait for, from the SceML graph alone (tests/export)."""

from __future__ import annotations

import scemlmodel as scm
from sceml.export.names import sanitize
from sceml.model import graph

ROOT = "Root"

Structure = list[frozenset[str]]


def expected_groups(node: scm.GraphElement, inline: set[scm.GraphElement]) -> Structure:
    """What the SceML graph says `node` waits for: each predecessor by name, or, for a node the
    export writes into its successor's trigger, what that node waits for (plus its own
    condition, named after it, unless it is a join, a port or a wait)."""
    alternatives: list[Structure] = []
    for before in graph.predecessors(node):
        if isinstance(before, scm.RootNode):
            alternatives.append([frozenset([ROOT])])
        elif before in inline:
            passing = isinstance(before, scm.JoiningPolicy | scm.TimeElapsed)
            own = frozenset() if passing else frozenset([sanitize(before.name)])
            alternatives.append([group | own for group in expected_groups(before, inline)])
        else:
            alternatives.append([frozenset([sanitize(before.name)])])
    one = isinstance(node, scm.JoinOneFinished) or (
        isinstance(node, scm.EndNode) and node.policy is scm.JoinPolicy.joinOne
    )
    if one:
        groups = [group for alternative in alternatives for group in alternative]
    else:
        groups = [frozenset()]
        for alternative in alternatives:
            groups = [done | group for done in groups for group in alternative]
    # A group that waits for all another waits for and more adds nothing to the OR: the
    # export leaves it out (`export.triggers.activation`), and so does the expectation.
    groups = [g for g in set(groups) if not any(other < g for other in groups)]
    return sorted(groups, key=sorted)

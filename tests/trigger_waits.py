"""What a node's trigger must wait for, from the SceML graph alone (tests/export)."""

from __future__ import annotations

import scemlmodel as scm
from sceml.export.names import sanitize
from sceml.model import graph

ROOT = "Root"

Structure = list[frozenset[str]]


def expected_groups(
    node: scm.GraphElement, inline: set[scm.GraphElement], delays: bool = False
) -> Structure:
    """What the SceML graph says `node` waits for: each predecessor by name, or, for a node the
    export writes into its successor's trigger, what that node waits for (plus its own
    condition, named after it, unless it is a join, a port or a wait).

    With `delays`, each name carries the delay its condition has (`waited`), a wait adding its
    duration to everything it waits for, and groups that test all another group tests and more
    are left out, as the export leaves them out (the OR means the same without them); equal
    groups are counted once."""
    alternatives: list[Structure] = []
    for before in graph.predecessors(node):
        if isinstance(before, scm.RootNode):
            alternatives.append([frozenset([waited(ROOT, 0.0, delays)])])
        elif before in inline:
            passing = isinstance(before, scm.JoiningPolicy | scm.TimeElapsed)
            own = (
                frozenset() if passing else frozenset([waited(sanitize(before.name), 0.0, delays)])
            )
            groups = expected_groups(before, inline, delays)
            if delays and isinstance(before, scm.TimeElapsed):
                groups = [_later(group, float(before.duration.value)) for group in groups]
            alternatives.append([group | own for group in groups])
        else:
            alternatives.append([frozenset([waited(sanitize(before.name), 0.0, delays)])])
    one = isinstance(node, scm.JoinOneFinished) or (
        isinstance(node, scm.EndNode) and node.policy is scm.JoinPolicy.joinOne
    )
    if one:
        groups = [group for alternative in alternatives for group in alternative]
    else:
        groups = [frozenset()]
        for alternative in alternatives:
            groups = [done | group for done in groups for group in alternative]
    if delays:
        groups = [g for g in set(groups) if not any(other < g for other in groups)]
    return sorted(groups, key=sorted)


def waited(name: str, delay: float, delays: bool = True) -> str:
    """A waited-for name, with its condition's delay when delays are compared."""
    return f"{name}@{round(delay, 9):g}" if delays else name


def _later(group: frozenset[str], seconds: float) -> frozenset[str]:
    shifted = set()
    for member in group:
        name, delay = member.rsplit("@", 1)
        shifted.add(waited(name, float(delay) + seconds))
    return frozenset(shifted)

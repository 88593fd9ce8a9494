"""Shared helpers for module tests: a name-free canonical form of a scenario's behaviour."""

from __future__ import annotations

import hashlib
from collections import Counter
from collections.abc import Callable

import pytest
from pyecore.ecore import EAttribute, EObject

import scemlmodel as scm
from sceml.model.graph import predecessors


def _content(obj: EObject) -> str:
    parts = []
    for feature in obj.eClass.eAllStructuralFeatures():
        # The map path is relative to the file it is saved in (io.save rebases it), so it is a
        # location, not behaviour; tests/core/test_io.py checks that it still reaches the map.
        if feature.name in ("name", "map") or feature.derived or feature.transient:
            continue
        held = obj.eGet(feature)
        items = list(held) if feature.many else [held]
        items = [item for item in items if item is not None]
        if isinstance(feature, EAttribute):
            texts = [str(getattr(item, "name", item)) for item in items]
        elif feature.containment:
            texts = [f"{item.eClass.name}({_content(item)})" for item in items]
        else:
            texts = [str(item.name) for item in items]  # actors and definitions, by name
        parts.append(f"{feature.name}={'|'.join(texts)}")
    return ";".join(parts)


def canonical_form(graph: scm.Graph) -> Counter[str]:
    """Each node as kind + content (actors, parameters) + the keys of its predecessors, names
    left out; two graphs with equal forms behave the same (SPEC §3)."""
    keys: dict[EObject, str] = {}

    def key(node: EObject) -> str:
        if node not in keys:
            before = sorted(key(p) for p in predecessors(node))
            text = f"{node.eClass.name}[{_content(node)}]<-({','.join(before)})"
            keys[node] = hashlib.sha256(text.encode()).hexdigest()
        return keys[node]

    return Counter(key(node) for node in graph.nodes)


@pytest.fixture
def canonical() -> Callable[[scm.Graph], Counter[str]]:
    """The canonical form function."""
    return canonical_form

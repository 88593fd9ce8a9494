"""A plain summary of a scenario or library: level, actors, nodes and modules."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from . import catalog
from .graph import actors, root_node, scenario_level


@dataclass
class ActorSummary:
    """One actor: name, kind and whether it is the ego."""

    name: str
    kind: str
    ego: bool


@dataclass
class UseSummary:
    """One module use: its name, the definition it refers to and its role bindings."""

    name: str
    definition: str
    source: str
    bindings: dict[str, str]


@dataclass
class Summary:
    """What `sceml info` reports."""

    kind: str
    name: str
    level: str | None = None
    map: str | None = None
    actors: list[ActorSummary] = field(default_factory=list)
    node_counts: dict[str, int] = field(default_factory=dict)
    flows: int = 0
    uses: list[UseSummary] = field(default_factory=list)
    modules: list[str] = field(default_factory=list)


def _definition_label(use: scm.ModuleUse) -> tuple[str, str]:
    definition = use.definition
    if definition is None:
        return "(none)", ""
    if isinstance(definition, EProxy):
        href = definition._proxy_path
        try:
            definition.force_resolve()
        except Exception:
            return f"(unresolved: {href})", href
        if not isinstance(definition, scm.ModuleDefinition):  # `#//`: the file's own root
            return f"(not a module definition: {href})", href.split("#")[0]
        return str(definition.name), href.split("#")[0]
    resource = definition.eResource
    return str(definition.name), resource.uri.plain if resource is not None else ""


def _count_nodes(nodes: Iterable[EObject]) -> dict[str, int]:
    counts: Counter[str] = Counter()
    for node in nodes:
        counts[catalog.category(node) or node.eClass.name] += 1
    return dict(sorted(counts.items()))


def summarize(root: scm.Scenario | scm.Library) -> Summary:
    """Summarise a scenario or library."""
    if isinstance(root, scm.Library):
        return Summary(
            kind="library",
            name=str(root.name or ""),
            modules=[str(module.name) for module in root.modules],
            node_counts=_count_nodes([n for m in root.modules for n in m.nodes]),
            flows=sum(len(m.flows) for m in root.modules),
        )
    rootnode = root_node(root)
    summary = Summary(
        kind="scenario",
        name=str(rootnode.scenarioName or "") if rootnode else "",
        level=scenario_level(root),
        map=rootnode.map if rootnode else None,
        node_counts=_count_nodes(list(root.nodes)),
        flows=len(root.flows),
    )
    summary.actors = [
        ActorSummary(str(actor.name), actor.eClass.name, bool(actor.isEgo))
        for actor in actors(root)
    ]
    for use in root.nodes:
        if isinstance(use, scm.ModuleUse):
            definition, source = _definition_label(use)
            bindings = {
                str(b.role): str(b.actor.name) if b.actor is not None else "?" for b in use.bindings
            }
            summary.uses.append(UseSummary(str(use.name), definition, source, bindings))
    return summary

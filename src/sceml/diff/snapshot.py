"""A scenario read as names and values: what a diff compares and a merge joins, never XMI positions.

Every actor and graph node becomes an `Element`: its kind, its name, and a flat dict of *leaves*
keyed by a readable path inside it (`destination.x`, `bindings[crosser]`, `environment.cloudState`).
A leaf is a hashable value: a number, a string, an enum literal, an actor's name, or a parameter
value as a tuple (`("value", 8.0)`, `("range", 5.0, 10.0, 1.0)`), so a parameter that changes
from a value to a range is one change of one leaf. Flows are pairs of node names. Diagram
positions are kept apart (`layout`): they never change what a scenario means.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from pyecore.ecore import EEnumLiteral, EObject, EProxy

import scemlmodel as scm

from .. import catalog
from ..traversal import attributes, containments, cross_references, stored

#: A leaf value: hashable, comparable, and readable in a report.
Leaf = Any

#: Keyed lists: the attribute that names an item, so `bindings[crosser]` survives reordering.
_ITEM_KEYS = {"bindings": "role", "overrides": "parameter"}


@dataclass
class Element:
    """One actor or graph node: kind, name, leaves by path, units of the parameter leaves."""

    kind: str
    name: str
    obj: EObject
    leaves: dict[str, Leaf] = field(default_factory=dict)
    units: dict[str, str] = field(default_factory=dict)
    layout: tuple[float, float] | None = None


@dataclass
class Snapshot:
    """A scenario as elements by name and flows as (source name, target name) pairs."""

    actors: dict[str, Element]
    nodes: dict[str, Element]
    flows: list[tuple[str, str]]
    root: scm.Scenario


def snapshot(scenario: scm.Scenario) -> Snapshot:
    """Read a scenario into names and leaves."""
    actors: dict[str, Element] = {}
    nodes: dict[str, Element] = {}
    for node in scenario.nodes:
        element = _element(node)
        nodes[_unique(element.name, nodes)] = element
        if isinstance(node, scm.RootNode):
            for actor in node.actors:
                read = _element(actor)
                actors[_unique(read.name, actors)] = read
    names = {element.obj: name for name, element in nodes.items()}
    flows = [
        (names[flow.source], names[flow.target])
        for flow in scenario.flows
        if flow.source in names and flow.target in names
    ]
    return Snapshot(actors=actors, nodes=nodes, flows=flows, root=scenario)


def _unique(name: str, taken: dict[str, Element]) -> str:
    """Names are unique in a valid scenario; a broken one still compares (`X`, `X#2`)."""
    if name not in taken:
        return name
    count = 2
    while f"{name}#{count}" in taken:
        count += 1
    return f"{name}#{count}"


def _element(obj: EObject) -> Element:
    name = str(obj.name) if getattr(obj, "name", None) else f"({obj.eClass.name})"
    element = Element(kind=obj.eClass.name, name=name, obj=obj)
    position = stored(obj, "diagramPosition") if "diagramPosition" in obj.__dict__ else None
    if isinstance(position, scm.DiagramPosition):
        element.layout = (_number(position.x), _number(position.y))
    _read(obj, "", element, top=True)
    return element


def _read(obj: EObject, prefix: str, element: Element, *, top: bool = False) -> None:
    """Add the leaves of `obj`'s features under `prefix`."""
    eclass = obj.eClass
    for attribute in attributes(eclass):
        if top and attribute.name == "name":
            continue
        # eGet, not the stored holder: an unset attribute reads as its default, as it does once
        # saved (files are written with their defaults) and read back.
        held = obj.eGet(attribute)
        if held is not None:
            element.leaves[prefix + attribute.name] = _plain(held)
    for reference in cross_references(eclass):
        held = stored(obj, reference.name)
        if held is not None and not reference.many:
            element.leaves[prefix + reference.name] = reference_leaf(held)
    for containment in containments(eclass):
        name = containment.name
        if (top and name in ("diagramPosition", "actors")) or name not in obj.__dict__:
            continue
        held = stored(obj, name)
        if containment.many:
            _read_items(obj, name, list(held), prefix, element)
        elif held is not None:
            _read_child(obj, name, held, prefix + name, element)


def _read_items(
    owner: EObject, name: str, items: list[EObject], prefix: str, element: Element
) -> None:
    key = _ITEM_KEYS.get(name)
    for index, item in enumerate(items):
        label = str(item.eGet(key)) if key else str(index)
        path = f"{prefix}{name}[{label}]"
        if isinstance(item, scm.RoleBinding):
            element.leaves[path] = reference_leaf(item.actor)
        elif isinstance(item, scm.ParameterOverride):
            _read_child(item, "value", item.value, path, element, with_unit=False)
        else:
            _read_child(owner, name, item, path, element)


def _read_child(
    owner: EObject,
    name: str,
    child: EObject | None,
    path: str,
    element: Element,
    *,
    with_unit: bool = True,
) -> None:
    if child is None:
        return
    if isinstance(child, scm.ParameterValue):
        element.leaves[path] = parameter_leaf(child)
        unit = _unit(owner, name) if with_unit else ""
        if unit:
            element.units[path] = unit
        return
    # A contained object (a position, the environment) is a leaf of its own kind, then its parts.
    element.leaves[path] = ("object", child.eClass.name)
    _read(child, path + ".", element)


def _unit(owner: EObject, name: str) -> str:
    try:
        return catalog.parameter(owner, name).unit
    except Exception:  # a feature the catalog does not describe has no unit to show
        return ""


def _number(value: object) -> float:
    return float(value) if isinstance(value, int | float) else 0.0


def _plain(value: object) -> Leaf:
    if isinstance(value, EEnumLiteral):
        return str(value.name)
    return value


def reference_leaf(target: object) -> Leaf:
    """A reference as a leaf: an actor or role by name, a module definition by file and name.

    A definition is named by its reference as written (file name and fragment), never loaded: a
    version git hands over in a temporary folder cannot reach its library, and must still read
    the same as the file in the work tree.
    """
    if target is None:
        return None
    if isinstance(target, EProxy):
        href = str(target._proxy_path)
        file, _, fragment = href.partition("#")
        return ("module", file.rsplit("/", 1)[-1], fragment)
    if isinstance(target, scm.ModuleDefinition):
        resource = target.eResource
        file = resource.uri.normalize().rsplit("/", 1)[-1] if resource is not None else ""
        return ("module", file, str(target.name))
    return ("actor", str(getattr(target, "name", "")))


def parameter_leaf(value: scm.ParameterValue) -> Leaf:
    """A parameter value as a tuple: its type word, then its numbers."""
    if isinstance(value, scm.Value):
        return ("value", value.value)
    if isinstance(value, scm.Range):
        return ("range", value.min, value.max, value.step)
    if isinstance(value, scm.UniformDistribution):
        return ("uniform", value.min, value.max)
    if isinstance(value, scm.NormalDistribution):
        return ("normal", value.mean, value.standardDeviation, value.lowerBound, value.upperBound)
    if isinstance(value, scm.DiscreteDistribution):
        return ("discrete", tuple((o.value, o.weight) for o in value.options))
    if isinstance(value, scm.ParameterRef):
        return ("ref", str(value.parameter.name) if value.parameter is not None else "?")
    return ("object", value.eClass.name)

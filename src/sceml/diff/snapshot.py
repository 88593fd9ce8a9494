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
from functools import cache
from typing import Any

from pyecore.ecore import EClass, EEnumLiteral, EObject, EProxy

import scemlmodel as scm

from ..model import catalog
from ..model.traversal import attributes, containments, cross_references, stored

#: A leaf value: hashable, comparable, and readable in a report.
Leaf = Any

#: Keyed lists: the attribute that names an item, so `bindings[crosser]` survives reordering.
ITEM_KEYS = {"bindings": "role", "overrides": "parameter"}


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
    ends = ((stored(flow, "source"), stored(flow, "target")) for flow in scenario.flows)
    flows = [(names[s], names[t]) for s, t in ends if s in names and t in names]
    return Snapshot(actors=actors, nodes=nodes, flows=flows, root=scenario)


def _unique(name: str, taken: dict[str, Element]) -> str:
    """Names are unique in a valid scenario; a broken one still compares (`X`, `X#2`)."""
    if name not in taken:
        return name
    count = 2
    while f"{name}#{count}" in taken:
        count += 1
    return f"{name}#{count}"


@dataclass(frozen=True)
class _Shape:
    """A metaclass's features as plain names, read once: each access to a pyecore feature's own
    attributes (`name`, `many`) goes through a descriptor, and a snapshot reads them per object."""

    kind: str
    attributes: tuple[tuple[str, object], ...]  # (name, default)
    references: tuple[str, ...]  # single-valued cross-references
    containments: tuple[tuple[str, bool], ...]  # (name, many)


@cache
def _shape(eclass: EClass) -> _Shape:
    return _Shape(
        kind=str(eclass.name),
        attributes=tuple((str(a.name), a.get_default_value()) for a in attributes(eclass)),
        references=tuple(str(r.name) for r in cross_references(eclass) if not r.many),
        containments=tuple((str(c.name), bool(c.many)) for c in containments(eclass)),
    )


def _element(obj: EObject) -> Element:
    shape = _shape(obj.eClass)
    given = stored(obj, "name") if any(n == "name" for n, _ in shape.attributes) else None
    name = str(given) if given else f"({shape.kind})"
    element = Element(kind=shape.kind, name=name, obj=obj)
    position = stored(obj, "diagramPosition")
    if isinstance(position, scm.DiagramPosition):
        element.layout = (_number(stored(position, "x")), _number(stored(position, "y")))
    _read(obj, "", element, top=True)
    return element


def _read(obj: EObject, prefix: str, element: Element, *, top: bool = False) -> None:
    """Add the leaves of `obj`'s features under `prefix`."""
    shape = _shape(obj.eClass)
    leaves = element.leaves
    for name, default in shape.attributes:
        if top and name == "name":
            continue
        # An unset attribute reads as its default, as it does once saved (files are written
        # with their defaults) and read back.
        held = stored(obj, name)
        if held is None:
            held = default
        if held is not None:
            leaves[prefix + name] = _plain(held)
    for name in shape.references:
        held = stored(obj, name)
        if held is not None:
            leaves[prefix + name] = reference_leaf(held)
    for name, many in shape.containments:
        if top and name in ("diagramPosition", "actors"):
            continue
        held = stored(obj, name)
        if held is None:
            continue
        if many:
            _read_items(obj, name, list(held), prefix, element)
        else:
            _read_child(obj, name, held, prefix + name, element)


def _read_items(
    owner: EObject, name: str, items: list[EObject], prefix: str, element: Element
) -> None:
    key = ITEM_KEYS.get(name)
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
    return ("actor", str(stored(target, "name") or "") if isinstance(target, EObject) else "")


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

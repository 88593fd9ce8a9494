"""Where a model element is: its line in the file read, its readable path and its URI fragment."""

from __future__ import annotations

from lxml import etree
from pyecore.ecore import EObject
from pyecore.resources.xmi import XMIResource


def line_in(resource: XMIResource, obj: EObject) -> int | None:
    """The line of the element `obj` was read from in `resource`'s file, if known."""
    element = _element_of(resource, obj)
    return element.sourceline if element is not None else None


def _containment_steps(obj: EObject) -> list[tuple[str, int]]:
    steps: list[tuple[str, int]] = []
    while obj.eContainer() is not None and obj.eContainmentFeature() is not None:
        feature = obj.eContainmentFeature()
        container = obj.eContainer()
        index = container.eGet(feature).index(obj) if feature.many else 0
        steps.append((feature.name, index))
        obj = container
    return list(reversed(steps))


def _element_of(resource: XMIResource, obj: EObject) -> etree._Element | None:
    """The XML element `obj` was read from, found by its containment steps in the parsed file.

    Each element's children are grouped by tag once per file (kept on the resource), so that
    locating thousands of diagnostics in a large file costs a dictionary lookup per step rather
    than a scan of every sibling.
    """
    tree = getattr(resource, "sceml_tree", None)
    if tree is None:
        return None
    groups: dict[etree._Element, dict[str, list[etree._Element]]]
    groups = resource.__dict__.setdefault("sceml_children", {})
    element = tree.getroot()
    for name, index in _containment_steps(obj):
        by_tag = groups.get(element)
        if by_tag is None:
            by_tag = groups[element] = {}
            for child in element:
                by_tag.setdefault(child.tag, []).append(child)
        children = by_tag.get(name, ())
        if index >= len(children):
            return None
        element = children[index]
    return element


def model_path(obj: EObject) -> str:
    """A readable path of element names from the document root, e.g. `CrossingManeuver/Accelerate_1`."""
    names = []
    current: EObject | None = obj
    while current is not None:
        label = _label(current)
        if label:
            names.append(label)
        current = current.eContainer()
    return "/".join(reversed(names))


def _label(obj: EObject) -> str:
    name = getattr(obj, "name", None)
    if name:
        return str(name)
    feature = obj.eContainmentFeature()
    if feature is None:
        return ""
    if feature.many:
        return f"{feature.name}[{obj.eContainer().eGet(feature).index(obj)}]"
    return str(feature.name)


def uri_fragment(obj: EObject) -> str:
    """The EMF URI fragment of an object inside its file, e.g. `//@nodes.3/@targetSpeed`."""
    return str(obj.eURIFragment())

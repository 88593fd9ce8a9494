"""A parsed XMI file seen through one metamodel release: the class of every element.

Migration rewrites the parsed tree before pyecore decodes it, so every element keeps the line it
was read from and diagnostics of a migrated file still point into the file on disk.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, field

from lxml import etree

from .ecore import Metamodel

XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"
_STEP = re.compile(r"@(\w+)(?:\.(\d+))?$")


@dataclass
class TreeModel:
    """The model root of a parsed file and, for each element, its class in `metamodel`.

    Classes are those of the release the file is being migrated from: operations name classes
    and features as they were in that release, whatever the operations before them renamed.
    """

    root: etree._Element
    metamodel: Metamodel
    classes: dict[etree._Element, str] = field(default_factory=dict)

    @classmethod
    def of(cls, root: etree._Element, metamodel: Metamodel) -> TreeModel:
        model = cls(root, metamodel)
        model.classes[root] = etree.QName(root).localname
        pending = [root]
        while pending:
            parent = pending.pop()
            parent_class = model.classes[parent]
            for child in parent.iterchildren(etree.Element):
                feature = metamodel.feature(parent_class, child.tag) if parent_class else None
                named = child.get(XSI_TYPE)
                if named is not None:
                    model.classes[child] = named.rpartition(":")[2]
                elif feature is not None:
                    model.classes[child] = feature.type
                else:
                    continue  # not a feature of this release: the loader reports it later
                if feature is not None and feature.containment:
                    pending.append(child)
        return model

    def instances(self, cls: str, *, exact: bool = False) -> list[etree._Element]:
        """Elements of class `cls` (and, unless `exact`, of its subclasses), in document order."""
        found = []
        for element in self.root.iter(etree.Element):
            name = self.classes.get(element)
            if name is None:
                continue
            if name == cls if exact else self.metamodel.is_kind_of(name, cls):
                found.append(element)
        return found

    def set_class(self, element: etree._Element, cls: str) -> None:
        """Give `element` another class in the file (its xsi:type, or the root's tag)."""
        if element is self.root:
            element.tag = etree.QName(etree.QName(element).namespace, cls).text
            return
        prefix = (element.get(XSI_TYPE) or "").rpartition(":")[0] or self.prefix
        element.set(XSI_TYPE, f"{prefix}:{cls}")

    @property
    def prefix(self) -> str:
        namespace = etree.QName(self.root).namespace
        return next(
            (p for p, uri in self.root.nsmap.items() if p and uri == namespace),
            self.metamodel.prefix,
        )

    def references(self) -> Iterator[tuple[etree._Element, str]]:
        """(element, attribute) of every reference this file writes as in-file path fragments."""
        for element, cls in list(self.classes.items()):
            if element.get("href", "").startswith("#//"):
                yield element, "href"
            features = self.metamodel.features(cls)
            for name in element.attrib:
                feature = features.get(name)
                if feature is not None and feature.kind == "reference" and not feature.containment:
                    yield element, name


def path(element: etree._Element) -> str:
    """A readable path of names from the model root, e.g. `UIS2/Accelerate_1/targetSpeed`."""
    parts = []
    current: etree._Element | None = element
    while current is not None:
        parent = current.getparent()
        name = current.get("name")
        if name:
            parts.append(name)
        elif parent is not None:
            same = [c for c in parent if c.tag == current.tag]
            parts.append(current.tag if len(same) == 1 else f"{current.tag}[{same.index(current)}]")
        current = parent
    return "/".join(reversed(parts))


class Fragments:
    """Keeps in-file references pointing at the same elements while operations reshape the tree.

    EMF writes a reference as a path of containment steps (`//@nodes.3/@actors.0`): renaming a
    containment feature, moving or deleting an element changes the paths of others. Each
    reference is resolved to its elements before an operation and written again from them after.
    """

    def __init__(self, model: TreeModel) -> None:
        self.model = model
        self.indexed: dict[etree._Element, bool] = {}
        self.targets: list[tuple[etree._Element, str, str, list[etree._Element | str]]] = []
        for element, attribute in model.references():
            value = element.get(attribute, "")
            prefix = "#" if attribute == "href" else ""
            resolved: list[etree._Element | str] = []
            for word in (value[1:] if prefix else value).split():
                target = self._resolve(word)
                resolved.append(target if target is not None else word)
            self.targets.append((element, attribute, prefix, resolved))

    def _resolve(self, fragment: str) -> etree._Element | None:
        if not fragment.startswith("//"):
            return None  # an ID (a module definition's name): survives reshaping
        current = self.model.root
        for step in fragment[2:].split("/") if fragment != "//" else []:
            found = _STEP.match(step)
            if found is None:
                return None
            tag, index = found.group(1), found.group(2)
            children = [c for c in current if c.tag == tag]
            position = int(index) if index is not None else 0
            if position >= len(children):
                return None
            current = children[position]
            self.indexed[current] = index is not None
        return current

    def restore(self) -> list[tuple[etree._Element, str]]:
        """Write every reference again; returns (holder, fragment) of targets that are gone."""
        lost = []
        for element, attribute, prefix, resolved in self.targets:
            if not self._attached(element) or attribute not in element.attrib:
                continue  # the holder was deleted, or the operation renamed the reference
            words = []
            for target in resolved:
                if isinstance(target, str):
                    words.append(target)
                elif self._attached(target):
                    words.append(self._fragment(target))
                else:
                    lost.append((element, attribute))
            if words:
                element.set(attribute, prefix + " ".join(words))
            else:
                del element.attrib[attribute]
        return lost

    def _attached(self, element: etree._Element) -> bool:
        # An element removed from its parent still belongs to the same lxml document, so its
        # tree's root says nothing; its ancestors do.
        root = self.model.root
        return element is root or any(a is root for a in element.iterancestors())

    def _fragment(self, element: etree._Element) -> str:
        steps = []
        current = element
        while current is not self.model.root:
            parent = current.getparent()
            assert parent is not None
            same = [c for c in parent if c.tag == current.tag]
            many = self.indexed.get(current, len(same) > 1)
            steps.append(f"@{current.tag}.{same.index(current)}" if many else f"@{current.tag}")
            current = parent
        return "//" + "/".join(reversed(steps))

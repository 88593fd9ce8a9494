"""Decode a parsed, checked SceML XMI tree into model objects directly, or decline the file.

pyecore's decoder (`XMIResource._decode_eobject` and `_decode_ereferences`) builds each object
through its generic setters; this reader walks the same lxml tree and writes the same end state
with `sceml.model.fastobjects`: the same objects in the same order, attribute values converted by the
same `from_string`, references resolved the same way (cross-file ones as lazy `EProxy`s), the same
`uuid_dict`, `_isset` order, containers, opposite ends and `_inverse_rels`.

It reads only what SceML and EMF write: typed elements for containments, attributes for values
and same-file references (`//@nodes.3/@actors.0` paths or iD values), `xsi:nil` elements for
features set to nothing, `href` elements for references into other files. On anything else, and
on anything wrong (an unknown feature or type, a value `check_literal` refuses, a duplicate iD, a
reference that does not resolve, a class that does not fit its feature), `decode` leaves the
resource untouched and returns False, and the caller runs pyecore's decoder, which reports the
problem with its usual message and line.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any

from lxml import etree
from pyecore.ecore import EAttribute, EObject, EProxy, EString
from pyecore.valuecontainer import EcoreUtils

import scemlmodel as scm

from . import lightobjects
from .fastobjects import (
    Slot,
    add_child,
    attribute_supported,
    child_supported,
    new,
    none_supported,
    reference_supported,
    set_reference,
    set_value,
    slot,
)

XSI_TYPE = "{http://www.w3.org/2001/XMLSchema-instance}type"
XSI_NIL = "{http://www.w3.org/2001/XMLSchema-instance}nil"  # pyecore's test, whatever the prefixes

# An iD value (ModuleDefinition.name) used as a reference: no path, URI or separator in it.
_ID = re.compile(r"[^\s/#]+")

CheckLiteral = Callable[[EAttribute, str], None]
_UNREAD = object()  # a text not converted yet


class _Declined(Exception):
    """The file holds something this reader leaves to pyecore's decoder."""


class _Plan:
    """How to read the elements of one class: its features by the name a file gives them."""

    __slots__ = ("attributes", "children", "cls", "fits", "nullable", "references")

    def __init__(self, cls: type[EObject]) -> None:
        self.cls = cls
        # name -> (slot, its values read so far by text or None for strings kept as read,
        # whether it is an iD)
        self.attributes: dict[str, tuple[Slot, dict[str, object] | None, bool]] = {}
        self.references: dict[str, Slot] = {}  # attribute form and href elements
        self.children: dict[str, Slot] = {}  # containments, by element tag
        self.nullable: dict[str, Slot] = {}  # single-valued features, for xsi:nil elements
        self.fits: dict[Slot, bool] = {}  # whether `cls` may be held by a containment
        found: dict[str, Any] = {}
        # pyecore takes the first feature of that name, own features before inherited ones.
        for feature in cls.eClass._eAllStructuralFeatures_gen():
            found.setdefault(feature.name, feature)
        for name, feature in found.items():
            if none_supported(feature):
                self.nullable[name] = slot(feature)
            if attribute_supported(feature):
                plain = feature._eType is EString  # no check, and from_string keeps the text
                self.attributes[name] = (slot(feature), None if plain else {}, bool(feature.iD))
            elif child_supported(feature):
                self.children[name] = slot(feature)
            elif reference_supported(feature) and slot(feature).kind is not None:
                self.references[name] = slot(feature)

    def fit(self, held_by: Slot) -> bool:
        """Whether an object of this class may be held by a feature (pyecore's type check)."""
        fits = self.fits.get(held_by)
        if fits is None:
            kind = held_by.kind
            fits = self.fits[held_by] = kind is not None and issubclass(self.cls, kind)
        return fits


def _concrete(cls: Any) -> bool:
    """Whether `cls` is a generated class pyecore can instantiate."""
    if not isinstance(cls, type) or not issubclass(cls, EObject):
        return False
    eclass: Any = cls.eClass  # type: ignore[attr-defined]
    return not eclass.abstract


def decode(
    resource: Any, xmlroot: etree._Element, check_literal: CheckLiteral, read_only: bool = False
) -> bool:
    """Build the model of `xmlroot` into `resource`; False, with nothing changed, if declined.

    `resource` is a SafeXMIResource whose prefixes and xsi/xmi keys are set up for this tree
    (as `_decode_tree` does); `check_literal` refuses attribute text (ValueError). With
    `read_only`, the objects are `sceml.model.lightobjects`' (for a load nothing will change).
    """
    if resource.contents or resource.uuid_dict or resource.xsitype != XSI_TYPE:
        return False
    reader = _Reader(resource, check_literal, read_only)
    try:
        root = reader.read(xmlroot)
    except Exception:  # _Declined, or a file this reader was not written for
        # pyecore's decoder is the reference for every file, so it also gets any file that
        # surprises this one; the objects made so far are new and nothing refers to them.
        # (tests/core/test_fast_reader.py checks that every file SceML writes is read here.)
        reader.discard()
        return False
    reader.commit(root, xmlroot)
    return True


class _Reader:
    """One decoding of one tree; nothing reaches the resource before `commit`."""

    def __init__(self, resource: Any, check_literal: CheckLiteral, read_only: bool) -> None:
        # The same writes, into pyecore's full objects or into read-only ones.
        self.new: Callable[[type[EObject]], EObject] = lightobjects.new if read_only else new
        self.set_value = lightobjects.set_value if read_only else set_value
        self.add_child = lightobjects.add_child if read_only else add_child
        self.set_reference = lightobjects.set_reference if read_only else set_reference
        self.resource = resource
        self.check_literal = check_literal
        self.xmiid: str = resource.xmiid
        self.plans: dict[object, _Plan] = {}  # by xsi:type text, class or (untyped) feature
        self.created: list[EObject] = []
        self.lines: list[int | None] = []  # the line of each object in `created`
        # Same-file references, set once every object exists: (holder, feature, text).
        self.later: list[tuple[EObject, Slot, str]] = []
        self.uuids: dict[str, EObject] = {}
        self.ids: dict[tuple[str, str], tuple[EObject, int | None]] = {}
        self.use_uuid = False

    # -- the tree ---------------------------------------------------------------------------

    def read(self, xmlroot: etree._Element) -> EObject:
        """Decode the whole tree and resolve its same-file references; returns the root object."""
        root, plan = self.start(xmlroot)
        self._walk(xmlroot, root, plan)
        self._resolve_all(root)
        return root

    def start(self, xmlroot: etree._Element) -> tuple[EObject, _Plan]:
        """The root object, with the root element's attributes; then `walk` its children."""
        if not isinstance(xmlroot.tag, str):
            raise _Declined
        # An xmi:XMI wrapper is declined here too: its namespace names no metamodel.
        qname = etree.QName(xmlroot)
        plan = self._plan_of(self._metaclass(qname.namespace, qname.localname))
        root = self.new(plan.cls)
        self.created.append(root)
        self.lines.append(xmlroot.sourceline)
        self.use_uuid = xmlroot.get(self.xmiid) is not None
        for key, text in xmlroot.items():
            if key == self.xmiid:
                root._internal_id = text
                self.uuids[text] = root
            elif key[0] != "{":
                self._root_attribute(root, plan, key, text, xmlroot)
        return root, plan

    def walk(self, elements: Iterable[etree._Element], root: EObject, plan: _Plan) -> None:
        """Decode `elements`, children of the root element (in document order, once each)."""
        self._walk(elements, root, plan)

    def finish(self, root: EObject) -> None:
        """Resolve the same-file references, once every element was walked."""
        self._resolve_all(root)

    def _root_attribute(
        self, root: EObject, plan: _Plan, key: str, text: str, element: etree._Element
    ) -> None:
        attribute = plan.attributes.get(key)
        if attribute is not None:
            feature, values, is_id = attribute
            value = text if values is None else self._value(feature, values, text)
            self.set_value(root, feature, value)
            if is_id:
                self._register_id(root, text, element)
                self.uuids[text] = root
        elif key in plan.references:
            self.later.append((root, plan.references[key], text))
        elif root.eClass.findEStructuralFeature(key) is not None:
            raise _Declined  # a feature of a shape pyecore decodes its own way
        # pyecore ignores root attributes that name no feature.

    def _walk(self, element: Iterable[etree._Element], parent: EObject, parent_plan: _Plan) -> None:
        # Depth is bounded: libxml2 refuses documents nested deeper than 256 levels.
        children = parent_plan.children
        plans = self.plans
        later = self.later
        uuids = self.uuids
        created = self.created
        lines = self.lines
        value_of = self._value
        xmiid = self.xmiid
        new, set_value, add_child = self.new, self.set_value, self.add_child
        for child in element:
            held_by = children.get(child.tag)
            if held_by is None:
                self._other(child, parent, parent_plan)
                continue
            items = child.items()
            # pyecore and EMF write xsi:type first; looking at it there saves a lookup.
            kind = items[0][1] if items and items[0][0] == XSI_TYPE else child.get(XSI_TYPE)
            if kind is None and child.get(XSI_NIL) is not None:
                self._nil(child, parent, parent_plan)
                continue
            plan = plans.get(kind if kind is not None else held_by)
            if plan is None:
                plan = self._plan_for(kind, held_by)
            if not plan.fits.get(held_by) and not plan.fit(held_by):
                raise _Declined
            obj = new(plan.cls)
            created.append(obj)
            lines.append(child.sourceline)
            attributes = plan.attributes
            for key, text in items:
                attribute = attributes.get(key)
                if attribute is not None:
                    feature, values, is_id = attribute
                    if values is None:
                        value: object = text
                    else:
                        value = values.get(text, _UNREAD)
                        if value is _UNREAD:
                            value = value_of(feature, values, text)
                    set_value(obj, feature, value)
                    if is_id:
                        self._register_id(obj, text, child)
                        uuids[text] = obj
                elif key == XSI_TYPE:
                    continue
                elif key in plan.references:
                    later.append((obj, plan.references[key], text))
                elif key == xmiid:
                    obj._internal_id = text
                    uuids[text] = obj
                else:
                    raise _Declined
            if not held_by.many and held_by.name in parent.__dict__:
                raise _Declined  # set twice: pyecore would replace the first
            add_child(parent, held_by, obj)
            if len(child):
                self._walk(child, obj, plan)

    def _other(self, element: etree._Element, parent: EObject, plan: _Plan) -> None:
        # An element that is not a contained object: a value written as nil, or a reference
        # into another file. pyecore checks for nil first.
        if element.get(XSI_NIL) is not None:
            self._nil(element, parent, plan)
        else:
            self._href(element, parent, plan)

    def _nil(self, element: etree._Element, parent: EObject, plan: _Plan) -> None:
        # `<description xsi:nil="true"/>`: SceML writes a feature set to nothing this way. pyecore
        # sets it to None and reads nothing else of the element (nor its children).
        feature = plan.nullable.get(element.tag)
        if feature is None or len(element) or element.get("href") is not None:
            raise _Declined
        if feature.name in parent.__dict__:
            raise _Declined
        self.set_value(parent, feature, None)

    def _href(self, element: etree._Element, parent: EObject, plan: _Plan) -> None:
        # `<definition href="library.xmi#Name" xsi:type="..."/>`: a reference into another file,
        # set at once (in document order) to a proxy that loads the file when first used.
        feature = plan.references.get(element.tag)
        href = element.get("href")
        if feature is None or feature.opposite is not None or not href or len(element):
            raise _Declined
        if feature.name in parent.__dict__:
            raise _Declined
        if any(key != "href" and key != XSI_TYPE for key in element.attrib):
            raise _Declined
        self.set_reference(parent, feature, EProxy(path=href, resource=self.resource))

    def _value(self, feature: Slot, values: dict[str, object], text: str) -> object:
        # The same text gives the same value: most numbers and enum literals repeat.
        try:
            return values[text]
        except KeyError:
            pass
        attribute = feature.feature
        try:
            self.check_literal(attribute, text)
        except ValueError:
            raise _Declined from None
        value = attribute._eType.from_string(text)  # may raise, for types SceML does not use
        if not EcoreUtils.isinstance(value, attribute._eType):
            raise _Declined
        values[text] = value
        return value

    def _register_id(self, obj: EObject, text: str, element: etree._Element) -> None:
        # SafeXMIResource's own record of iD values (ModuleDefinition.name), for its duplicate check.
        key = (obj.eClass.name, text)
        if key in self.ids:
            raise _Declined
        self.ids[key] = (obj, element.sourceline)

    # -- classes ----------------------------------------------------------------------------

    def _plan_for(self, kind: str | None, held_by: Slot) -> _Plan:
        if kind is None:
            cls = held_by.kind
            if not _concrete(cls):
                raise _Declined
        else:
            parts = kind.split(":")
            if len(parts) != 2 or not parts[0] or parts[0] not in self.resource.prefixes:
                raise _Declined
            cls = self._metaclass(self.resource.prefixes[parts[0]], parts[1])
        plan = self._plan_of(cls)
        self.plans[kind if kind is not None else held_by] = plan
        return plan

    def _metaclass(self, namespace: str | None, name: str) -> type[EObject]:
        try:
            package = self.resource.get_metamodel(namespace)
        except Exception:
            raise _Declined from None
        cls: Any = package.getEClassifier(name) if package is scm else None
        if not _concrete(cls):
            raise _Declined
        return cls  # type: ignore[no-any-return]

    def _plan_of(self, cls: type[EObject]) -> _Plan:
        plan = self.plans.get(cls)
        if plan is None:
            plan = self.plans[cls] = _Plan(cls)
        return plan

    # -- references -------------------------------------------------------------------------

    def _resolve_all(self, root: EObject) -> None:
        # In pyecore's order: holders in document order, each holder's attributes in order.
        found: dict[str, EObject] = {}
        resolve = self._resolve
        set_reference = self.set_reference
        for holder, feature, text in self.later:
            target = found.get(text)
            if target is None:
                target = found[text] = resolve(root, text)
            if not isinstance(target, feature.kind) or feature.name in holder.__dict__:
                raise _Declined  # of another class, or set before (by an href or nil element)
            set_reference(holder, feature, target)

    def _resolve(self, root: EObject, text: str) -> EObject:
        uuids = self.uuids
        if text.startswith("//@"):
            if self.use_uuid and text[2:] in uuids:
                return uuids[text[2:]]  # pyecore tries a path as an xmi:id first
            return self._navigate(root, text[3:].split("/@"))
        if _ID.fullmatch(text) and text in uuids:
            return uuids[text]
        raise _Declined

    def _navigate(self, root: EObject, steps: list[str]) -> EObject:
        # `//@nodes.3/@actors.0`: containments by name, with an index for many-valued ones.
        # pyecore also walks other attributes, names as indices and negative indices.
        current = root
        for step in steps:
            name, dot, index = step.partition(".")
            feature = self._plan_of(type(current)).children.get(name)
            held = current.__dict__.get(name) if feature is not None else None
            if held is None or bool(dot) != feature.many:  # type: ignore[union-attr]
                raise _Declined
            if dot:
                if not (index.isascii() and index.isdigit()):
                    raise _Declined
                position = int(index)
                if position >= len(held.items):
                    raise _Declined
                current = held.items[position]
            else:
                current = held._value
                if current is None:
                    raise _Declined
        return current

    # -- the outcome ------------------------------------------------------------------------

    def commit(self, root: EObject, xmlroot: etree._Element | None) -> None:
        """Hand the model to the resource, as pyecore's decoder leaves it (without the tree
        when it was read while parsed: its elements are gone)."""
        resource = self.resource
        root._eresource = resource
        resource.use_uuid = self.use_uuid
        resource.contents.append(root)
        resource.uuid_dict.update(self.uuids)
        resource._sceml_ids.update(self.ids)
        resource.sceml_lines = dict(zip(self.created, self.lines, strict=True))
        if xmlroot is None:
            return
        last = xmlroot
        while len(last):
            last = last[-1]
        resource._sceml_node = last  # the element pyecore's decoder visits last

    def discard(self) -> None:
        """Forget the objects made so far, so that `allInstances()` does not list them."""
        for obj in self.created:
            EObject._instances.discard(obj)
        self.created.clear()
        self.lines.clear()

"""The XSD simple type of an attribute, found from its element's path, and a schema that checks
attribute values against such types without the document around them.

    types = attribute_types("1.2")
    types.of(["OpenSCENARIO", "Storyboard", ..., "AbsoluteTargetSpeed"], "value")  # "Double"
    check = ValueCheck.of(types, ["Double", "Double"])    # None if the XSD relates values
    check.valid(["13.9", "inf"])                            # False: "inf" is no xsd:double

Why: a batch of samples differs only in some attribute values of one document. Under XSD 1.0,
when one such document is valid, another that differs from it only in attribute values is
valid exactly when each of those values is valid for its attribute's declared simple type: an
attribute's type follows from its element's declared type, which attribute values do not change
(no xsi:type is written), and the OpenSCENARIO XSDs have no identity constraints (key, keyref,
unique) and no ID or IDREF types, the only rules that relate a value to the rest of the
document. `ValueCheck.of` refuses a schema that has them. So the values alone are checked, by
libxml2 against the official XSD's own simple type definitions, in one small element: a few
microseconds instead of the whole document's 0.1 ms.

The OpenSCENARIO XSDs declare every complex type by name and every element with a `type`; a
content model nests sequence, choice, all and group references, and the only extensions are
simple contents of xsd:string. Anything else (an anonymous type, an unknown element) is
answered None, and the caller checks the whole document instead.
"""

from __future__ import annotations

import copy
import functools
from collections.abc import Iterator, Sequence

from lxml import etree

from ..files.safexml import hardened_parser
from .schema import xsd_bytes

XSD = "http://www.w3.org/2001/XMLSchema"
_X = f"{{{XSD}}}"
#: What an XSD may contain that makes a value's validity depend on the rest of the document.
_DOCUMENT_WIDE = (f"{_X}key", f"{_X}keyref", f"{_X}unique")
_DOCUMENT_WIDE_TYPES = ("ID", "IDREF", "IDREFS", "ENTITY", "ENTITIES", "NOTATION")
#: The structure of a content model that `_children` walks into.
_GROUPING = {f"{_X}sequence", f"{_X}choice", f"{_X}all", f"{_X}complexContent", f"{_X}extension"}


class AttributeTypes:
    """The named types of one XSD, to look up the type of an attribute at an element path."""

    def __init__(self, xsd: etree._Element) -> None:
        self.xsd = xsd
        self.elements = _named(xsd, "element")
        self.complex_types = _named(xsd, "complexType")
        self.simple_types = _named(xsd, "simpleType")
        self.groups = _named(xsd, "group")

    def of(self, path: Sequence[str], attribute: str) -> str | None:
        """The type name (as the XSD writes it, e.g. `Double` or `xsd:string`) of `attribute`
        on the element at `path` (tags from the root), or None if the XSD does not say."""
        if not path or path[0] not in self.elements:
            return None
        type_name = _type_of(self.elements[path[0]])
        for tag in path[1:]:
            if type_name is None:
                return None
            type_name = self._child_type(type_name, tag)
        if type_name is None or type_name not in self.complex_types:
            return None
        # The XSDs' complex types are all named and flat: every attribute under one is its own.
        for declared in self.complex_types[type_name].iter(f"{_X}attribute"):
            if declared.get("name") == attribute:
                # A fixed value is a rule of the declaration, not of the type: not checked alone.
                return None if declared.get("fixed") is not None else _type_of(declared)
        return None

    def _child_type(self, type_name: str, tag: str) -> str | None:
        complex_type = self.complex_types.get(type_name)
        if complex_type is None:
            return None
        for element in self._children(complex_type):
            if element.get("name") == tag:
                return _type_of(element)
        return None

    def _children(self, model: etree._Element) -> Iterator[etree._Element]:
        """The element declarations of a content model, through its groups."""
        for part in model:
            if part.tag == f"{_X}element":
                yield part
            elif part.tag == f"{_X}group" and part.get("ref") in self.groups:
                yield from self._children(self.groups[part.get("ref", "")])
            elif part.tag in _GROUPING:
                yield from self._children(part)


def _type_of(declaration: etree._Element) -> str | None:
    """The `type` a declaration names; None for an anonymous type, which the walk does not read."""
    named = declaration.get("type")
    return named if isinstance(named, str) else None


def _named(xsd: etree._Element, kind: str) -> dict[str, etree._Element]:
    return {node.get("name", ""): node for node in xsd.iterchildren(f"{_X}{kind}")}


@functools.cache
def attribute_types(version: str) -> AttributeTypes:
    """The attribute types of the OpenSCENARIO XSD of `version`, read once per process."""
    return AttributeTypes(etree.fromstring(xsd_bytes(version), hardened_parser()))


class ValueCheck:
    """Attribute values checked against their XSD simple types, all in one small element."""

    def __init__(self, schema: etree.XMLSchema, count: int) -> None:
        self.schema = schema
        self.element = etree.Element("values")
        self.names = [f"v{k}" for k in range(count)]

    @classmethod
    def of(cls, schema: AttributeTypes, types: Sequence[str]) -> ValueCheck | None:
        """A check of values of `types` (names from `schema.of`); None when that schema relates
        values to the rest of a document."""
        xsd = schema.xsd
        if any(True for tag in _DOCUMENT_WIDE for _ in xsd.iter(tag)) or _names_id_types(xsd):
            return None
        try:
            return cls(etree.XMLSchema(_values_schema(xsd, types)), len(types))
        except etree.XMLSchemaParseError:  # a type the XSD's simple types do not define
            return None

    def valid(self, values: Sequence[str]) -> bool:
        """Whether every value is valid for its type (values in the order of the types)."""
        element = self.element
        for name, value in zip(self.names, values, strict=True):
            element.set(name, value)
        return bool(self.schema.validate(element))


def _names_id_types(xsd: etree._Element) -> bool:
    for node in xsd.iter():
        for key in ("type", "base", "memberTypes", "itemType"):
            for name in (node.get(key) or "").split():
                if name.rpartition(":")[2] in _DOCUMENT_WIDE_TYPES:
                    return True
    return False


def _values_schema(xsd: etree._Element, types: Sequence[str]) -> etree._Element:
    """A schema with every simple type of `xsd` and one element, `values`, whose attribute
    v<k> is required and of types[k]."""
    schema = etree.Element(f"{_X}schema", nsmap=xsd.nsmap)
    for simple in xsd.iterchildren(f"{_X}simpleType"):
        schema.append(copy.deepcopy(simple))
    element = etree.SubElement(schema, f"{_X}element", name="values")
    complex_type = etree.SubElement(element, f"{_X}complexType")
    for k, type_name in enumerate(types):
        etree.SubElement(
            complex_type, f"{_X}attribute", name=f"v{k}", type=type_name, use="required"
        )
    return schema

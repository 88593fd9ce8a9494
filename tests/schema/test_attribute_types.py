"""Attribute types looked up in the official XSDs, and the values-only check built on them."""

from __future__ import annotations

import pytest
from lxml import etree

from sceml.xosc.attribute_types import AttributeTypes, ValueCheck, attribute_types

SPEED = [
    "OpenSCENARIO", "Storyboard", "Story", "Act", "ManeuverGroup", "Maneuver", "Event", "Action",
    "PrivateAction", "LongitudinalAction", "SpeedAction", "SpeedActionTarget",
    "AbsoluteTargetSpeed",
]  # fmt: skip


@pytest.mark.parametrize("version", ["1.0", "1.1", "1.2", "1.3"])
def test_types_are_those_the_xsd_declares(version: str) -> None:
    types = attribute_types(version)
    # Read off the XSDs by hand: AbsoluteTargetSpeed's value, FileHeader's revMajor, Private's
    # entityRef, and a StartTrigger (an element whose type, Trigger, has another name).
    assert types.of(SPEED, "value") == "Double"
    assert types.of(["OpenSCENARIO", "FileHeader"], "revMajor") == "UnsignedShort"
    assert types.of(["OpenSCENARIO", "Storyboard", "Init", "Actions", "Private"], "entityRef") == (
        "String"
    )
    trigger = [*SPEED[:5], "Maneuver", "Event", "StartTrigger", "ConditionGroup", "Condition"]
    assert types.of(trigger, "delay") == "Double"
    assert types.of(trigger, "conditionEdge") == "ConditionEdge"


def test_what_the_xsd_does_not_declare_has_no_type() -> None:
    types = attribute_types("1.3")
    assert types.of(SPEED, "speed") is None  # no such attribute
    assert types.of([*SPEED[:-1], "Speedy"], "value") is None  # no such element
    assert types.of(["Scenario"], "name") is None  # no such root
    assert types.of([], "name") is None


def _types(body: str) -> AttributeTypes:
    xsd = f"""<xsd:schema xmlns:xsd="http://www.w3.org/2001/XMLSchema">
      <xsd:element name="R" type="R"/>
      <xsd:complexType name="R">
        <xsd:sequence><xsd:element name="A" type="A" maxOccurs="unbounded"/></xsd:sequence>
      </xsd:complexType>
      {body}
    </xsd:schema>"""
    return AttributeTypes(etree.fromstring(xsd))


def test_values_are_checked_against_their_types_facets_included() -> None:
    types = _types(
        """<xsd:complexType name="A"><xsd:attribute name="v" type="Small"/></xsd:complexType>
        <xsd:simpleType name="Small">
          <xsd:restriction base="xsd:double"><xsd:maxInclusive value="10"/></xsd:restriction>
        </xsd:simpleType>"""
    )
    assert types.of(["R", "A"], "v") == "Small"
    check = ValueCheck.of(types, ["Small", "xsd:int"])
    assert check is not None
    assert check.valid(["9.5", "3"])
    assert not check.valid(["10.5", "3"])
    assert not check.valid(["9.5", "3.5"])
    assert not check.valid(["inf", "3"])


@pytest.mark.parametrize(
    "body",
    [
        # A value that must be unique in the document, or refer to another: not checkable alone.
        """<xsd:complexType name="A"><xsd:attribute name="v" type="xsd:ID"/></xsd:complexType>""",
        """<xsd:complexType name="A"><xsd:attribute name="v" type="Ref"/></xsd:complexType>
        <xsd:simpleType name="Ref"><xsd:restriction base="xsd:IDREF"/></xsd:simpleType>""",
    ],
)
def test_a_schema_that_relates_values_to_the_document_is_refused(body: str) -> None:
    assert ValueCheck.of(_types(body), ["xsd:string"]) is None


def test_a_schema_with_identity_constraints_is_refused() -> None:
    xsd = """<xsd:schema xmlns:xsd="http://www.w3.org/2001/XMLSchema">
      <xsd:element name="R" type="R">
        <xsd:unique name="u"><xsd:selector xpath="A"/><xsd:field xpath="@v"/></xsd:unique>
      </xsd:element>
      <xsd:complexType name="R"><xsd:attribute name="v" type="xsd:string"/></xsd:complexType>
    </xsd:schema>"""
    assert ValueCheck.of(AttributeTypes(etree.fromstring(xsd)), ["xsd:string"]) is None


@pytest.mark.parametrize("version", ["1.0", "1.1", "1.2", "1.3"])
def test_the_official_xsds_allow_the_values_only_check(version: str) -> None:
    assert ValueCheck.of(attribute_types(version), ["Double"]) is not None


def test_a_fixed_attribute_or_an_unknown_type_is_not_checked_alone() -> None:
    types = _types(
        """<xsd:complexType name="A"><xsd:attribute name="v" type="xsd:double" fixed="1"/>
        <xsd:attribute name="w" type="xsd:double"/></xsd:complexType>"""
    )
    assert types.of(["R", "A"], "v") is None  # any other number would break the document
    assert types.of(["R", "A"], "w") == "xsd:double"
    assert ValueCheck.of(types, ["Nowhere"]) is None

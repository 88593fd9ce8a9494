"""Where pyecore 0.15.2 and EMF disagree: each trap shown on a scratch metamodel, and each shown
avoided by the SceML metamodel or by sceml.model."""

from __future__ import annotations

import datetime
import math
from pathlib import Path

import pytest
from lxml import etree
from pyecore.ecore import (
    EAttribute,
    EClass,
    EDate,
    EDouble,
    EInt,
    EPackage,
    EReference,
    EString,
)
from pyecore.resources import URI, ResourceSet

import scemlmodel as scm
from sceml.errors import SaveError
from sceml.model.build import ScenarioBuilder, lane
from sceml.model.saving import save

from .conftest import ECORE, Harness

METAMODEL = etree.parse(str(ECORE))


def _scratch(tmp_path: Path, ns_prefix: str | None = "scratch") -> tuple[ResourceSet, EPackage]:
    """A small metamodel: A holds Bs, refers to Bs, and has an int, a double and a date."""
    package = EPackage("scratch", nsURI="http://example.org/scratch/1", nsPrefix=ns_prefix)
    a, b = EClass("A"), EClass("B")
    special = EClass("SpecialB", superclass=(b,))
    package.eClassifiers.extend([a, b, special])
    a.eStructuralFeatures.extend(
        [
            EAttribute("count", EInt),
            EAttribute("ratio", EDouble),
            EAttribute("when", EDate),
            EReference("items", b, upper=-1, containment=True),
            EReference("refs", b, upper=-1),
        ]
    )
    b.eStructuralFeatures.append(EAttribute("name", EString))
    resource_set = ResourceSet()
    resource = resource_set.create_resource(URI(str(tmp_path / "scratch.ecore")))
    resource.append(package)
    resource.save()
    resource_set.metamodel_registry[package.nsURI] = package
    return resource_set, package


def _save(resource_set: ResourceSet, path: Path, *roots: object) -> Path:
    resource = resource_set.create_resource(URI(str(path)))
    for root in roots:
        resource.append(root)
    resource.save()
    return path


def _ecore_features(kind: str) -> list[etree._Element]:
    return METAMODEL.xpath(
        "//eStructuralFeatures[@xsi:type=$kind]",
        namespaces={"xsi": "http://www.w3.org/2001/XMLSchema-instance"},
        kind=f"ecore:{kind}",
    )


# default_value ----------------------------------------------------------------------------------


def test_trap_pyecore_drops_default_value_when_writing_ecore(tmp_path: Path) -> None:
    package = EPackage("d", nsURI="http://example.org/d", nsPrefix="d")
    cls = EClass("C")
    cls.eStructuralFeatures.append(EAttribute("n", EInt, default_value=5))
    package.eClassifiers.append(cls)
    path = _save(ResourceSet(), tmp_path / "d.ecore", package)
    assert "5" not in path.read_text()


def test_sceml_defaults_are_written_as_default_value_literal() -> None:
    with_default = [a for a in _ecore_features("EAttribute") if a.get("defaultValueLiteral")]
    assert {a.get("name") for a in with_default} >= {"level", "policy", "isEgo", "timeOfDay"}
    # What the generated code uses is what the .ecore says.
    assert scm.RootNode.level.default_value is scm.AbstractionLevel.functional
    assert scm.EndNode.policy.default_value is scm.JoinPolicy.joinAll


# eOpposite ---------------------------------------------------------------------------------------


def test_trap_eopposite_set_on_one_end_is_not_written(tmp_path: Path) -> None:
    package = EPackage("o", nsURI="http://example.org/o", nsPrefix="o")
    a, b = EClass("A"), EClass("B")
    package.eClassifiers.extend([a, b])
    owner = EReference("owner", a)
    b.eStructuralFeatures.append(owner)
    a.eStructuralFeatures.append(EReference("bs", b, upper=-1, eOpposite=owner))
    path = _save(ResourceSet(), tmp_path / "o.ecore", package)
    assert "eOpposite" not in path.read_text()


def test_sceml_opposites_are_declared_on_both_ends() -> None:
    opposites = {
        f.get("name"): f.get("eOpposite")
        for f in _ecore_features("EReference")
        if f.get("eOpposite")
    }
    assert opposites == {
        "source": "#//GraphElement/outgoing",
        "target": "#//GraphElement/incoming",
        "incoming": "#//Flow/target",
        "outgoing": "#//Flow/source",
    }


# enum literal vs name ------------------------------------------------------------------------------


def test_trap_emf_refuses_an_enum_written_by_name_when_literal_differs(
    emf: Harness, tmp_path: Path
) -> None:
    ecore = tmp_path / "e.ecore"
    ecore.write_text(
        '<?xml version="1.0" encoding="UTF-8"?>\n<ecore:EPackage xmi:version="2.0" '
        'xmlns:xmi="http://www.omg.org/XMI" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" '
        'xmlns:ecore="http://www.eclipse.org/emf/2002/Ecore" name="e" nsURI="http://example.org/e" '
        'nsPrefix="e">\n<eClassifiers xsi:type="ecore:EEnum" name="Side">\n'
        '<eLiterals name="left" literal="LEFT"/><eLiterals name="right" value="1" literal="RIGHT"/>'
        '</eClassifiers>\n<eClassifiers xsi:type="ecore:EClass" name="C">\n'
        '<eStructuralFeatures xsi:type="ecore:EAttribute" name="side" eType="#//Side"/>\n'
        "</eClassifiers>\n</ecore:EPackage>\n"
    )
    resource_set = ResourceSet()
    package = resource_set.get_resource(URI(str(ecore))).contents[0]
    resource_set.metamodel_registry[package.nsURI] = package
    cls = package.getEClassifier("C")
    instance = cls(side=package.getEClassifier("Side").getEEnumLiteral("right"))
    path = _save(resource_set, tmp_path / "c.xmi", instance)
    assert 'side="right"' in path.read_text()
    result = emf.run("features", ecore, path, check=False)
    assert result.returncode == 1 and "right" in result.stdout


def test_sceml_enum_literals_equal_their_names() -> None:
    literals = METAMODEL.findall(".//eLiterals")
    assert len(literals) > 20
    assert [
        (e.get("name"), e.get("literal")) for e in literals if e.get("name") != e.get("literal")
    ] == []


# EDate -------------------------------------------------------------------------------------------


def test_trap_emf_reads_pyecore_microseconds_as_milliseconds(emf: Harness, tmp_path: Path) -> None:
    resource_set, package = _scratch(tmp_path)
    when = datetime.datetime(2026, 1, 1, 12, 0, 0, 123456)
    path = _save(resource_set, tmp_path / "date.xmi", package.getEClassifier("A")(when=when))
    assert 'when="2026-01-01T12:00:00.123456"' in path.read_text()
    result = emf.run("features", tmp_path / "scratch.ecore", path)
    # 123456 "milliseconds" are 2 min 3.456 s: EMF reads another instant than was written.
    assert "12:02:03" in result.stdout


def test_sceml_has_no_edate() -> None:
    assert [a.get("name") for a in _ecore_features("EAttribute") if "EDate" in a.get("eType")] == []
    assert (
        'name="date" eType="ecore:EDataType http://www.eclipse.org/emf/2002/Ecore#//EString"'
        in (ECORE.read_text())
    )


# non-finite doubles and 64-bit ints ---------------------------------------------------------------


@pytest.mark.parametrize(
    ("feature", "value", "written"),
    [("ratio", math.inf, "inf"), ("ratio", math.nan, "nan"), ("count", 2**31, "2147483648")],
)
def test_trap_emf_refuses_what_pyecore_writes_for_out_of_range_numbers(
    emf: Harness, tmp_path: Path, feature: str, value: float, written: str
) -> None:
    resource_set, package = _scratch(tmp_path)
    path = _save(resource_set, tmp_path / "n.xmi", package.getEClassifier("A")(**{feature: value}))
    assert f'{feature}="{written}"' in path.read_text()
    result = emf.run("features", tmp_path / "scratch.ecore", path, check=False)
    assert result.returncode == 1 and "NumberFormatException" in result.stdout


def _scenario_with(speed: float, lane_id: int) -> scm.Scenario:
    builder = ScenarioBuilder("S", level="concrete")
    ego = builder.actor("Car", "ego", ego=True, start=lane(1, lane_id, 10.0), speed=speed)
    builder.chain(builder.root, builder.add("KeepVelocity", ego, duration=3.0), builder.end)
    return builder.scenario


@pytest.mark.parametrize(
    ("speed", "lane_id", "message"),
    [
        (math.inf, 1, "value is inf, which EMF cannot read"),
        (math.nan, 1, "value is nan, which EMF cannot read"),
        (5.0, 2**31, "2147483648 does not fit a 32-bit int"),
        (5.0, -(2**31) - 1, "does not fit a 32-bit int"),
    ],
)
def test_io_save_refuses_numbers_emf_cannot_read(
    tmp_path: Path, speed: float, lane_id: int, message: str
) -> None:
    target = tmp_path / "s.xmi"
    target.write_bytes(b"good")
    with pytest.raises(SaveError) as caught:
        save(_scenario_with(speed, lane_id), target)
    assert message in caught.value.message
    assert caught.value.element in ("Root/ego/initialSpeed", "Root/ego/startPosition")
    assert target.read_bytes() == b"good"


def test_io_save_accepts_the_extremes_of_int_and_double(emf: Harness, tmp_path: Path) -> None:
    path = save(_scenario_with(1.7976931348623157e308, -(2**31)), tmp_path / "edge.xmi")
    result = emf.run("features", ECORE, path)
    assert "laneId=-2147483648" in result.stdout and "value=1.7976931348623157E308" in result.stdout


# nsPrefix ----------------------------------------------------------------------------------------


def test_trap_package_without_ns_prefix_is_written_as_none(emf: Harness, tmp_path: Path) -> None:
    resource_set, package = _scratch(tmp_path, ns_prefix=None)
    a = package.getEClassifier("A")()
    a.items.append(package.getEClassifier("SpecialB")())
    path = _save(resource_set, tmp_path / "p.xmi", a)
    assert 'xsi:type="None:SpecialB"' in path.read_text()
    result = emf.run("features", tmp_path / "scratch.ecore", path, check=False)
    assert result.returncode == 1


def test_sceml_package_has_a_prefix_and_files_use_it(tmp_path: Path) -> None:
    assert METAMODEL.getroot().get("nsPrefix") == scm.nsPrefix == "scemlmodel"
    text = save(_scenario_with(5.0, 1), tmp_path / "s.xmi").read_text()
    assert 'xsi:type="scemlmodel:RootNode"' in text and "None:" not in text


# many-valued references across files ---------------------------------------------------------------


def test_trap_mixed_many_valued_reference_comes_back_unresolvable(
    emf: Harness, tmp_path: Path
) -> None:
    resource_set, package = _scratch(tmp_path)
    a_class, b_class = package.getEClassifier("A"), package.getEClassifier("B")
    (tmp_path / "in").mkdir()
    other = a_class()
    other.items.append(b_class(name="far"))
    _save(resource_set, tmp_path / "in" / "other.xmi", other)
    holder, near = a_class(), b_class(name="near")
    holder.refs.extend([near, other.items[0]])
    _save(resource_set, tmp_path / "in" / "multi.xmi", holder, near)
    emf.run("roundtrip", tmp_path / "scratch.ecore", tmp_path / "in", tmp_path / "out", "multi.xmi")
    written = (tmp_path / "out" / "multi.xmi").read_text()
    assert '<refs href="#/1"/>' in written
    reader = ResourceSet()
    reader.metamodel_registry[package.nsURI] = package
    refs = reader.get_resource(URI(str(tmp_path / "out" / "multi.xmi"))).contents[0].refs
    with pytest.raises(AttributeError):
        [target.name for target in refs]  # noqa: B018


def test_sceml_cross_file_capable_references_are_single_valued() -> None:
    many = [
        f.get("name")
        for f in _ecore_features("EReference")
        if f.get("containment") != "true"
        and f.get("transient") != "true"
        and f.get("upperBound") == "-1"
    ]
    assert many == []

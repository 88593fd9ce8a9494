"""Tests for sceml.xosc.schema: XSD validation, version detection and hostile-input refusal."""

from __future__ import annotations

import copy
import dataclasses
import importlib.resources
from pathlib import Path

import pytest
from lxml import etree

from sceml.errors import SceMLError
from sceml.xosc import schema
from sceml.xosc.schema import (
    SUPPORTED_VERSIONS,
    SchemaIssue,
    UnsafeXMLError,
    UnsupportedVersionError,
    XMLParseError,
    declared_version,
    is_valid_tree,
    parse_file,
    validate_file,
    validate_tree,
)

DATA = Path(__file__).parent / "data"
MINIMAL = {v: DATA / f"minimal_{v.replace('.', '_')}.xosc" for v in SUPPORTED_VERSIONS}


def _header_doc(attrs: str) -> etree._Element:
    return etree.fromstring(f"<OpenSCENARIO><FileHeader {attrs}/></OpenSCENARIO>")


# --- valid documents -----------------------------------------------------------------------


@pytest.mark.parametrize("version", SUPPORTED_VERSIONS)
def test_minimal_file_of_each_version_is_valid(version: str) -> None:
    path = MINIMAL[version]
    assert validate_file(path) == []
    tree = parse_file(path)
    assert declared_version(tree) == version
    assert validate_tree(tree) == []
    assert is_valid_tree(tree, version)


def test_tree_built_in_memory_validates_without_source_lines() -> None:
    root = copy.deepcopy(parse_file(MINIMAL["1.3"]).getroot())  # detached copy
    vehicle = root.find("Entities/ScenarioObject/Vehicle")
    assert vehicle is not None
    del vehicle.attrib["vehicleCategory"]
    etree.SubElement(root.find("Entities"), "ScenarioObject")  # no name, no entity
    issues = validate_tree(root)
    assert issues
    assert all(isinstance(i, SchemaIssue) and i.path for i in issues)
    assert any("vehicleCategory" in i.reason for i in issues)


def test_explicit_version_overrides_file_header() -> None:
    tree = parse_file(MINIMAL["1.2"])
    assert validate_tree(tree, "1.3") == []  # the minimal 1.2 body is also valid 1.3
    with pytest.raises(UnsupportedVersionError):
        validate_tree(tree, "2.0")


def test_1_1_uses_errata_schema_with_comma_in_expressions() -> None:
    # 1.1.1 (chosen) allows ${max($a, 1)}; the superseded 1.1.0 pattern lacks ','.
    tree = parse_file(MINIMAL["1.1"])
    performance = tree.find("Entities/ScenarioObject/Vehicle/Performance")
    assert performance is not None
    performance.set("maxSpeed", "${max($EgoSpeed, 1)}")
    assert validate_tree(tree) == []


# --- invalid documents ---------------------------------------------------------------------


def test_missing_required_attribute_is_reported_with_line_and_path() -> None:
    issues = validate_file(DATA / "invalid_missing_attribute_1_2.xosc")
    assert len(issues) == 1
    issue = issues[0]
    assert issue.line == 13
    assert issue.path == "/OpenSCENARIO/Entities/ScenarioObject/Vehicle"
    assert "missing required attribute 'vehicleCategory'" in issue.reason
    assert issue.message.startswith("line 13")
    assert str(issue) == issue.message
    assert "\n" not in issue.message


def test_wrong_element_points_at_the_offending_child() -> None:
    issues = validate_file(DATA / "invalid_wrong_element_1_3.xosc")
    assert len(issues) == 1
    issue = issues[0]
    assert issue.line == 18
    assert issue.path is not None and issue.path.endswith("/Vehicle/Performence")
    assert "'Performence'" in issue.reason and "'Performance' expected" in issue.reason
    assert not is_valid_tree(parse_file(DATA / "invalid_wrong_element_1_3.xosc"))


def test_child_position_survives_comments_and_pis(tmp_path: Path) -> None:
    data = (DATA / "invalid_wrong_element_1_3.xosc").read_bytes()
    f = tmp_path / "commented.xosc"
    f.write_bytes(data.replace(b"<BoundingBox>", b"<!-- a --><?pi b?><BoundingBox>"))
    (issue,) = validate_file(f)
    assert issue.line == 18 and issue.path is not None
    assert issue.path.endswith("/Performence")


def test_schema_issue_is_frozen() -> None:
    issue = validate_file(DATA / "invalid_missing_attribute_1_2.xosc")[0]
    with pytest.raises(dataclasses.FrozenInstanceError):
        issue.line = 1  # type: ignore[misc]


def test_malformed_xml_becomes_an_issue_with_file_and_line(tmp_path: Path) -> None:
    bad = tmp_path / "broken.xosc"
    bad.write_text("<OpenSCENARIO>\n  <FileHeader>\n</OpenSCENARIO>\n", encoding="utf-8")
    (issue,) = validate_file(bad)
    assert issue.line == 3
    assert str(bad) in issue.message and ":3:" in issue.message
    assert "mismatch" in issue.reason
    with pytest.raises(XMLParseError) as info:
        parse_file(bad)
    assert info.value.line == 3 and info.value.file == str(bad)


# --- version detection ---------------------------------------------------------------------


def test_declared_version_accepts_tree_or_root() -> None:
    tree = parse_file(MINIMAL["1.3"])
    assert declared_version(tree) == declared_version(tree.getroot()) == "1.3"


@pytest.mark.parametrize(
    ("attrs", "fragment"),
    [
        ('revMajor="1"', "revMinor"),
        ('revMajor="1" revMinor="4"', "1.4 is not supported"),
        ('revMajor="2" revMinor="0"', "2.0 is not supported"),
        ('revMajor="1" revMinor="$minor"', "not literal integers"),
    ],
)
def test_declared_version_rejects_bad_headers(attrs: str, fragment: str) -> None:
    with pytest.raises(UnsupportedVersionError, match=fragment.replace("$", r"\$")):
        declared_version(_header_doc(attrs))


def test_declared_version_needs_a_file_header() -> None:
    with pytest.raises(UnsupportedVersionError, match="no FileHeader"):
        declared_version(etree.fromstring("<OpenSCENARIO/>"))


def test_errors_are_sceml_errors_and_value_errors() -> None:
    assert issubclass(UnsupportedVersionError, SceMLError)
    assert issubclass(UnsupportedVersionError, ValueError)
    assert issubclass(UnsafeXMLError, schema.SchemaError)


def test_validate_file_names_the_file_when_version_is_unsupported(tmp_path: Path) -> None:
    f = tmp_path / "future.xosc"
    f.write_text('<OpenSCENARIO><FileHeader revMajor="1" revMinor="9"/></OpenSCENARIO>')
    with pytest.raises(UnsupportedVersionError) as info:
        validate_file(f)
    assert info.value.file == str(f)
    assert str(info.value).startswith(f"{f}: ")


# --- hostile input -------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["billion_laughs.xosc", "xxe.xosc"])
def test_dtd_documents_are_refused_before_parsing(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = DATA / name
    parsed: list[object] = []
    monkeypatch.setattr(etree, "parse", lambda *a, **k: parsed.append(a))
    monkeypatch.setattr(etree, "fromstring", lambda *a, **k: parsed.append(a))
    with pytest.raises(UnsafeXMLError) as info:
        validate_file(path)
    assert parsed == []  # the entities are never expanded: the parser never sees the file
    err = info.value
    assert err.file == str(path) and err.line == 2
    assert str(err).startswith(f"{path}:2: DOCTYPE")
    # Nothing was expanded or fetched into the error.
    assert "lollol" not in str(err) and "root:" not in str(err)


def test_dtd_after_comment_and_pi_in_utf16_is_refused(tmp_path: Path) -> None:
    text = (
        '<?xml version="1.0" encoding="UTF-16"?>\n<!-- a comment -->\n<?pi data?>\n'
        '<!DOCTYPE OpenSCENARIO [<!ENTITY x SYSTEM "file:///etc/passwd">]>\n'
        "<OpenSCENARIO>&x;</OpenSCENARIO>\n"
    )
    f = tmp_path / "utf16.xosc"
    f.write_bytes(text.encode("utf-16"))
    with pytest.raises(UnsafeXMLError) as info:
        parse_file(f)
    assert info.value.line == 4


def test_doctype_text_inside_a_comment_is_not_refused(tmp_path: Path) -> None:
    data = (
        MINIMAL["1.3"]
        .read_bytes()
        .replace(b"<CatalogLocations/>", b"<!-- never write <!DOCTYPE here --><CatalogLocations/>")
    )
    f = tmp_path / "comment.xosc"
    f.write_bytes(data)
    assert validate_file(f) == []


# --- caching and speed ---------------------------------------------------------------------


def test_schemas_are_loaded_once_per_version() -> None:
    assert schema._lxml_schema("1.3") is schema._lxml_schema("1.3")
    assert schema._lxml_schema("1.2") is not schema._lxml_schema("1.3")


def test_xsd_comes_from_the_qc_package() -> None:
    assert schema._XSD_FOLDERS == {"1.0": "1.0.0", "1.1": "1.1.1", "1.2": "1.2.0", "1.3": "1.3.0"}
    assert b"ASAM OpenSCENARIO V1.1.1" in schema.xsd_bytes("1.1")


def test_validating_a_tree_does_not_serialise(monkeypatch: pytest.MonkeyPatch) -> None:
    tree = parse_file(MINIMAL["1.3"])
    schema._lxml_schema("1.3")  # warm the cache; loading the XSD legitimately parses

    def forbidden(*args: object, **kwargs: object) -> None:
        raise AssertionError("validate_tree must not serialise or reparse")

    for name in ("tostring", "fromstring", "XML", "parse"):
        monkeypatch.setattr(etree, name, forbidden)
    assert validate_tree(tree) == []


def _twenty_kb_tree() -> etree._ElementTree:
    tree = parse_file(MINIMAL["1.3"])
    entities = tree.find("Entities")
    actions = tree.find("Storyboard/Init/Actions")
    assert entities is not None and actions is not None
    template_obj, template_private = entities[0], actions[0]
    i = 0
    while len(etree.tostring(tree)) < 20_000:
        i += 1
        obj = copy.deepcopy(template_obj)
        obj.set("name", f"Car{i}")
        entities.append(obj)
        private = copy.deepcopy(template_private)
        private.set("entityRef", f"Car{i}")
        actions.append(private)
    return tree


def test_validating_a_tree_reuses_the_compiled_schema_and_never_reparses(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    tree = _twenty_kb_tree()
    assert validate_tree(tree) == []
    compiled = schema._lxml_schema.cache_info().misses
    parsed: list[object] = []
    monkeypatch.setattr(etree, "fromstring", lambda *a, **k: parsed.append(a))
    monkeypatch.setattr(etree, "tostring", lambda *a, **k: parsed.append(a))
    for _ in range(3):
        assert validate_tree(tree) == []
    assert schema._lxml_schema.cache_info().misses == compiled and parsed == []


@pytest.mark.parametrize("version", SUPPORTED_VERSIONS)
def test_the_xsd_is_found_without_importing_the_checker_package(version: str) -> None:
    # The same bytes as the package's own resource lookup gives (which imports pydantic).
    via_package = importlib.resources.files("qc_openscenario.schema") / schema._XSD_FOLDERS[version]
    assert schema.xsd_bytes(version) == (via_package / schema._XSD_NAME).read_bytes()

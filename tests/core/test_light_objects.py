"""The read-only load (`sceml validate`'s lighter objects) validates and reads like pyecore's.

Every `.xmi` file of the repository (examples, the validation corpus, the hostile corpus, the
players' scenarios) is validated after a full load and after a read-only one, and the reports
must be the same; the models must read the same feature by feature; every file SceML writes is
read while it is parsed (sceml.model.xmi_stream), the others the whole-tree way; and code that
tries to change a read-only object must fail at once.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from pyecore.ecore import EAttribute, EObject, EProxy

import scemlmodel as scm
from sceml.errors import LoadError
from sceml.model import fastobjects, xmi_stream
from sceml.model.lightobjects import ReadOnlyModelError, is_read_only
from sceml.model.loading import load
from sceml.model.traversal import all_contents, features, single_value
from sceml.report import FileReport
from sceml.validation import validate
from sceml.validation.files import validate_file
from sceml.validation.limits import Limits

REPO = Path(__file__).resolve().parents[2]
FILES = sorted([*(REPO / "examples").rglob("*.xmi"), *(REPO / "tests").rglob("*.xmi")])
WRITTEN_BY_SCEML = [
    p
    for p in FILES
    if p.is_relative_to(REPO / "examples") or p.is_relative_to(REPO / "tests/validation")
]
UIS1 = REPO / "examples" / "uis1-concrete.xmi"
UIS2 = REPO / "examples" / "uis2-logical.xmi"


def _ids(paths: list[Path]) -> list[str]:
    return [str(p.relative_to(REPO)) for p in paths]


def report_text(report: FileReport) -> list[str]:
    """Everything a report says, object addresses (in some pyecore messages) aside."""
    said = [f"unreadable: {report.unreadable}"]
    for d in report.diagnostics:
        said.append(f"{d.severity.name} {d.code} {d.file}:{d.line} {d.fragment} {d.message}")
    return [re.sub(r"0x[0-9a-f]+", "0x...", text) for text in said]


@pytest.mark.parametrize("path", FILES, ids=_ids(FILES))
def test_validation_reports_the_same_after_either_load(path: Path) -> None:
    full = validate_file(path, Limits(), None, read_only=False)
    light = validate_file(path, Limits(), None, read_only=True)
    assert report_text(light) == report_text(full)
    assert not any("ReadOnlyModelError" in d.message for d in light.diagnostics)


def test_the_corpus_is_all_there() -> None:
    # A glob that finds nothing would make the test above pass vacuously.
    for folder in ("examples", "tests/validation/corpus", "tests/hostile/corpus"):
        assert any(p.is_relative_to(REPO / folder) for p in FILES), folder
    assert len(FILES) > 150


@pytest.fixture
def streamed(monkeypatch: pytest.MonkeyPatch) -> list[bool]:
    """What `xmi_stream.decode` answered, file by file, during the test."""
    answers: list[bool] = []
    original = xmi_stream.decode

    def spy(*args: Any) -> bool:
        answers.append(original(*args))
        return answers[-1]

    monkeypatch.setattr(xmi_stream, "decode", spy)
    return answers


@pytest.mark.parametrize("path", WRITTEN_BY_SCEML, ids=_ids(WRITTEN_BY_SCEML))
def test_read_only_objects_read_like_full_ones(path: Path, streamed: list[bool]) -> None:
    try:
        full = load(path)
    except LoadError:
        with pytest.raises(LoadError):
            load(path, read_only=True)
        return
    light = load(path, read_only=True)
    assert streamed[:1] == [True], "a file SceML wrote was not read while parsed"
    assert is_read_only(light.root) and not is_read_only(full.root)
    full_objects = [full.root, *all_contents(full.root)]
    light_objects = [light.root, *all_contents(light.root)]
    assert len(light_objects) == len(full_objects)
    position = {id(obj): index for index, obj in enumerate(light_objects)}
    expected = {id(obj): index for index, obj in enumerate(full_objects)}
    for one, other in zip(full_objects, light_objects, strict=True):
        assert type(other) is type(one)
        assert is_read_only(other)
        assert light.line_of(other) == full.line_of(one)
        container = other.eContainer()
        assert (position.get(id(container)) if container else None) == (
            expected.get(id(one.eContainer())) if one.eContainer() else None
        )
        assert other.eContainmentFeature() is one.eContainmentFeature()
        assert list(other._isset) == list(one._isset)
        assert len(other._isset) == len(one._isset)
        for feature in features(one.eClass):
            assert other.eIsSet(feature) == one.eIsSet(feature), feature.name
            assert _readable(other.eGet(feature), position) == _readable(
                one.eGet(feature), expected
            ), feature.name
            if not feature.many:
                assert _readable(single_value(other, feature.name), position) == _readable(
                    single_value(one, feature.name), expected
                )


def _readable(value: Any, index: dict[int, int]) -> Any:
    """A feature's value as data: model objects by their place in the walk (or proxy path)."""
    if isinstance(value, EProxy):
        return ("proxy", object.__getattribute__(value, "_proxy_path"))
    if isinstance(value, EObject):
        return ("object", index.get(id(value), type(value).__name__))
    if hasattr(value, "__iter__") and not isinstance(value, str):
        return [_readable(item, index) for item in value]
    return value


@pytest.fixture
def scenario() -> Any:
    return load(UIS1, read_only=True).root


def test_setting_a_feature_is_refused(scenario: Any) -> None:
    root = scenario.nodes[0]
    with pytest.raises(ReadOnlyModelError):
        root.name = "Other"  # set in the file
    with pytest.raises(ReadOnlyModelError):
        root.eSet("description", "changed")
    node = scenario.nodes[2]
    with pytest.raises(ReadOnlyModelError):
        node.maxRuns = 3  # never set: pyecore makes a holder, then marks the feature
    with pytest.raises(ReadOnlyModelError):
        node.referenceActor = None


def test_adding_and_removing_is_refused(scenario: Any) -> None:
    with pytest.raises(ReadOnlyModelError):
        scenario.nodes.append(scm.EndNode(name="Another"))
    with pytest.raises(ReadOnlyModelError):
        scenario.nodes.remove(scenario.nodes[-1])
    with pytest.raises(ReadOnlyModelError):
        scenario.nodes.pop()
    with pytest.raises(ReadOnlyModelError):
        scenario.flows.clear()
    flow = scenario.flows[0]
    with pytest.raises(ReadOnlyModelError):
        flow.target = scenario.nodes[1]  # and its opposite end
    with pytest.raises(ReadOnlyModelError):
        flow.delete()


def test_bookkeeping_for_edits_is_refused(scenario: Any) -> None:
    value = scenario.nodes[0].maxDuration
    with pytest.raises(ReadOnlyModelError):
        value.listeners.append(object())
    with pytest.raises(ReadOnlyModelError):
        value._inverse_rels.add((scenario, None))
    with pytest.raises(ReadOnlyModelError):
        value._isset.clear()
    with pytest.raises(ReadOnlyModelError):
        fastobjects.set_value(value, fastobjects.slot(scm.Value.value), 1.0)
    assert value.value == 60.0


def test_references_into_other_files_and_their_targets_stay_usable() -> None:
    # UIS2 uses a library's module: the library is read read-only too, and the module
    # expansion records its copies' references in the definitions' parameters and the
    # scenario's actors (real sets there) and removes them again.
    document = load(UIS2, read_only=True)
    use = next(node for node in document.root.nodes if isinstance(node, scm.ModuleUse))
    proxy = use.definition
    proxy.force_resolve()
    definition = object.__getattribute__(proxy, "_wrapped")
    assert isinstance(definition, scm.ModuleDefinition) and is_read_only(definition)
    actors = list(document.root.nodes[0].actors)
    assert actors and all(type(a._inverse_rels) is set for a in actors)
    assert not document.root.nodes[0].maxDuration._inverse_rels
    recorded = [set(a._inverse_rels) for a in actors]
    diagnostics = validate(document.root, document=document)
    assert not any(d.code == "SCEML-X000" for d in diagnostics)
    assert [set(a._inverse_rels) for a in actors] == recorded


def test_features_of_values_are_plain_attributes() -> None:
    # Held keeps a value; attributes hold data, references model objects: both read the same.
    document = load(UIS1, read_only=True)
    value = document.root.nodes[0].maxDuration
    assert isinstance(scm.Value.value, EAttribute)
    assert value.value == 60.0 and value.eGet("value") == 60.0
    assert value.__dict__["value"]._get() == 60.0


HOSTILE = sorted((REPO / "tests" / "hostile" / "corpus").glob("*.xmi"))


@pytest.mark.parametrize("path", HOSTILE, ids=_ids(HOSTILE))
def test_files_the_stream_declines_give_the_whole_tree_errors(
    path: Path, streamed: list[bool]
) -> None:
    # Each hostile file is refused or decoded the whole-tree way, with the same error and line.
    def outcome(read_only: bool) -> str:
        try:
            load(path, read_only=read_only)
        except LoadError as error:
            return re.sub(r"0x[0-9a-f]+", "0x...", f"{error} (line {error.line})")
        return "loaded"

    assert outcome(True) == outcome(False)


def test_streaming_frees_the_tree_as_it_goes(monkeypatch: pytest.MonkeyPatch) -> None:
    # Each top-level element is cleared once read and dropped once the next one is: at the end
    # the parsed tree is the root element and one empty child.
    parses: list[Any] = []
    original = xmi_stream.hardened_iterparse

    def kept(*args: Any, **kwargs: Any) -> Any:
        parses.append(original(*args, **kwargs))
        return parses[-1]

    monkeypatch.setattr(xmi_stream, "hardened_iterparse", kept)
    document = load(UIS1, read_only=True)
    assert len(parses) == 1
    left = parses[0].root
    assert len(left) == 1 and len(left[0]) == 0 and not left[0].attrib
    assert len(document.root.nodes) > 5 and len(document.root.flows) > 5
    assert document.line_of(document.root.flows[-1]) is not None


_FLOW = '<flows xsi:type="scemlmodel:Flow" source="//@nodes.0" target="//@nodes.2"/>'
# UIS1 changed so that the stream declines it at some point; (text replaced, its replacement,
# whether the whole-tree path still reads it).
VARIANTS = {
    "prefix declared below the root": (
        _FLOW,
        _FLOW.replace("<flows ", '<flows xmlns:other="urn:other" '),
        True,
    ),
    "unknown element between two flows": (_FLOW, _FLOW + "<unknown/>", False),
    "unknown element at the end": (
        "</scemlmodel:Scenario>",
        "<unknown/></scemlmodel:Scenario>",
        False,
    ),
    "repeated xmi:id in two top-level elements": (
        _FLOW,
        _FLOW.replace("<flows ", '<flows xmi:id="a" ')
        + _FLOW.replace("<flows ", '<flows xmi:id="a" '),
        False,
    ),
    "wrong xsi:type deep in the last node": (
        '<flows xsi:type="scemlmodel:Flow" source="//@nodes.8"',
        '<flows xsi:type="scemlmodel:Nothing" source="//@nodes.8"',
        False,
    ),
    "malformed XML after the first nodes": (_FLOW, _FLOW + "<flows", False),
    "a dangling reference": ('source="//@nodes.0"', 'source="//@nodes.99"', False),
}


@pytest.mark.parametrize("variant", list(VARIANTS), ids=list(VARIANTS))
def test_a_declined_stream_reads_the_whole_tree_way(
    variant: str, tmp_path: Path, streamed: list[bool]
) -> None:
    old, new, readable = VARIANTS[variant]
    text = UIS1.read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "variant.xmi"  # its map is not there: both ways report that too
    path.write_text(text.replace(old, new, 1), encoding="utf-8")

    def outcome(read_only: bool) -> list[str]:
        report = validate_file(path, Limits(), None, read_only=read_only)
        return report_text(report)

    full = outcome(False)
    streamed.clear()
    assert outcome(True) == full
    assert streamed == [False]
    assert (full[0] == "unreadable: None") == readable, full[0]

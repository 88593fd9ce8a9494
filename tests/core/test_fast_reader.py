"""The fast XMI reader (sceml.model.xmi_reader) builds exactly what pyecore's decoder builds, or declines.

Every `.xmi` file of the repository and random scenarios are loaded both ways and compared object
by object (tests/core/model_state.py), with their resources, their saved bytes and the lines of
their elements; broken files give the same error both ways; files the reader does not handle go
to pyecore's decoder and load as before; a fast-loaded model edits like one pyecore built.
"""

from __future__ import annotations

import contextlib
import re
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from editor.test_random_edits import draw_op
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from pyecore.resources import URI
from strategies import scenarios

import scemlmodel as scm
from sceml.editor import EditorSession, OperationError
from sceml.errors import LoadError, SaveError
from sceml.model import xmi_reader
from sceml.model import xmi_reader as io_xmi_reader
from sceml.model.documents import Document, new_resource_set
from sceml.model.loading import load, unresolved_references
from sceml.model.saving import save
from sceml.model.xmiresource import SafeXMIResource, _check_literal, parse_xml_safely

from .model_state import difference, model_state, paths, resource_state

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
FILES = sorted([*EXAMPLES.rglob("*.xmi"), *(REPO / "tests").rglob("*.xmi")])
# Files SceML itself wrote (or that read like it): the reader must take every one of them.
WRITTEN_BY_SCEML = [
    p for p in FILES if p.is_relative_to(EXAMPLES) or p.is_relative_to(REPO / "tests/validation")
]


@contextlib.contextmanager
def decoding(fast: bool) -> Iterator[list[bool]]:
    """Load with or without the fast reader; yields what the reader answered, file by file."""
    answers: list[bool] = []
    original_flag = SafeXMIResource.fast_decoding
    original_decode = xmi_reader.decode

    def spy(*args: Any) -> bool:
        answers.append(original_decode(*args))
        return answers[-1]

    SafeXMIResource.fast_decoding = fast
    io_xmi_reader.decode = spy  # type: ignore[attr-defined]
    try:
        yield answers
    finally:
        SafeXMIResource.fast_decoding = original_flag
        io_xmi_reader.decode = original_decode  # type: ignore[attr-defined]


def outcome(path: Path, fast: bool) -> tuple[Document | None, str | None, list[bool]]:
    """The document `path` loads to, or the error it gives, and the reader's answers."""
    with decoding(fast) as answers:
        try:
            return load(path), None, answers
        except LoadError as error:
            # pyecore's messages may show an object's address, which differs from run to run.
            message = re.sub(r"0x[0-9a-f]+", "0x...", str(error))
            return None, f"{message} (line {error.line})", answers


def whole_state(document: Document) -> dict[str, Any]:
    """The model, every other file loaded into its resource set, and the resources."""
    roots = {"root": document.root}
    resources = list(document.resource_set.resources.values())
    for index, resource in enumerate(r for r in resources if r is not document.resource):
        if resource.contents:
            roots[f"file{index}"] = resource.contents[0]
    names = paths(roots)
    return {
        "objects": model_state(roots),
        "resources": [resource_state(r, names) for r in resources if r.contents],
        "files": [Path(key).name for key in document.resource_set.resources],
    }


def lines(document: Document) -> list[int | None]:
    """The line of every element, as Document.line_of finds it."""
    return [document.line_of(obj) for obj in [document.root, *document.root.eAllContents()]]


_UUID = re.compile(rb"[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}")


def saved(document: Document, path: Path) -> bytes | str:
    """The bytes the model saves to, or the error saving gives.

    A file with xmi:ids gets new random ids for the objects that had none: they are numbered
    in order of appearance instead.
    """
    try:
        data = save(document.root, path).read_bytes()
    except SaveError as error:
        return str(error).replace(str(path), "OUT")
    numbers: dict[bytes, bytes] = {}
    return _UUID.sub(lambda m: numbers.setdefault(m[0], b"id%d" % len(numbers)), data)


def assert_same(path: Path, tmp: Path) -> list[bool]:
    """Load `path` both ways and compare everything; returns the fast reader's answers."""
    slow, slow_error, _ = outcome(path, fast=False)
    fast, fast_error, answers = outcome(path, fast=True)
    assert fast_error == slow_error
    if slow is None or fast is None:
        assert slow is fast is None
        if "not a valid SceML model" in str(slow_error):
            assert True not in answers  # the decoding error comes from pyecore's decoder
        return answers
    assert difference(whole_state(slow), whole_state(fast)) is None
    assert lines(fast) == lines(slow)
    # Cross-file references resolve, lazily, to the same objects (or fail the same way).
    slow_links = [(h.name, href, why) for h, href, why in unresolved_references(slow.root)]
    fast_links = [(h.name, href, why) for h, href, why in unresolved_references(fast.root)]
    assert fast_links == slow_links
    assert difference(whole_state(slow), whole_state(fast)) is None
    assert saved(fast, tmp / "fast.xmi") == saved(slow, tmp / "slow.xmi")
    return answers


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(REPO)))
def test_every_file_loads_the_same_both_ways(path: Path, tmp_path: Path) -> None:
    answers = assert_same(path, tmp_path)
    if path in WRITTEN_BY_SCEML and answers:
        assert answers[0] is True, "the fast reader declined a file SceML wrote"


def test_the_files_are_there() -> None:
    assert len(WRITTEN_BY_SCEML) > 80
    assert any("hostile" in p.parts for p in FILES)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.sampled_from(["functional", "logical", "concrete"]).flatmap(
        lambda level: scenarios(level, max_nodes=10)
    )
)
def test_random_scenarios_load_the_same_both_ways(scenario: scm.Scenario) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = save(scenario, Path(folder) / "model.xmi")
        assert assert_same(path, Path(folder)) == [True]


def test_the_comparison_sees_a_difference() -> None:
    # A check that cannot fail proves nothing: one changed value must show.
    path = EXAMPLES / "uis1-concrete.xmi"
    first, _, _ = outcome(path, fast=True)
    second, _, _ = outcome(path, fast=True)
    assert first is not None and second is not None
    assert difference(whole_state(first), whole_state(second)) is None
    second.root.nodes[2].name = "Renamed"
    assert difference(whole_state(first), whole_state(second)) is not None


# -- what the reader leaves to pyecore --------------------------------------------------------

UIS1 = (EXAMPLES / "uis1-concrete.xmi").read_text()
LIBRARY = (EXAMPLES / "library" / "sceml-library.xmi").read_text()

#: Edits of a real file that pyecore reads (or refuses) and the reader leaves to it:
#: (name, file, text to replace, replacement, whether the reader takes the file).
VARIANTS = [
    ("fragment with #", UIS1, 'source="//@nodes.0"', 'source="#//@nodes.0"', False),
    (
        "type and path",
        UIS1,
        'source="//@nodes.0"',
        'source="scemlmodel:RootNode //@nodes.0"',
        False,
    ),
    ("root number", UIS1, 'source="//@nodes.0"', 'source="/0/@nodes.0"', False),
    ("single slash", UIS1, 'source="//@nodes.0"', 'source="/@nodes.0"', False),
    ("negative index", UIS1, 'target="//@nodes.1"', 'target="//@nodes.-1"', False),
    ("empty reference", UIS1, 'source="//@nodes.0"', 'source=""', False),
    (
        "untyped element",
        UIS1,
        '<environment xsi:type="scemlmodel:Environment"',
        "<environment",
        True,
    ),
    (
        "unknown xmi attribute",
        UIS1,
        "<environment xsi:",
        '<environment xmi:version="2.0" xsi:',
        False,
    ),
    ("xmi:id", UIS1, "<environment xsi:", '<environment xmi:id="env" xsi:', True),
    ("root xmi:id", UIS1, 'xmi:version="2.0"', 'xmi:version="2.0" xmi:id="top"', True),
    ("unknown root attribute", UIS1, 'xmi:version="2.0"', 'xmi:version="2.0" colour="red"', True),
    (
        "nil with children",
        UIS1,
        "</nodes>",
        '<description xsi:nil="true"><x/></description></nodes>',
        False,
    ),
    ("nil containment", UIS1, "</nodes>", '<diagramPosition xsi:nil="true"/></nodes>', True),
    (
        "nil twice",
        UIS1,
        "</nodes>",
        '<author xsi:nil="true"/><author xsi:nil="true"/></nodes>',
        False,
    ),
    (
        "containment twice",
        UIS1,
        "<environment xsi:",
        '<maxDuration xsi:type="scemlmodel:Value" value="1.0"/><environment xsi:',
        False,
    ),
    ("processing instruction", UIS1, "<environment", "<?keep me?><environment", True),
    ("unknown attribute", UIS1, 'name="ego"', 'name="ego" wings="2"', False),
    ("bad number", UIS1, 'value="60.0"', 'value="sixty"', False),
    ("bad enum literal", UIS1, 'cloudState="free"', 'cloudState="sunny"', False),
    ("dangling path", UIS1, 'target="//@nodes.1"', 'target="//@nodes.99"', False),
    ("reference of the wrong type", UIS1, 'target="//@nodes.1"', 'target="//@flows.0"', False),
    ("unknown id", UIS1, 'target="//@nodes.1"', 'target="Nowhere"', False),
    ("boolean in capitals", UIS1, 'isEgo="true"', 'isEgo="TRUE"', True),
    ("int with a sign", UIS1, 'laneId="1"', 'laneId="+1"', True),
    (
        "wrong class for the feature",
        UIS1,
        '<environment xsi:type="scemlmodel:Environment"',
        '<environment xsi:type="scemlmodel:Value"',
        False,
    ),
    ("module by id", LIBRARY, "</scemlmodel:Library>", "</scemlmodel:Library>", True),
    ("duplicate module", LIBRARY, 'name="CrossingManeuver"', 'name="Overtaking"', False),
]


@pytest.mark.parametrize("variant", VARIANTS, ids=lambda v: v[0])
def test_unusual_files_load_or_fail_as_pyecore_has_them(
    variant: tuple[str, str, str, str, bool], tmp_path: Path
) -> None:
    _, text, old, new, taken = variant
    assert old in text
    folder = tmp_path / "model"
    shutil.copytree(EXAMPLES, folder, ignore=shutil.ignore_patterns("*.py"))
    shutil.copytree(REPO / "maps", tmp_path / "maps")
    path = folder / ("library/edited.xmi" if text is LIBRARY else "edited.xmi")
    path.write_text(text.replace(old, new, 1))
    answers = assert_same(path, tmp_path)
    assert answers[:1] == [taken]


def test_a_declined_file_leaves_nothing_behind(tmp_path: Path) -> None:
    # The dangling reference is found last, after every object was made.
    path = tmp_path / "dangling.xmi"
    path.write_text(UIS1.replace('target="//@nodes.1"', 'target="//@nodes.99"'))
    resource = new_resource_set().create_resource(URI(str(path)))
    tree = parse_xml_safely(path)
    resource.prefixes.update(tree.getroot().nsmap)
    resource.xsitype = xmi_reader.XSI_TYPE
    resource.xmiid = "{http://www.omg.org/XMI}id"
    flows_before = sum(1 for obj in scm.Flow.eClass.allInstances() if type(obj) is scm.Flow)
    assert xmi_reader.decode(resource, tree.getroot(), _check_literal) is False
    flows_after = sum(1 for obj in scm.Flow.eClass.allInstances() if type(obj) is scm.Flow)
    assert flows_after == flows_before
    assert resource.contents == [] and resource.uuid_dict == {}


def test_pyecore_edits_a_fast_loaded_model_as_one_it_built(tmp_path: Path) -> None:
    def edited(fast: bool) -> Document:
        document, _, _ = outcome(EXAMPLES / "uis2-concrete.xmi", fast)
        assert document is not None
        root = document.root
        use = next(n for n in root.nodes if isinstance(n, scm.ModuleUse))
        first = root.flows[0]
        root.flows.remove(first)
        first.source = None
        root.nodes[2].delete()
        start = root.nodes[0]
        start.actors[0].name = "hero"
        start.actors.remove(start.actors[-1])
        added = scm.Stop(name="Halt", referenceActor=start.actors[0])
        root.nodes.append(added)
        root.flows.append(scm.Flow(source=use, target=added))
        root.flows[1].target = added
        return document

    slow, fast = edited(False), edited(True)
    assert difference(whole_state(slow), whole_state(fast)) is None
    assert saved(fast, tmp_path / "fast.xmi") == saved(slow, tmp_path / "slow.xmi")


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data(), requests=st.integers(1, 6))
def test_the_editor_edits_undoes_and_redoes_a_fast_loaded_model_alike(
    data: st.DataObject, requests: int
) -> None:
    with tempfile.TemporaryDirectory() as folder:
        shutil.copytree(EXAMPLES, Path(folder) / "examples", ignore=shutil.ignore_patterns("*.py"))
        path = Path(folder) / "examples" / "uis2-concrete.xmi"
        with decoding(fast=False):
            slow = EditorSession()
            view = slow.open(path)
            requested: list[list[dict[str, Any]]] = []
            for _ in range(requests):
                ops = [draw_op(data, view) for _ in range(data.draw(st.integers(1, 3)))]
                requested.append(ops)
                try:
                    view = slow.apply(ops)
                except OperationError:
                    view = slow.view()
            slow_states = _history_states(slow)
        with decoding(fast=True) as answers:
            fast = EditorSession()
            fast.open(path)
            for ops in requested:  # as the slow session had them, views included
                try:
                    fast.apply(ops)
                except OperationError:
                    fast.view()
            fast_states = _history_states(fast)
        assert answers[:1] == [True]
        assert difference(slow_states, fast_states) is None


def _history_states(session: EditorSession) -> list[Any]:
    """The model's state now, after undoing everything, and after redoing it all."""
    assert session.document is not None
    states = [whole_state(session.document)]
    steps = 0
    while session.stack.undo_label is not None:
        session.undo()
        steps += 1
    states.append(whole_state(session.document))
    for _ in range(steps):
        session.redo()
    states.append(whole_state(session.document))
    return states


def test_a_reader_failure_falls_back_to_pyecore(monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(*args: object) -> None:
        raise RuntimeError("a bug in the reader")

    monkeypatch.setattr(xmi_reader, "set_reference", broken)
    slow, _, _ = outcome(EXAMPLES / "uis1-concrete.xmi", fast=False)
    fast, error, answers = outcome(EXAMPLES / "uis1-concrete.xmi", fast=True)
    assert error is None and answers == [False]
    assert slow is not None and fast is not None
    assert difference(whole_state(slow), whole_state(fast)) is None

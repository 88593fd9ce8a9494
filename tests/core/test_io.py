"""Loading and saving XMI: equal content after a round trip, relative cross-file references,
located errors, refused hostile input and atomic writes."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.errors import LoadError, SaveError
from sceml.files.writing import write_atomically
from sceml.model.compare import differences
from sceml.model.loading import load, load_scenario, unresolved_references
from sceml.model.locating import model_path, uri_fragment
from sceml.model.saving import save

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE_FILES = sorted(EXAMPLES.glob("*.xmi")) + sorted((EXAMPLES / "library").glob("*.xmi"))


def test_the_reference_examples_are_all_there() -> None:
    names = {path.name for path in EXAMPLE_FILES}
    for level in ("functional", "logical", "concrete"):
        assert {f"uis1-{level}.xmi", f"uis2-{level}.xmi"} <= names
    assert "sceml-library.xmi" in names


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_loads_saves_and_reloads_equal(path: Path, examples_copy: Path) -> None:
    source = examples_copy / path.relative_to(EXAMPLES)
    original = load(source)
    resaved = source.with_name("resaved-" + source.name)
    save(original.root, resaved)
    reloaded = load(resaved)
    assert differences(original.root, reloaded.root) == []


def test_round_trip_sees_a_real_change(examples_copy: Path) -> None:
    # The comparison itself must be able to fail.
    source = examples_copy / "uis1-concrete.xmi"
    first, second = load(source), load(source)
    second.root.nodes[2].targetSpeed.value = 9.5
    assert differences(first.root, second.root) == ["//nodes[2]/targetSpeed/value: 8.0 != 9.5"]


def test_cross_file_reference_resolves_relative_to_the_referring_file(examples_copy: Path) -> None:
    document = load(examples_copy / "uis2-concrete.xmi")
    use = next(n for n in document.root.nodes if isinstance(n, scm.ModuleUse))
    assert use.definition.name == "CrossingManeuver"
    assert (
        document.file_of(use.definition) == (examples_copy / "library/sceml-library.xmi").resolve()
    )


def test_moving_scenario_and_library_together_keeps_references(
    examples_copy: Path, tmp_path: Path
) -> None:
    moved = tmp_path / "elsewhere" / "deeper"
    shutil.copytree(examples_copy, moved)
    use = next(
        n for n in load(moved / "uis2-logical.xmi").root.nodes if isinstance(n, scm.ModuleUse)
    )
    assert [r.name for r in use.definition.roles] == ["crosser", "trigger"]


def test_save_elsewhere_rewrites_relative_hrefs(examples_copy: Path, tmp_path: Path) -> None:
    document = load(examples_copy / "uis2-concrete.xmi")
    target = tmp_path / "out" / "nested" / "copy.xmi"
    save(document.root, target)
    assert 'href="../../examples/library/sceml-library.xmi#CrossingManeuver"' in target.read_text()
    reloaded = load(target, allowed_roots=[tmp_path])
    use = next(n for n in reloaded.root.nodes if isinstance(n, scm.ModuleUse))
    assert use.definition.name == "CrossingManeuver"


def test_library_change_is_seen_by_the_scenario(examples_copy: Path) -> None:
    library = load(examples_copy / "library" / "sceml-library.xmi")
    library.root.modules[0].description = "changed in the library"
    save(library.root, examples_copy / "library" / "sceml-library.xmi")
    use = next(
        n
        for n in load(examples_copy / "uis2-concrete.xmi").root.nodes
        if isinstance(n, scm.ModuleUse)
    )
    assert use.definition.description == "changed in the library"


def test_line_of_elements(examples_copy: Path) -> None:
    path = examples_copy / "uis1-concrete.xmi"
    document = load(path)
    lines = path.read_text().splitlines()
    for node in document.root.nodes:
        line = document.line_of(node)
        assert line is not None and f'name="{node.name}"' in lines[line - 1]


def test_model_path_and_fragment(examples_copy: Path) -> None:
    document = load(examples_copy / "uis2-concrete.xmi")
    ego = document.root.nodes[0].actors[0]
    assert model_path(ego.initialSpeed) == "Root/ego/initialSpeed"
    assert uri_fragment(ego) == "//@nodes.0/@actors.0"


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(LoadError, match="no such file"):
        load(tmp_path / "absent.xmi")


def test_malformed_xml_names_file_and_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.xmi"
    bad.write_text(
        '<?xml version="1.0"?>\n<scemlmodel:Scenario xmlns:scemlmodel="https://sceml.org/metamodel/1.2">\n<nodes>\n'
    )
    with pytest.raises(LoadError) as caught:
        load(bad)
    assert caught.value.file == str(bad) and caught.value.line is not None
    assert str(caught.value).startswith(f"{bad}:")


def test_doctype_is_refused_without_expansion(tmp_path: Path) -> None:
    bomb = tmp_path / "bomb.xmi"
    entities = "".join(f'<!ENTITY e{i} "&e{i - 1};&e{i - 1};">' for i in range(1, 30))
    bomb.write_text(
        f'<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY e0 "ha">{entities}]>\n<x>&e29;</x>'
    )
    with pytest.raises(LoadError, match="DTD") as caught:
        load(bomb)
    assert caught.value.line == 2


def test_wrong_root_element(tmp_path: Path) -> None:
    other = tmp_path / "flow.xmi"
    other.write_text(
        '<?xml version="1.0"?>\n<scemlmodel:Flow xmlns:xmi="http://www.omg.org/XMI" '
        'xmlns:scemlmodel="https://sceml.org/metamodel/1.2" xmi:version="2.0"/>\n'
    )
    with pytest.raises(LoadError, match="expected a Scenario or Library"):
        load(other)


def test_load_scenario_refuses_a_library() -> None:
    with pytest.raises(LoadError, match="expected a scenario"):
        load_scenario(EXAMPLES / "library" / "sceml-library.xmi")


def test_reference_outside_allowed_folders_is_refused(examples_copy: Path, tmp_path: Path) -> None:
    document = load(examples_copy / "uis2-concrete.xmi", allowed_roots=[tmp_path / "nowhere"])
    problems = list(unresolved_references(document.root))
    assert len(problems) == 1 and "allowed folders" in problems[0][2]


def test_network_reference_is_never_fetched(examples_copy: Path) -> None:
    path = examples_copy / "uis2-concrete.xmi"
    path.write_text(
        path.read_text().replace("library/sceml-library.xmi", "http://192.0.2.1/lib.xmi")
    )
    problems = list(unresolved_references(load(path).root))
    assert len(problems) == 1 and "only local files" in problems[0][2]


def test_save_is_atomic_when_serialisation_fails(examples_copy: Path, monkeypatch) -> None:
    path = examples_copy / "uis1-concrete.xmi"
    before = path.read_bytes()
    document = load(path)

    def explode(*args, **kwargs):
        raise RuntimeError("disk on fire")

    monkeypatch.setattr(document.resource, "save", explode)
    with pytest.raises(SaveError):
        save(document.root, path)
    assert path.read_bytes() == before
    assert [p.name for p in path.parent.iterdir() if p.name.endswith(".tmp")] == []


def test_write_atomically_leaves_no_partial_file(tmp_path: Path, monkeypatch) -> None:
    target = tmp_path / "out.xmi"
    target.write_bytes(b"good")

    def failing_replace(source, destination):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", failing_replace)
    with pytest.raises(SaveError, match="No space left"):
        write_atomically(target, b"new content")
    assert target.read_bytes() == b"good"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.xmi"]


def test_save_elsewhere_keeps_the_map_reachable(examples_copy: Path, tmp_path: Path) -> None:
    document = load(examples_copy / "uis1-concrete.xmi")
    target = tmp_path / "out" / "nested" / "uis1.xmi"
    save(document.root, target)
    saved = load(target, allowed_roots=[tmp_path]).root.nodes[0]
    assert saved.map == "../../maps/intersection.xodr"
    assert (target.parent / saved.map).resolve() == (tmp_path / "maps/intersection.xodr").resolve()
    # The model in memory, and a save in place, keep the original path.
    assert document.root.nodes[0].map == "../maps/intersection.xodr"
    save(document.root, examples_copy / "uis1-concrete.xmi")
    assert 'map="../maps/intersection.xodr"' in (examples_copy / "uis1-concrete.xmi").read_text()


def test_lines_are_those_of_the_file_as_read_after_the_model_changes() -> None:
    # The parse tree is not kept; each object keeps the line it was read from, so an edit (the
    # editor's) does not shift the lines reported for the objects after it.
    path = EXAMPLES / "uis1-concrete.xmi"
    document = load(path)
    text = path.read_text(encoding="utf-8").splitlines()
    nodes = list(document.root.nodes)
    before = {node: document.line_of(node) for node in nodes}
    for node, line in before.items():
        assert line is not None and f'name="{node.name}"' in text[line - 1]
    document.root.nodes.remove(nodes[1])
    added = scm.KeepVelocity(name="Added")
    document.root.nodes.append(added)
    assert [document.line_of(node) for node in nodes[2:]] == [before[n] for n in nodes[2:]]
    assert document.line_of(added) is None
    assert document.resource.sceml_tree is None  # only the lines were kept


_TWO_PROBLEMS = """<?xml version='1.0' encoding='UTF-8'?>
<scemlmodel:Scenario xmlns:xmi="http://www.omg.org/XMI" xmlns:scemlmodel="{ns}"
    xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xmi:version="2.0">
  <nodes xsi:type="scemlmodel:RootNode" name="Root" level="concrete">
    <actors xsi:type="scemlmodel:Car" xmi:id="a1" name="ego"/>
    <actors xsi:type="scemlmodel:Car" xmi:id="a1" name="other"/>
    <actors xsi:type="scemlmodel:Car" xmi:id="a1" name="third"/>
  </nodes>
  <nodes xsi:type="scemlmodel:{kind}" name="End"/>
</scemlmodel:Scenario>
"""


@pytest.mark.parametrize(
    ("kind", "line", "words"),
    [
        # A wrong type is reported before a repeated id, even one on an earlier line.
        ("Teleport", 9, "Teleport"),
        # Else the first repetition, naming the line of the first use.
        ("EndNode", 6, "duplicate xmi:id 'a1' (first on line 5)"),
    ],
)
def test_a_wrong_type_comes_before_a_repeated_id(
    tmp_path: Path, kind: str, line: int, words: str
) -> None:
    path = tmp_path / "two-problems.xmi"
    path.write_text(_TWO_PROBLEMS.format(ns=scm.nsURI, kind=kind), encoding="utf-8")
    with pytest.raises(LoadError) as caught:
        load(path)
    assert caught.value.line == line
    assert words in caught.value.message

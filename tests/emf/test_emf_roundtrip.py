"""Real Eclipse EMF reads what SceML writes and SceML reads what EMF writes, with nothing lost."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from metamodel_releases import CURRENT

from sceml.model.compare import differences
from sceml.model.loading import load, unresolved_references
from sceml.model.saving import save

from .conftest import ECORE, REPO, Harness

EXAMPLES = REPO / "examples"
EXAMPLE_FILES = sorted(
    p.relative_to(EXAMPLES)
    for p in [*EXAMPLES.glob("*.xmi"), *(EXAMPLES / "library").glob("*.xmi")]
)


@pytest.fixture(scope="module")
def emf_written(emf: Harness, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Every example, loaded by EMF with references resolved, validated and saved by EMF."""
    out = tmp_path_factory.mktemp("emf-written")
    result = emf.run("roundtrip", ECORE, EXAMPLES, out, *EXAMPLE_FILES)
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    return out


def test_metamodel_passes_emf_diagnostician(emf: Harness) -> None:
    result = emf.run("check-ecore", ECORE)
    assert result.stdout.splitlines() == [
        f"PACKAGE scemlmodel https://sceml.org/metamodel/{CURRENT}"
    ]


def test_diagnostician_is_able_to_complain(emf: Harness, tmp_path: Path) -> None:
    # A metamodel with a class that names an undefined supertype must not pass.
    broken = tmp_path / "broken.ecore"
    broken.write_text(
        ECORE.read_text().replace('eSuperTypes="#//Graph"', 'eSuperTypes="#//Grahp"', 1)
    )
    result = emf.run("check-ecore", broken, check=False)
    assert result.returncode != 0


def test_emf_saved_every_example_and_the_library(emf_written: Path) -> None:
    assert sorted(p.relative_to(emf_written) for p in emf_written.rglob("*.xmi")) == EXAMPLE_FILES
    assert (
        'href="library/sceml-library.xmi#CrossingManeuver"'
        in (emf_written / "uis2-concrete.xmi").read_text()
    )


@pytest.mark.parametrize("name", EXAMPLE_FILES, ids=str)
def test_emf_written_file_reads_back_equal_in_sceml(emf_written: Path, name: Path) -> None:
    original = load(EXAMPLES / name)
    from_emf = load(emf_written / name)
    assert differences(original.root, from_emf.root) == []
    assert list(unresolved_references(from_emf.root)) == []


@pytest.mark.parametrize("name", EXAMPLE_FILES, ids=str)
def test_sceml_rewrite_of_emf_file_reads_back_equal_in_emf(
    emf: Harness, emf_written: Path, tmp_path: Path, name: Path
) -> None:
    # EMF wrote it, pyecore reads and writes it, EMF reads both and compares them. Both folders
    # sit side by side, so the relative map path (rebased by save) reads the same in both.
    source, rewritten = tmp_path / "emf", tmp_path / "rewritten"
    shutil.copytree(emf_written, source)
    for library in (source / "library").glob("*.xmi"):
        save(load(library).root, rewritten / "library" / library.name)
    document = load(source / name, allowed_roots=[source])
    save(document.root, rewritten / name)
    result = emf.run("compare", ECORE, source / name, rewritten / name)
    assert result.stdout.strip() == "EQUAL"


def test_emf_compare_sees_a_real_change(emf: Harness, emf_written: Path, tmp_path: Path) -> None:
    changed = tmp_path / "changed"
    shutil.copytree(emf_written, changed)
    path = changed / "uis1-concrete.xmi"
    path.write_text(path.read_text().replace('value="8.0"', 'value="8.5"', 1))
    result = emf.run("compare", ECORE, emf_written / "uis1-concrete.xmi", path, check=False)
    assert result.returncode == 1
    assert "DIFF /[0]/nodes[2]/targetSpeed[0]/value: [8.0] != [8.5]" in result.stdout

"""Real Eclipse EMF, with the current .ecore, reads files that `sceml migrate` wrote from every
kept release's material, and writes them back so that SceML reads the same model."""

from __future__ import annotations

import shutil
from pathlib import Path

from sceml.model.compare import differences
from sceml.model.loading import load
from sceml.model.migrating import migrate_file

from .conftest import ECORE, REPO, Harness

HISTORY = REPO / "metamodel" / "history"


def test_emf_reads_migrated_files_of_every_release(emf: Harness, tmp_path: Path) -> None:
    for release in sorted(p for p in HISTORY.iterdir() if (p / "examples").is_dir()):
        source, out = tmp_path / release.name / "in", tmp_path / release.name / "out"
        shutil.copytree(release / "examples", source)
        shutil.copytree(release / "maps", source.parent / "maps")
        files = sorted(p.relative_to(source) for p in source.rglob("*.xmi"))
        for name in files:
            migrate_file(source / name)
        (out / "library").mkdir(parents=True)
        result = emf.run("roundtrip", ECORE, source, out, *files)
        assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
        for name in files:
            assert differences(load(source / name).root, load(out / name).root) == []


def test_emf_refuses_an_unmigrated_older_file(emf: Harness, tmp_path: Path) -> None:
    # Why `sceml migrate` exists: EMF knows only the release it is given.
    shutil.copytree(HISTORY / "1.0" / "examples", tmp_path / "in")
    (tmp_path / "out").mkdir()
    result = emf.run(
        "roundtrip",
        ECORE,
        tmp_path / "in",
        tmp_path / "out",
        Path("uis1-functional.xmi"),
        check=False,
    )
    assert result.returncode != 0
    assert "Package with uri 'https://sceml.org/metamodel/1.0' not found" in result.stdout

"""Files saved with every kept release load, validate, export as before, and migrate on disk."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from metamodel_releases import CURRENT, METAMODEL, REPO

import scemlmodel as scm
from sceml.errors import LoadError
from sceml.export.writer import export_to_file
from sceml.migrations import check_release, installed
from sceml.model.compare import differences
from sceml.model.loading import load, load_scenario
from sceml.model.migrating import migrate_file
from sceml.validation import validate
from sceml.validation.engine import Severity

RELEASES = sorted(p.parent for p in (METAMODEL / "history").glob("*/scemlmodel.ecore"))
MATERIAL = sorted(
    path
    for release in RELEASES
    for path in [*release.glob("examples/*.xmi"), *release.glob("examples/library/*.xmi")]
)


def _id(path: Path) -> str:
    return str(path.relative_to(METAMODEL / "history"))


def test_release_1_0_is_kept_with_its_material() -> None:
    kept = METAMODEL / "history" / "1.0"
    assert 'nsURI="https://sceml.org/metamodel/1.0"' in (kept / "scemlmodel.ecore").read_text()
    names = {p.name for p in (kept / "examples").glob("*.xmi")}
    assert {"uis1-concrete.xmi", "uis2-logical.xmi", "overtaking-functional.xmi"} <= names
    assert (kept / "examples" / "library" / "sceml-library.xmi").is_file()


def test_the_current_release_is_newer_than_1_0_and_the_package_says_which() -> None:
    assert scm.nsURI == f"https://sceml.org/metamodel/{CURRENT}"
    assert installed().current.version == CURRENT != "1.0"
    assert check_release().problems == []


@pytest.mark.parametrize("path", MATERIAL, ids=_id)
def test_old_files_load_migrated_and_validate_clean(path: Path) -> None:
    document = load(path)
    if f'{scm.nsURI}"' not in path.read_text():
        report = document.migration
        assert report is not None and report.to_release == installed().current.version
        assert report.from_release == path.relative_to(METAMODEL / "history").parts[0]
    errors = [d for d in validate(document.root, document=document) if d.severity >= Severity.ERROR]
    assert errors == []


#: Every kept export: (the export, the example it was made from, version, profile).
EXPORTS = [
    (export, export.parent.parent / "examples" / f"{stem}.xmi", suffix)
    for export in sorted((METAMODEL / "history").glob("*/exports/*.xosc"))
    for stem, _, suffix in [export.stem.rpartition("-")]
]


def _export(source: Path, target: Path, suffix: str) -> bytes:
    version, profile = ("1.0", "carla") if suffix == "carla" else (suffix, "generic")
    document = load_scenario(source)
    written = export_to_file(
        document.root, target, version=version, profile=profile, source_path=source
    )
    return written.read_bytes()


@pytest.mark.parametrize(
    ("before", "source", "suffix"), EXPORTS, ids=lambda v: getattr(v, "name", v)
)
def test_a_migrated_example_exports_as_the_current_release_does(
    before: Path, source: Path, suffix: str, tmp_path: Path
) -> None:
    """The export of an old file, migrated in memory, is byte for byte the export of the same
    scenario saved with the current release (the examples as the current build writes them),
    written to the same place beside the same map.

    `before` (what that release's SceML wrote) is kept for people to compare by hand: the
    exporter itself has changed since (docs/openscenario-mapping.md), so it is not the yardstick
    of the migration.
    """
    old = tmp_path / "old"
    shutil.copytree(before.parent.parent, old, ignore=shutil.ignore_patterns("exports"))
    new = tmp_path / "new"
    shutil.copytree(REPO / "examples", new / "examples")
    shutil.copytree(REPO / "maps", new / "maps")
    for project in (old, new):
        (project / ".sceml-root").touch()
    migrated = load_scenario(old / "examples" / source.name)
    current = load_scenario(new / "examples" / source.name)
    if differences(migrated.root, current.root):
        pytest.skip(
            f"examples/{source.name} changed since release {migrated.migration.from_release}"
        )
    assert _export(old / "examples" / source.name, old / "exports" / before.name, suffix) == (
        _export(new / "examples" / source.name, new / "exports" / before.name, suffix)
    )


def test_kept_exports_are_what_release_1_0_wrote() -> None:
    # The yardstick for people: each kept export names its map beside the release's examples.
    kept = sorted((METAMODEL / "history" / "1.0" / "exports").glob("*.xosc"))
    assert len(kept) == 7
    for export in kept:
        text = export.read_text()
        assert '<LogicFile filepath="../maps/intersection.xodr"/>' in text
        assert 'revMajor="1"' in text


def test_migrate_writes_current_files_that_load_without_migration(tmp_path: Path) -> None:
    examples = tmp_path / "examples"
    shutil.copytree(METAMODEL / "history" / "1.0" / "examples", examples)
    shutil.copytree(METAMODEL / "history" / "1.0" / "maps", tmp_path / "maps")
    (tmp_path / ".sceml-root").touch()
    for path in sorted(examples.rglob("*.xmi")):
        outcome = migrate_file(path, backup=True)
        assert outcome.report is not None and outcome.written == path
        assert outcome.backup is not None and outcome.backup.read_bytes().count(b"metamodel/1.0")
    for path in sorted(examples.rglob("*.xmi")):
        assert f'xmlns:scemlmodel="{scm.nsURI}"'.encode() in path.read_bytes()
        document = load(path)
        assert document.migrations() == []


def test_rewritten_examples_equal_what_sceml_writes_today(tmp_path: Path) -> None:
    # Release 1.1 changed nothing a file holds but the namespace, so a migrated 1.0 example is
    # the example as the current build writes it, where the example itself did not change.
    source = METAMODEL / "history" / "1.0" / "examples" / "uis1-concrete.xmi"
    target = tmp_path / "examples" / "uis1-concrete.xmi"
    shutil.copytree(source.parent, target.parent)
    migrate_file(target)
    assert target.read_bytes() == (REPO / "examples" / "uis1-concrete.xmi").read_bytes()


def test_a_newer_release_than_this_sceml_is_refused(tmp_path: Path) -> None:
    newer = tmp_path / "newer.xmi"
    newer.write_text(
        (REPO / "examples" / "uis1-functional.xmi")
        .read_text()
        .replace(scm.nsURI, "https://sceml.org/metamodel/7.0")
    )
    with pytest.raises(
        LoadError, match=f"release 7.0, newer than this SceML's {CURRENT}"
    ) as caught:
        load(newer)
    assert caught.value.line == 2


def test_an_unknown_old_release_is_refused(tmp_path: Path) -> None:
    odd = tmp_path / "odd.xmi"
    odd.write_text(
        (REPO / "examples" / "uis1-functional.xmi")
        .read_text()
        .replace(scm.nsURI, "https://sceml.org/metamodel/0.9")
    )
    with pytest.raises(LoadError, match="release 0.9, which no SceML released"):
        load(odd)

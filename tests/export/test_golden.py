"""Golden files: UIS1 and UIS2 in every version (generic) and in 1.0 (carla), byte for byte."""

from __future__ import annotations

import difflib
from pathlib import Path

import pytest

from sceml.export import build_xosc
from sceml.files.writing import write_atomically
from sceml.model.loading import load_scenario
from sceml.xosc import schema
from sceml.xosc.qualitychecker import run_quality_checker

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
GOLDEN = Path(__file__).resolve().parent / "golden"

CASES = [
    (name, version, "generic")
    for name in ("uis1", "uis2")
    for version in ("1.0", "1.1", "1.2", "1.3")
]
CASES += [(name, "1.0", "carla") for name in ("uis1", "uis2")]


def golden_path(name: str, version: str, profile: str) -> Path:
    return GOLDEN / f"{name}-{version}-{profile}.xosc"


def exported(name: str, version: str, profile: str) -> bytes:
    source = EXAMPLES / f"{name}-concrete.xmi"
    town = "Town03" if profile == "carla" else None
    document = build_xosc(
        load_scenario(source).root,
        version=version,
        profile=profile,
        source_path=source,
        output_path=golden_path(name, version, profile),
        town=town,
    )
    return document.data


@pytest.mark.parametrize(("name", "version", "profile"), CASES)
def test_export_matches_golden(name: str, version: str, profile: str, update_golden: bool) -> None:
    path = golden_path(name, version, profile)
    data = exported(name, version, profile)
    if update_golden:
        write_atomically(path, data)
    expected = path.read_text(encoding="utf-8").splitlines(keepends=True)
    actual = data.decode("utf-8").splitlines(keepends=True)
    diff = "".join(difflib.unified_diff(expected, actual, str(path), "exported", n=2))
    assert not diff, f"export differs from {path.name} (rerun with --update-golden):\n{diff}"


@pytest.mark.parametrize(("name", "version", "profile"), CASES)
def test_golden_passes_the_xsd_of_its_version(name: str, version: str, profile: str) -> None:
    path = golden_path(name, version, profile)
    assert schema.declared_version(schema.parse_file(path)) == version
    assert schema.validate_file(path) == []


@pytest.mark.parametrize(
    ("name", "version"), [(n, v) for n in ("uis1", "uis2") for v in ("1.2", "1.3")]
)
def test_golden_has_no_quality_checker_issues(name: str, version: str) -> None:
    report = run_quality_checker(golden_path(name, version, "generic"))
    assert report.ok, [str(issue) for issue in report.issues]
    assert not report.skipped_below_1_2


def test_export_is_deterministic() -> None:
    assert exported("uis2", "1.3", "generic") == exported("uis2", "1.3", "generic")


def test_generic_goldens_refer_to_the_project_map() -> None:
    for name, version, profile in CASES:
        tree = schema.parse_file(golden_path(name, version, profile))
        logic = tree.getroot().find("RoadNetwork/LogicFile").get("filepath")
        if profile == "carla":
            assert logic == "Town03"
        else:
            assert (GOLDEN / logic).resolve() == REPO / "maps" / "intersection.xodr"

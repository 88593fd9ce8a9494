"""The release check CI runs: a breaking change to the .ecore needs its migration step."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from metamodel_releases import (
    CURRENT,
    HISTORY_10,
    METAMODEL,
    NEXT,
    edit_ecore,
    load_with_ecore,
    migrated_copy,
    next_release,
)

from sceml.migrations import History, check_release


def _rename_drive_distance(text: str) -> str:
    # DriveDistance.distance -> length: the feature is declared on DriveDistance alone.
    start = text.index('name="DriveDistance"')
    at = text.index('name="distance"', start)
    return text[:at] + 'name="length"' + text[at + len('name="distance"') :]


def test_the_repository_passes() -> None:
    result = check_release(History(METAMODEL))
    assert result.problems == []
    assert result.last_release == CURRENT  # the current release is kept in history/


def test_the_cli_check_passes_on_the_repository() -> None:
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "sceml.cli",
            "dev",
            "check-release",
            "--root",
            str(METAMODEL.parent),
        ],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    assert f"metamodel release {CURRENT}" in run.stdout


def test_an_additive_change_passes_without_a_release(metamodel_copy: Path) -> None:
    history = edit_ecore(
        metamodel_copy,
        lambda text: text.replace(
            '<eClassifiers xsi:type="ecore:EClass" name="Stop"',
            '<eClassifiers xsi:type="ecore:EClass" name="Honk" eSuperTypes="#//Condition"/>\n'
            '  <eClassifiers xsi:type="ecore:EClass" name="Stop"',
            1,
        ),
    )
    assert check_release(history).problems == []


def test_a_renamed_feature_fails_naming_it(metamodel_copy: Path) -> None:
    history = edit_ecore(metamodel_copy, _rename_drive_distance)
    problems = check_release(history).problems
    assert len(problems) == 1
    assert "DriveDistance.distance was removed or renamed" in problems[0]
    assert "raise the release" in problems[0]


def test_a_new_release_without_the_operation_still_fails(metamodel_copy: Path) -> None:
    history = next_release(metamodel_copy, _rename_drive_distance, "operations: []\n")
    problems = check_release(history).problems
    assert len(problems) == 1
    assert "DriveDistance.distance" in problems[0] and f"{CURRENT}-to-{NEXT}.yaml" in problems[0]


def test_a_new_release_without_a_step_fails(metamodel_copy: Path) -> None:
    history = next_release(metamodel_copy, _rename_drive_distance, None)
    assert any(
        f"no migration step from release {CURRENT} to {NEXT}" in p
        for p in check_release(history).problems
    )


def test_the_migration_makes_it_pass_and_old_files_load(
    metamodel_copy: Path, tmp_path: Path
) -> None:
    history = next_release(
        metamodel_copy,
        _rename_drive_distance,
        "operations:\n  - rename_feature: {class: DriveDistance, from: distance, to: length}\n",
    )
    assert check_release(history).problems == []
    # A 1.0 file goes through every step and loads with the next metamodel, value kept.
    source = HISTORY_10 / "examples" / "uis2-concrete.xmi"
    target, report = migrated_copy(source, tmp_path / "uis2.xmi", history)
    assert report is not None and (report.from_release, report.to_release) == ("1.0", NEXT)
    [change] = report.changes
    assert (change.operation, change.element, change.line, change.detail) == (
        "rename_feature",
        "DriveDistance_1",
        60,
        "distance -> length",
    )
    scenario = load_with_ecore(metamodel_copy / "scemlmodel.ecore", target)
    drive = next(n for n in scenario.nodes if n.eClass.name == "DriveDistance")
    assert drive.length.value == 60.0


def test_the_package_must_record_its_release(metamodel_copy: Path) -> None:
    history = edit_ecore(
        metamodel_copy,
        lambda text: text.replace(f'key="version" value="{CURRENT}"', 'key="version" value="1.0"'),
    )
    assert any("records release '1.0'" in p for p in check_release(history).problems)


def test_a_step_naming_what_the_release_lacks_fails(metamodel_copy: Path) -> None:
    history = next_release(
        metamodel_copy,
        _rename_drive_distance,
        "operations:\n  - rename_feature: {class: DriveDistance, from: distance, to: length}\n"
        "  - rename_feature: {class: Follow, from: gap, to: distance}\n",
    )
    assert any(
        f"Follow has no feature 'gap' in release {CURRENT}" in p
        for p in check_release(history).problems
    )

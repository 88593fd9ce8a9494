"""Files that concretize, promote and sample write into another folder can be read back by every
command: references may reach the input's folder, its project root (the nearest folder above
with a VCS checkout or a `.sceml-root` marker) and every folder given with `--allow`."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from sceml.cli import cli
from sceml.files.safefiles import reading_roots
from sceml.model.loading import load
from sceml.model.saving import save

UIS2_VALUES = [
    "ego.initialSpeed=5",
    "Accelerate_1.targetSpeed=7",
    "InLocationRadius_2.radius=4",
    "DriveDistance_1.speed=10",
    "CrossingManeuver_1.triggerRadius=15",
    "CrossingManeuver_1.crossingSpeed=1.5",
]


def sceml(*arguments: object) -> Result:
    result = CliRunner().invoke(cli, [str(a) for a in arguments])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {arguments}") from result.exception
    return result


def concretize(examples: Path, output: Path) -> None:
    settings = [item for value in UIS2_VALUES for item in ("--set", value)]
    result = sceml("concretize", examples / "uis2-logical.xmi", *settings, "-o", output)
    assert result.exit_code == 0, result.output


#: Every command that reads a model, run on `file` with the extra arguments given.
READERS: dict[str, Callable[[Path, Path], list[object]]] = {
    "info": lambda file, out: ["info", file],
    "validate": lambda file, out: ["validate", file],
    "export": lambda file, out: ["export", file, "-o", out / "a.xosc"],
    "render": lambda file, out: ["render", file, "-o", out / "a.svg"],
    "report": lambda file, out: ["report", file, "-o", out / "a.html"],
    "flatten": lambda file, out: ["flatten", file, "-o", out / "flat.xmi"],
    "module extract": lambda file, out: [
        "module",
        "extract",
        file,
        "--nodes",
        "Accelerate_1",
        "--name",
        "Speedup",
        "--into",
        out / "lib.xmi",
        "-o",
        out / "extracted.xmi",
    ],
}


@pytest.mark.parametrize("command", sorted(READERS))
def test_a_concretized_file_in_another_folder_of_the_project_is_read_back(
    examples_copy: Path, command: str
) -> None:
    project = examples_copy.parent
    (project / ".git").mkdir()  # the project's root, as a checkout marks it
    derived = project / "out" / "uis2-c.xmi"
    concretize(examples_copy, derived)
    result = sceml(*READERS[command](derived, project / "out"))
    assert result.exit_code == 0, result.output


def test_the_sceml_root_marker_marks_a_project(examples_copy: Path) -> None:
    project = examples_copy.parent
    (project / ".sceml-root").touch()
    derived = project / "out" / "uis2-c.xmi"
    concretize(examples_copy, derived)
    assert sceml("export", derived, "-o", project / "a.xosc").exit_code == 0


@pytest.mark.parametrize("command", sorted(READERS))
def test_outside_a_project_allow_names_the_library_folder(
    examples_copy: Path, command: str
) -> None:
    project = examples_copy.parent
    (project / ".sceml-root").unlink()  # no project: only the file's folder is allowed
    derived = project / "out" / "uis2-c.xmi"
    concretize(examples_copy, derived)
    denied = sceml(*READERS[command](derived, project / "out"))
    assert denied.exit_code != 0
    page = project / "out" / "a.html"  # the report shows its diagnostics in the page
    said = denied.output + (page.read_text() if page.exists() else "")
    assert "leaves the allowed folders" in said and "--allow" in said, said
    arguments = READERS[command](derived, project / "out")
    # The library, and the map the examples name from a sibling folder (../maps).
    allowed = sceml(*arguments, "--allow", examples_copy / "library", "--allow", project / "maps")
    assert allowed.exit_code == 0, allowed.output


def test_sampled_and_promoted_files_are_read_back(examples_copy: Path) -> None:
    project = examples_copy.parent
    (project / ".hg").mkdir()
    samples = project / "samples"
    result = sceml(
        "sample", examples_copy / "uis2-logical.xmi", "--n", "2", "--format", "xmi", "-o", samples
    )
    assert result.exit_code == 0, result.output
    for sample in sorted(samples.glob("*.xmi")):
        assert sceml("validate", sample).exit_code == 0, sample
    promoted = project / "out" / "uis1-promoted.xmi"
    result = sceml(
        "promote",
        examples_copy / "uis1-functional.xmi",
        "--ranges",
        examples_copy / "uis1-ranges.yaml",
        "-o",
        promoted,
    )
    assert result.exit_code == 0, result.output
    assert sceml("validate", promoted).exit_code == 0


@pytest.mark.parametrize(
    "arguments",
    [
        ["sample", "--n", "1", "--workers", "1"],
        ["export-distribution"],
        ["concretize", *[a for v in UIS2_VALUES for a in ("--set", v)]],
    ],
    ids=["sample", "export-distribution", "concretize"],
)
def test_commands_on_logical_files_take_allow(examples_copy: Path, arguments: list[str]) -> None:
    (examples_copy.parent / ".sceml-root").unlink()  # no project: only the file's folder
    logical = examples_copy / "sub" / "uis2-logical.xmi"
    save(load(examples_copy / "uis2-logical.xmi").root, logical)  # refers to ../library
    command, *options = arguments
    out = examples_copy.parent / "out" / ("c.xmi" if command == "concretize" else "")
    denied = sceml(command, logical, *options, "-o", out)
    assert denied.exit_code != 0 and "--allow" in denied.output, denied.output
    library, maps = examples_copy / "library", examples_copy.parent / "maps"
    allowed = sceml(command, logical, *options, "-o", out, "--allow", library, "--allow", maps)
    assert allowed.exit_code == 0, allowed.output


def test_reading_roots_is_the_one_rule(tmp_path: Path) -> None:
    (tmp_path / ".git").mkdir()
    file = tmp_path / "a" / "b" / "s.xmi"
    extra = tmp_path.parent
    assert reading_roots(file, [extra]) == [file.parent, tmp_path, extra]
    (tmp_path / "a" / ".sceml-root").parent.mkdir(parents=True)
    (tmp_path / "a" / ".sceml-root").touch()
    assert reading_roots(file) == [file.parent, tmp_path / "a"]

"""An output that cannot be written (its parent is a file, a read-only file system, no
permission) is a clean error on every writing command: exit 1, `OUT: cannot write: reason`, no
traceback and nothing left behind."""

from __future__ import annotations

import errno
import os
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from sceml.cli import cli, commands

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
UIS1 = EXAMPLES / "uis1-concrete.xmi"
LOGICAL = EXAMPLES / "uis1-logical.xmi"
CONCRETE_VALUES = [
    "--set",
    "ego.initialSpeed=5",
    "--set",
    "Accelerate_1.targetSpeed=8",
    "--set",
    "InVehicleRadius_1.radius=12",
    "--set",
    "Accelerate_2.targetSpeed=4",
]

#: Every command that writes a file, given the output path `out` (a file or a folder).
WRITERS: dict[str, Callable[[Path], list[str]]] = {
    "export": lambda out: ["export", str(UIS1), "-o", str(out / "a.xosc")],
    "render": lambda out: ["render", str(UIS1), "-o", str(out / "a.svg")],
    "report": lambda out: ["report", str(UIS1), "-o", str(out / "a.html")],
    "flatten": lambda out: ["flatten", str(UIS1), "-o", str(out / "a.xmi")],
    "migrate": lambda out: ["migrate", str(UIS1), "-o", str(out / "a.xmi")],
    "concretize": lambda out: ["concretize", str(LOGICAL), *CONCRETE_VALUES, "-o", str(out / "a")],
    "promote": lambda out: [
        "promote",
        str(EXAMPLES / "uis1-functional.xmi"),
        "--ranges",
        str(EXAMPLES / "uis1-ranges.yaml"),
        "-o",
        str(out / "a.xmi"),
    ],
    "sample": lambda out: ["sample", str(LOGICAL), "--n", "2", "--workers", "1", "-o", str(out)],
    "export-distribution": lambda out: ["export-distribution", str(LOGICAL), "-o", str(out)],
    "module extract": lambda out: [
        "module",
        "extract",
        str(UIS1),
        "--nodes",
        "Accelerate_1",
        "--name",
        "Speedup",
        "--into",
        str(out / "lib.xmi"),
        "-o",
        str(out / "a.xmi"),
    ],
    "simulate": lambda out: ["simulate", str(UIS1), "-o", str(out / "run.html")],
    "explore": lambda out: ["explore", str(LOGICAL), "--budget", "2", "--top", "1", "-o", str(out)],
    "validate": lambda out: ["validate", str(UIS1), "-o", str(out / "report.txt")],
    "diff": lambda out: ["diff", str(UIS1), str(LOGICAL), "-o", str(out / "d.txt")],
    "merge": lambda out: ["merge", str(UIS1), str(UIS1), str(UIS1), "-o", str(out / "m.xmi")],
    "import": lambda out: [
        "import",
        str(Path(__file__).resolve().parents[1] / "export/golden/uis1-1.3-generic.xosc"),
        "-o",
        str(out / "a.xmi"),
    ],
    "extract": lambda out: [
        "extract",
        str(Path(__file__).resolve().parents[1] / "extract/data/uis1-esmini.csv"),
        "--map",
        str(EXAMPLES.parent / "maps" / "intersection.xodr"),
        "-o",
        str(out / "a.xmi"),
    ],
    "check-xosc": lambda out: [
        "check-xosc",
        "--no-quality-checker",
        str(Path(__file__).resolve().parents[1] / "export/golden/uis1-1.3-generic.xosc"),
        "-o",
        str(out / "report.txt"),
    ],
}


def _files(folder: Path) -> list[Path]:
    return sorted(folder.rglob("*"))


def _check(arguments: list[str], tmp_path: Path, before: list[Path], reason: str) -> None:
    result = CliRunner().invoke(cli, arguments)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {arguments}") from result.exception
    assert result.exit_code == 1, result.output
    assert "cannot write" in result.output and reason in result.output, result.output
    assert "Traceback" not in result.output
    assert _files(tmp_path) == before


def _leaves(name: str, command: click.Command) -> Iterator[tuple[str, click.Command]]:
    if isinstance(command, click.Group):
        context = click.Context(command)
        for child in command.list_commands(context):
            found = command.get_command(context, child)
            assert found is not None
            yield from _leaves(f"{name} {child}", found)
    else:
        yield name, command


def test_every_writing_command_is_listed() -> None:
    # Read from the CLI's registry: every command with an -o option writes what it names.
    writers = {
        name
        for top, command in commands().items()
        for name, leaf in _leaves(top, command)
        if any("-o" in p.opts for p in leaf.params if isinstance(p, click.Option))
    }
    # dev class-diagram writes the metamodel's pictures into the repository's docs folder.
    assert set(WRITERS) == writers - {"dev class-diagram"}


@pytest.mark.parametrize("command", sorted(WRITERS))
def test_output_below_a_file(tmp_path: Path, command: str) -> None:
    blocker = tmp_path / "blocker"
    blocker.write_text("a file, not a folder")
    before = _files(tmp_path)
    _check(WRITERS[command](blocker / "out"), tmp_path, before, "not a folder")


@pytest.mark.parametrize(
    ("error", "reason"),
    [
        (errno.EROFS, "Read-only file system"),
        (errno.EACCES, "Permission denied"),
    ],
)
@pytest.mark.parametrize("folders", [False, True], ids=["files", "files-and-folders"])
@pytest.mark.parametrize("command", sorted(WRITERS))
def test_output_on_a_file_system_that_refuses_writes(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    command: str,
    error: int,
    reason: str,
    folders: bool,
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    before = _files(tmp_path)

    def refuse(*args: object, **kwargs: object) -> object:
        raise OSError(error, os.strerror(error))

    # Every file SceML writes is first created as a temporary file beside its target; folders
    # are created with mkdir (and must be removed again when no file could be written in
    # them). Refusing both is what a read-only mount or a missing permission do.
    monkeypatch.setattr(tempfile, "mkstemp", refuse)
    if folders:
        monkeypatch.setattr(os, "mkdir", refuse)
    _check(WRITERS[command](out / "sub"), tmp_path, before, reason)

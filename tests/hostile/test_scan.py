"""Every command against every class of bad input: a missing input, an input that cannot be read
(a folder), a malformed one, a hostile one, an output that cannot be written, and every option
given a value its type refuses. Each gives the documented exit code (2 for unusable input or
arguments, 1 for an output that cannot be written), never a traceback, and leaves no file."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from sceml.cli import cli, commands
from sceml.cli.common import Parsed

from .test_corpus import deadline

HERE = Path(__file__).resolve().parent
CORPUS = HERE / "corpus"
EXAMPLES = HERE.parents[1] / "examples"
XOSC = HERE.parent / "export" / "golden" / "uis1-1.3-generic.xosc"
CONCRETE, LOGICAL = EXAMPLES / "uis1-concrete.xmi", EXAMPLES / "uis1-logical.xmi"
#: A recorded esmini log of UIS2 at 1.0, for `check-run`.
PLAYER_LOG = HERE.parent / "players" / "data" / "uis2-concrete-1.0.log.txt"
RECORDING = HERE.parent / "extract" / "data" / "uis1-esmini.csv"
MAP = EXAMPLES.parent / "maps" / "intersection.xodr"

#: Each command with good arguments: (input file, arguments after it, given the output folder).
COMMANDS: dict[str, tuple[Path, Callable[[Path], list[str]]]] = {
    "info": (CONCRETE, lambda out: []),
    "validate": (CONCRETE, lambda out: ["-o", str(out / "report.txt")]),
    "export": (CONCRETE, lambda out: ["-o", str(out / "a.xosc")]),
    "render": (CONCRETE, lambda out: ["-o", str(out / "a.svg")]),
    "report": (CONCRETE, lambda out: ["-o", str(out / "a.html")]),
    "flatten": (CONCRETE, lambda out: ["-o", str(out / "a.xmi")]),
    "migrate": (CONCRETE, lambda out: ["-o", str(out / "m.xmi")]),
    "check-xosc": (XOSC, lambda out: ["--no-quality-checker", "-o", str(out / "report.txt")]),
    "import": (XOSC, lambda out: ["-o", str(out / "i.xmi")]),
    "check-run": (EXAMPLES / "uis2-concrete.xmi", lambda out: ["--log", str(PLAYER_LOG)]),
    "extract": (RECORDING, lambda out: ["-o", str(out / "e.xmi"), "--map", str(MAP)]),
    "concretize": (
        LOGICAL,
        lambda out: [
            *("--set", "ego.initialSpeed=5", "--set", "Accelerate_1.targetSpeed=8"),
            *("--set", "InVehicleRadius_1.radius=12", "--set", "Accelerate_2.targetSpeed=4"),
            *("-o", str(out / "c.xmi")),
        ],
    ),
    "promote": (
        EXAMPLES / "uis1-functional.xmi",
        lambda out: ["--ranges", str(EXAMPLES / "uis1-ranges.yaml"), "-o", str(out / "p.xmi")],
    ),
    "sample": (LOGICAL, lambda out: ["--n", "2", "--workers", "1", "-o", str(out / "s")]),
    "export-distribution": (LOGICAL, lambda out: ["-o", str(out / "d")]),
    "simulate": (
        CONCRETE,
        lambda out: [
            *("-o", str(out / "run.html"), "--csv", str(out / "t.csv")),
            *("--json", str(out / "s.json")),
        ],
    ),
    "explore": (LOGICAL, lambda out: ["--budget", "2", "--top", "1", "-o", str(out / "x")]),
    "diff": (CONCRETE, lambda out: [str(LOGICAL), "-o", str(out / "d.txt")]),
    "merge": (CONCRETE, lambda out: [str(CONCRETE), str(CONCRETE), "-o", str(out / "m.xmi")]),
    "module list": (EXAMPLES / "library" / "sceml-library.xmi", lambda out: []),
    "module show": (EXAMPLES / "library" / "sceml-library.xmi", lambda out: ["CrossingManeuver"]),
    "module extract": (
        CONCRETE,
        lambda out: [
            *("--nodes", "Accelerate_1", "--name", "Speedup"),
            *("--into", str(out / "lib.xmi"), "-o", str(out / "e.xmi")),
        ],
    ),
}
READS_ONLY = {"info", "module list", "module show", "check-run"}
#: Commands whose output is a report on their inputs, written whether or not they can be read.
REPORTERS = {"validate", "check-xosc"}

#: Commands that read OpenSCENARIO; the others read SceML models.
XOSC_READERS = {"check-xosc", "import"}
#: Bad input files by class, of the kind each command reads.
BAD_INPUTS = {
    "missing": lambda tmp, xosc: tmp / ("missing.xosc" if xosc else "missing.xmi"),
    "folder": lambda tmp, xosc: tmp,
    "malformed": lambda tmp, xosc: CORPUS / ("xosc_truncated.xosc" if xosc else "truncated.xmi"),
    "hostile": lambda tmp, xosc: (
        CORPUS / ("xosc_billion_laughs.xosc" if xosc else "billion_laughs.xmi")
    ),
}


def _leaf_commands() -> dict[str, click.Command]:
    found = {}
    for name, command in commands().items():
        if isinstance(command, click.Group):
            found.update({f"{name} {sub}": c for sub, c in command.commands.items()})
        else:
            found[name] = command
    return found


def run(arguments: list[str]) -> tuple[int, str]:
    with deadline():
        result = CliRunner().invoke(cli, arguments)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {arguments}") from result.exception
    assert "Traceback" not in result.output
    return result.exit_code, result.output


def arguments(command: str, file: Path, out: Path) -> list[str]:
    _, rest = COMMANDS[command]
    return [*command.split(), str(file), *rest(out)]


def files(folder: Path) -> list[Path]:
    return sorted(folder.rglob("*"))


def test_every_command_is_scanned() -> None:
    # `edit` is scanned by test_edit_refuses_bad_input_before_serving; `git-setup` reads no
    # input file (tests/diff/test_git.py runs it).
    assert set(COMMANDS) == set(_leaf_commands()) - {
        "dev generate",
        "dev check-release",
        "dev release",
        "dev class-diagram",
        "edit",
        "git-setup",
    }


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_good_arguments_work(tmp_path: Path, command: str) -> None:
    # The baseline the scan varies: each bad run differs from this one in one way.
    code, output = run(arguments(command, COMMANDS[command][0], tmp_path))
    assert code == 0, output


@pytest.mark.parametrize("kind", sorted(BAD_INPUTS))
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_bad_input(tmp_path: Path, command: str, kind: str) -> None:
    out = tmp_path / "out"
    out.mkdir()
    bad = BAD_INPUTS[kind](tmp_path / "in", command in XOSC_READERS)
    if kind == "folder":
        bad.mkdir()
    code, output = run(arguments(command, bad, out))
    assert code == 2, output
    report = out / "report.txt"
    if command in REPORTERS and report.exists():  # the report is the product: it says why
        assert files(out) == [report] and "unreadable" in report.read_text()
    else:
        assert files(out) == [], files(out)


@pytest.mark.parametrize("kind", ["folder", "malformed", "hostile", "missing folder"])
def test_edit_refuses_bad_input_before_serving(tmp_path: Path, kind: str) -> None:
    # `edit` serves until Ctrl-C, so it has no good-arguments run here; a missing FILE is a new
    # scenario, so "missing" means a file in a folder that does not exist. `run` returning at
    # all (within the deadline) shows that no server was started.
    bad = tmp_path / "absent" / "new.xmi"
    if kind != "missing folder":
        bad = BAD_INPUTS[kind](tmp_path / "in", False)
    if kind == "folder":
        bad.mkdir()
    before = files(tmp_path)
    code, output = run(["edit", str(bad), "--no-browser"])
    assert code == 2, output
    assert "http://" not in output and str(bad.name) in output, output
    assert files(tmp_path) == before


@pytest.mark.parametrize("command", sorted(set(COMMANDS) - READS_ONLY))
def test_unwritable_output(tmp_path: Path, command: str) -> None:
    blocker = tmp_path / "blocker"
    blocker.write_text("a file where a folder should be")
    before = files(tmp_path)
    code, output = run(arguments(command, COMMANDS[command][0], blocker))
    assert code == 1 and "cannot write" in output, output
    assert files(tmp_path) == before


def _bad_value(parameter: click.Parameter) -> str | None:
    """A value the parameter's type refuses, or None when its type accepts any text."""
    kind = parameter.type
    if isinstance(kind, click.Choice):
        return "no-such-choice"
    if isinstance(kind, click.IntRange | click.FloatRange):
        return "-1" if kind.min is not None and kind.min >= 0 else "not-a-number"
    if isinstance(kind, Parsed):
        return "not valid at all"
    if isinstance(kind, click.Path) and kind.exists:
        return "/no/such/file"
    return None


BAD_OPTIONS = [
    (command, option.opts[-1], value)
    for command, command_object in sorted(_leaf_commands().items())
    if command in COMMANDS
    for option in command_object.params
    if isinstance(option, click.Option) and (value := _bad_value(option)) is not None
]


@pytest.mark.parametrize(
    ("command", "option", "value"), BAD_OPTIONS, ids=[f"{c} {o}" for c, o, _ in BAD_OPTIONS]
)
def test_bad_option_value(tmp_path: Path, command: str, option: str, value: str) -> None:
    code, output = run([*arguments(command, COMMANDS[command][0], tmp_path), option, value])
    assert code == 2 and "Invalid value" in output, output
    assert files(tmp_path) == [], files(tmp_path)


def test_the_scan_covers_options() -> None:
    assert len(BAD_OPTIONS) >= 25
    assert ("export", "--date", "not valid at all") in BAD_OPTIONS

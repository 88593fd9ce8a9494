"""Every hostile or broken file, through every entry point that reads it, gets a clear, located
error and the right exit code, quickly, with bounded memory and never a traceback (cases and
expectations: corpus/MANIFEST, written by make_corpus.py)."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner
from metamodel_releases import CURRENT

from sceml.cli import cli
from sceml.cli import commands as cli_commands
from sceml.errors import LoadError
from sceml.files.safexml import MAX_BYTES_VARIABLE
from sceml.model.loading import load, unresolved_references
from sceml.modules.flatten import FlattenError, flatten

from .make_corpus import CORPUS, READERS, cases, manifest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
#: A recorded esmini log (of UIS2 at 1.0) for `check-run`, whose model is the hostile file.
PLAYER_LOG = EXAMPLES.parent / "tests" / "players" / "data" / "uis2-concrete-1.0.log.txt"
SECONDS = 20  # generous for a loaded 2-core machine; a hang is what this catches
MANIFEST = [line.split("\t") for line in (CORPUS / "MANIFEST").read_text().splitlines()]

#: How each entry point named in the MANIFEST is run on a file, writing into a folder.
ENTRY_POINTS: dict[str, Callable[[Path, Path], list[str]]] = {
    "info": lambda file, out: ["info", str(file)],
    "validate": lambda file, out: ["validate", str(file)],
    "export": lambda file, out: ["export", str(file), "-o", str(out / "out.xosc")],
    "render": lambda file, out: ["render", str(file), "-o", str(out / "out.svg")],
    "flatten": lambda file, out: ["flatten", str(file), "-o", str(out / "flat.xmi")],
    "module-list": lambda file, out: ["module", "list", str(file)],
    "sample": lambda file, out: ["sample", str(file), "-o", str(out / "samples"), "--workers", "1"],
    "concretize": lambda file, out: ["concretize", str(file), "-o", str(out / "concrete.xmi")],
    "report": lambda file, out: ["report", str(file), "-o", str(out / "report.html")],
    "export-distribution": lambda file, out: ["export-distribution", str(file), "-o", str(out)],
    "check-xosc": lambda file, out: ["check-xosc", "--no-quality-checker", str(file)],
    "simulate": lambda file, out: ["simulate", str(file), "-o", str(out / "run.html")],
    "explore": lambda file, out: ["explore", str(file), "--budget", "2", "-o", str(out / "x")],
    "import": lambda file, out: ["import", str(file), "-o", str(out / "imported.xmi")],
    "migrate": lambda file, out: ["migrate", str(file), "-o", str(out / "migrated.xmi")],
    "check-run": lambda file, out: ["check-run", str(file), "--log", str(PLAYER_LOG)],
    "extract": lambda file, out: [
        "extract",
        str(file),
        "-o",
        str(out / "extracted.xmi"),
        "--map",
        str(EXAMPLES.parent / "maps" / "intersection.xodr"),
    ],
    "diff": lambda file, out: ["diff", str(EXAMPLES / "uis1-concrete.xmi"), str(file)],
    "merge": lambda file, out: [
        "merge",
        str(file),
        *(str(EXAMPLES / "uis1-concrete.xmi"),) * 2,
        "-o",
        str(out / "merged.xmi"),
    ],
    "limits": lambda file, out: [
        "validate",
        "--limits",
        str(file),
        str(EXAMPLES / "uis1-concrete.xmi"),
    ],
    "ranges": lambda file, out: [
        "promote",
        str(EXAMPLES / "uis1-functional.xmi"),
        "--ranges",
        str(file),
        "-o",
        str(out / "promoted.xmi"),
    ],
}


def entry_points(readers: str) -> list[str]:
    """The entry points a MANIFEST field names (a group of READERS stands for its members)."""
    return [e for name in readers.split(",") for e in READERS.get(name, (name,))]


RUNS = [
    (name, entry, int(code), None if line == "-" else int(line), text)
    for name, readers, code, line, text in MANIFEST
    for entry in entry_points(readers)
]


@contextlib.contextmanager
def deadline(seconds: int = SECONDS) -> Iterator[None]:
    """Fail instead of hanging when the body takes longer than `seconds`."""

    def expire(signum: int, frame: object) -> None:
        raise TimeoutError(f"took longer than {seconds} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def run(arguments: list[str]) -> tuple[int, str]:
    """Exit code and output (stdout and stderr) of `sceml ARGUMENTS`, failing on a traceback."""
    with deadline():
        result = CliRunner().invoke(cli, arguments)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {arguments}") from result.exception
    assert "Traceback" not in result.output
    return result.exit_code, result.output


def test_corpus_matches_its_generator() -> None:
    # Contents are edits of examples/ as they were when the corpus was made, and examples may be
    # rebuilt since; what must agree is the list of cases and their expectations.
    assert (CORPUS / "MANIFEST").read_text() == manifest(cases())
    assert all((CORPUS / entry[0]).is_file() for entry in MANIFEST)


def test_every_entry_point_is_known_and_used() -> None:
    used = {entry for _, entry, *_ in RUNS}
    assert used == set(ENTRY_POINTS)
    # Each command that reads a file the user names is in the table (dev tools excepted,
    # `edit`, which serves the file until stopped: tests/editor runs it on broken files, and
    # `git-setup`, which reads no model: tests/diff/test_git.py).
    commands = {
        arguments[0] for arguments in (f(Path("f"), Path("o")) for f in ENTRY_POINTS.values())
    }
    assert commands == set(cli_commands()) - {"dev", "edit", "git-setup"}


@pytest.mark.parametrize(
    ("name", "entry", "code", "line", "expected"),
    RUNS,
    ids=[f"{run[0]}-{run[1]}" for run in RUNS],
)
def test_case(
    tmp_path: Path, name: str, entry: str, code: int, line: int | None, expected: str
) -> None:
    file = CORPUS / name
    exit_code, output = run(ENTRY_POINTS[entry](file, tmp_path))
    assert exit_code == code, output
    assert expected in output, output
    if not code:
        return
    # The error names the file (or the file a case expects, where a problem lies in a library
    # the file refers to)...
    named = re.match(r"([\w.-]+\.xmi):\d+: ", expected)
    assert str(CORPUS / named.group(1) if named else file) in output, output
    if line is not None:  # ...and the line, gcc-style or in a report
        assert f"{file}:{line}:" in output or f"line {line}:" in output, output
    if code == 2:  # input that cannot be used leaves nothing behind
        assert list(tmp_path.iterdir()) == [], list(tmp_path.iterdir())


def test_every_xmi_case_is_a_load_error_or_a_located_reference_problem() -> None:
    for name, readers, code, line, _ in MANIFEST:
        if not name.endswith(".xmi") or code == "0" or "sample" in readers.split(","):
            continue
        try:
            document = load(CORPUS / name)
        except LoadError as error:
            assert error.file == str(CORPUS / name) and code == "2"
            assert error.line == (None if line == "-" else int(line)), name
            continue
        if name.startswith("self_use"):
            continue
        broken = list(unresolved_references(document.root))
        assert len(broken) == 1 and document.line_of(broken[0][0]) == int(line), name


@pytest.mark.parametrize(
    "name", ["self_use_direct_scenario.xmi", "self_use_transitive_scenario.xmi"]
)
def test_module_using_itself_loads_and_flatten_reports_it(name: str) -> None:
    with deadline():
        document = load(CORPUS / name)
        with pytest.raises(FlattenError, match="module uses itself"):
            flatten(document.root)


def _sparse(path: Path, size: int) -> Path:
    with path.open("wb") as stream:
        stream.write(b'<?xml version="1.0"?>\n<x>')
        stream.truncate(size)
    return path


HUGE = {"model": "huge.xmi", "xosc": "huge.xosc", "config": "huge.yaml"}


@pytest.mark.parametrize(
    ("entry", "name"), [(e, HUGE[group]) for group, members in READERS.items() for e in members]
)
def test_a_100_mb_file_is_refused_by_size_before_reading(
    tmp_path: Path, entry: str, name: str
) -> None:
    huge = _sparse(tmp_path / name, 100 * 1024 * 1024)  # sparse: costs no disk
    out = tmp_path / "out"
    out.mkdir()
    exit_code, output = run(ENTRY_POINTS[entry](huge, out))
    assert exit_code == 2 and str(huge) in output, output
    assert "100 MiB, above the 64 MiB limit" in output or "104857600 bytes, above" in output
    assert list(out.iterdir()) == []


def test_the_size_limit_is_configurable(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(MAX_BYTES_VARIABLE, "1000")
    exit_code, output = run(["info", str(EXAMPLES / "uis1-concrete.xmi")])
    assert exit_code == 2 and "above the 1000-byte limit" in output
    assert load(EXAMPLES / "uis1-concrete.xmi", max_bytes=10**6).root is not None
    monkeypatch.setenv(MAX_BYTES_VARIABLE, "lots")
    exit_code, output = run(["info", str(EXAMPLES / "uis1-concrete.xmi")])
    assert exit_code == 2 and "SCEML_MAX_BYTES='lots'" in output


def test_100k_nested_elements_are_a_clean_error(tmp_path: Path) -> None:
    deep = tmp_path / "deep.xmi"
    body = "<nodes>" * 100_000 + "</nodes>" * 100_000
    deep.write_text(
        f'<?xml version="1.0"?>\n<s:Scenario xmlns:s="https://sceml.org/metamodel/{CURRENT}">'
        f"{body}</s:Scenario>"
    )
    exit_code, output = run(["info", str(deep)])
    assert exit_code == 2 and "Excessive depth" in output


def test_utf16_dtd_is_refused(tmp_path: Path) -> None:
    # The byte scan for "<!DOCTYPE" cannot see UTF-16; the parsed tree still shows the DTD.
    bomb = tmp_path / "bomb16.xmi"
    bomb.write_bytes(
        (CORPUS / "billion_laughs.xmi").read_text().replace("UTF-8", "UTF-16").encode("utf-16")
    )
    with pytest.raises(LoadError, match="DTDs"):
        load(bomb)


_MEASURE = """
import resource, sys
from sceml.cli import cli, commands
try:
    cli(sys.argv[1:])
except SystemExit as exit:
    code = exit.code
print(code, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024)
"""


def _measure(arguments: list[str]) -> tuple[int, int, str]:
    """Exit code, peak memory (MB) and stderr of `sceml ARGUMENTS` in a fresh process."""
    done = subprocess.run(
        [sys.executable, "-c", _MEASURE, *arguments],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONWARNINGS": ""},
    )
    code, megabytes = done.stdout.split()[-2:]
    return int(code), int(megabytes), done.stderr


@pytest.mark.parametrize(
    ("entry", "name"),
    [
        ("info", "billion_laughs.xmi"),
        ("info", "huge.xmi"),
        ("check-xosc", "xosc_billion_laughs.xosc"),
        ("check-xosc", "huge.xosc"),
        ("ranges", "config_alias_bomb.yaml"),
        ("limits", "config_alias_bomb.yaml"),
    ],
)
def test_hostile_files_cost_little_memory_and_time(tmp_path: Path, entry: str, name: str) -> None:
    path = CORPUS / name if not name.startswith("huge") else _sparse(tmp_path / name, 100 << 20)
    _, base, _ = _measure(ENTRY_POINTS["info"](EXAMPLES / "uis1-concrete.xmi", tmp_path))
    code, megabytes, errors = _measure(ENTRY_POINTS[entry](path, tmp_path))
    assert code == 2 and "Traceback" not in errors, errors
    assert megabytes < base + 50, (megabytes, base)


def test_manifest_is_machine_readable() -> None:
    # One case per line with five fields; the exit codes are the CLI's, entry points are known.
    for name, readers, code, line, text in MANIFEST:
        assert code in {"0", "1", "2"} and (line == "-" or line.isdigit()) and text, name
        assert all(entry in ENTRY_POINTS for entry in entry_points(readers)), name

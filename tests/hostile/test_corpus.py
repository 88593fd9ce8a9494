"""Every hostile or broken file gets a clear, located error and the right exit code, quickly,
with bounded memory and never a traceback (cases and expectations: corpus/MANIFEST)."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml import io, schema
from sceml.cli import cli
from sceml.errors import LoadError, SceMLError
from sceml.modules.flatten import FlattenError, flatten

from .make_corpus import CORPUS, cases, manifest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SECONDS = 20  # generous for a loaded 2-core machine; a hang is what this catches
ENTRIES = [line.split("\t") for line in (CORPUS / "MANIFEST").read_text().splitlines()]


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


def run(command: str, path: Path) -> tuple[int, str]:
    """Exit code and output of `sceml COMMAND PATH`, failing on any traceback."""
    if command == "check-xosc" and command not in cli.commands:
        # Until `sceml check-xosc` is registered, its reader is tested directly.
        try:
            schema.parse_file(path)
        except SceMLError as error:
            return error.exit_code, str(error)
        return 0, ""
    with deadline():
        result = CliRunner().invoke(cli, [command, str(path)])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {command}") from result.exception
    assert "Traceback" not in result.output
    return result.exit_code, result.output


def test_corpus_matches_its_generator() -> None:
    # Contents are edits of examples/ as they were when the corpus was made, and examples may be
    # rebuilt since; what must agree is the list of cases and their expectations.
    assert (CORPUS / "MANIFEST").read_text() == manifest(cases())
    assert all((CORPUS / entry[0]).is_file() for entry in ENTRIES)


@pytest.mark.parametrize(
    ("name", "command", "code", "expected"), ENTRIES, ids=[e[0] for e in ENTRIES]
)
def test_case(name: str, command: str, code: str, expected: str) -> None:
    exit_code, output = run(command, CORPUS / name)
    assert exit_code == int(code), output
    assert expected in output
    if exit_code:
        assert f"{CORPUS / name}" in output  # the error names the file...
    if exit_code == 2 and "DTD" not in expected and command == "info":
        assert f"{CORPUS / name}:" in output  # ...and, for content errors, the line


def test_every_xmi_case_is_a_load_error_or_a_located_reference_problem() -> None:
    for name, command, code, _ in ENTRIES:
        if command != "info" or code == "0":
            continue
        try:
            document = io.load(CORPUS / name)
        except LoadError as error:
            assert error.file == str(CORPUS / name) and code == "2"
            continue
        broken = list(io.unresolved_references(document.root))
        assert len(broken) == 1 and document.line_of(broken[0][0]) == 64, name


@pytest.mark.parametrize(
    "name", ["self_use_direct_scenario.xmi", "self_use_transitive_scenario.xmi"]
)
def test_module_using_itself_loads_and_flatten_reports_it(name: str) -> None:
    with deadline():
        document = io.load(CORPUS / name)
        with pytest.raises(FlattenError, match="module uses itself"):
            flatten(document.root)


def _sparse(path: Path, size: int) -> Path:
    with path.open("wb") as stream:
        stream.write(b'<?xml version="1.0"?>\n<x>')
        stream.truncate(size)
    return path


def test_a_100_mb_file_is_refused_by_size_before_reading(tmp_path: Path) -> None:
    huge = _sparse(tmp_path / "huge.xmi", 100 * 1024 * 1024)
    exit_code, output = run("info", huge)
    assert exit_code == 2 and "104.9 MB, above the 67 MB limit" in output


def test_the_size_limit_is_configurable(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(io.MAX_BYTES_VARIABLE, "1000")
    exit_code, output = run("info", EXAMPLES / "uis1-concrete.xmi")
    assert exit_code == 2 and "above the 0 MB limit" in output
    assert io.load(EXAMPLES / "uis1-concrete.xmi", max_bytes=10**6).root is not None
    monkeypatch.setenv(io.MAX_BYTES_VARIABLE, "lots")
    exit_code, output = run("info", EXAMPLES / "uis1-concrete.xmi")
    assert exit_code == 2 and "SCEML_MAX_BYTES='lots'" in output


def test_100k_nested_elements_are_a_clean_error(tmp_path: Path) -> None:
    deep = tmp_path / "deep.xmi"
    body = "<nodes>" * 100_000 + "</nodes>" * 100_000
    deep.write_text(
        f'<?xml version="1.0"?>\n<s:Scenario xmlns:s="https://sceml.org/metamodel/1.0">{body}</s:Scenario>'
    )
    exit_code, output = run("info", deep)
    assert exit_code == 2 and "Excessive depth" in output


def test_utf16_dtd_is_refused(tmp_path: Path) -> None:
    # The byte scan for "<!DOCTYPE" cannot see UTF-16; the parsed tree still shows the DTD.
    bomb = tmp_path / "bomb16.xmi"
    bomb.write_bytes(
        (CORPUS / "billion_laughs.xmi").read_text().replace("UTF-8", "UTF-16").encode("utf-16")
    )
    with pytest.raises(LoadError, match="DTDs"):
        io.load(bomb)


_MEASURE = """
import resource, sys
from sceml.cli import cli
try:
    cli([sys.argv[1], sys.argv[2]])
except SystemExit as exit:
    code = exit.code
print(code, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss // 1024)
"""


@pytest.mark.parametrize("name", ["billion_laughs.xmi", "huge.xmi"])
def test_hostile_files_cost_little_memory_and_time(tmp_path: Path, name: str) -> None:
    path = CORPUS / name if name != "huge.xmi" else _sparse(tmp_path / name, 100 * 1024 * 1024)
    baseline = subprocess.run(
        [sys.executable, "-c", _MEASURE, "info", str(EXAMPLES / "uis1-concrete.xmi")],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONWARNINGS": ""},
    )
    measured = subprocess.run(
        [sys.executable, "-c", _MEASURE, "info", str(path)],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONWARNINGS": ""},
    )
    code, megabytes = measured.stdout.split()[-2:]
    base = int(baseline.stdout.split()[-1])
    assert code == "2" and "Traceback" not in measured.stderr
    assert int(megabytes) < base + 50, (megabytes, base)


def test_manifest_is_machine_readable() -> None:
    # One case per line with four fields; the exit codes are the CLI's.
    assert all(len(entry) == 4 and entry[2] in {"0", "1", "2"} for entry in ENTRIES)
    assert json.dumps(ENTRIES)

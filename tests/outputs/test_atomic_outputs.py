"""Failed exports, renders, samples and saves leave no partial file and never replace a good
file with a bad one: every failure is forced in the middle of a real CLI run."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import graphviz
import pytest
from click.testing import CliRunner, Result
from lxml import etree

from sceml.cli import cli
from sceml.files.writing import write_atomically
from sceml.xosc import schema
from sceml.xosc.attribute_types import ValueCheck

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GOOD = b"<good>previous output</good>\n"


def invoke(arguments: list[str]) -> Result:
    result = CliRunner().invoke(cli, arguments)
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"traceback from sceml {arguments}") from result.exception
    return result


def temporaries(folder: Path) -> list[Path]:
    """Temporary files write_atomically may have left (`.NAME.*.tmp`)."""
    return sorted(folder.rglob(".*.tmp"))


def failing_replace(monkeypatch: pytest.MonkeyPatch, when: Callable[[Path], bool]) -> None:
    """Make the rename that completes an atomic write fail for targets `when` accepts."""
    real = os.replace

    def replace(source: str | os.PathLike[str], target: str | os.PathLike[str]) -> None:
        if when(Path(target)):
            raise OSError(28, "No space left on device")
        real(source, target)

    monkeypatch.setattr(os, "replace", replace)


def _invalid(*args: object, **kwargs: object) -> list[schema.SchemaIssue]:
    reason = "forced by the test"
    return [schema.SchemaIssue(message=reason, line=None, path=None, reason=reason)]


def test_export_refused_by_the_xsd_keeps_the_previous_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    output = tmp_path / "out.xosc"
    output.write_bytes(GOOD)
    monkeypatch.setattr(schema, "validate_tree", _invalid)
    result = invoke(["export", str(EXAMPLES / "uis1-concrete.xmi"), "-o", str(output)])
    assert result.exit_code == 1 and "forced by the test" in result.output, result.output
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []


def test_export_interrupted_while_writing_keeps_the_previous_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    output = tmp_path / "out.xosc"
    output.write_bytes(GOOD)
    failing_replace(monkeypatch, lambda target: target == output)
    result = invoke(["export", str(EXAMPLES / "uis1-concrete.xmi"), "-o", str(output)])
    assert result.exit_code == 1 and "No space left on device" in result.output
    assert str(output) in result.output
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []


def test_export_that_succeeds_replaces_the_file_with_a_valid_one(tmp_path: Path) -> None:
    # The counterpart of the two tests above: the same command does replace the file.
    output = tmp_path / "out.xosc"
    output.write_bytes(GOOD)
    assert invoke(["export", str(EXAMPLES / "uis1-concrete.xmi"), "-o", str(output)]).exit_code == 0
    assert schema.validate_file(output) == []
    assert temporaries(tmp_path) == []


def test_render_failing_in_graphviz_keeps_the_previous_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    output = tmp_path / "out.svg"
    output.write_bytes(GOOD)

    def crash(self: graphviz.Digraph, *args: object, **kwargs: object) -> bytes:
        raise graphviz.CalledProcessError(1, ["dot"], stderr=b"dot: out of memory")

    monkeypatch.setattr(graphviz.Digraph, "pipe", crash)
    result = invoke(["render", str(EXAMPLES / "uis1-concrete.xmi"), "-o", str(output)])
    assert result.exit_code != 0 and "out of memory" in result.output, result.output
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []


def test_render_interrupted_while_writing_keeps_the_previous_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    output = tmp_path / "out.svg"
    output.write_bytes(GOOD)
    failing_replace(monkeypatch, lambda target: target == output)
    result = invoke(["render", str(EXAMPLES / "uis1-concrete.xmi"), "-o", str(output)])
    assert result.exit_code == 1 and str(output) in result.output
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []


def _sample(out: Path) -> Result:
    return invoke(
        ["sample", str(EXAMPLES / "uis1-logical.xmi"), "-o", str(out), "--n", "4", "--workers", "1"]
    )


def _xosc_files(out: Path) -> list[Path]:
    return sorted(out.glob("*.xosc"))


def test_a_sample_refused_by_the_xsd_writes_nothing_and_the_others_are_complete(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "samples"
    calls = {"n": 0, "refused": False}
    real_valid, real_validate = schema.is_valid_tree, schema.validate_tree

    def third_is_invalid(tree: etree._Element, version: str | None = None) -> bool:
        calls["n"] += 1
        calls["refused"] = calls["n"] == 3
        return not calls["refused"] and real_valid(tree, version)

    def issues(tree: etree._Element, version: str | None = None) -> list[schema.SchemaIssue]:
        return _invalid() if calls["refused"] else real_validate(tree, version)

    monkeypatch.setattr(schema, "is_valid_tree", third_is_invalid)
    monkeypatch.setattr(schema, "validate_tree", issues)
    # Every sample is checked as a whole document, not by its sampled values alone (which
    # would pass), so that the third check refuses one.
    monkeypatch.setattr(ValueCheck, "valid", lambda self, values: False)
    result = _sample(out)
    assert result.exit_code == 0 and "3 written, 1 skipped (xsd: forced by the test: 1)" in (
        result.output
    ), result.output
    written = _xosc_files(out)
    assert len(written) == 3
    monkeypatch.undo()
    for path in written:  # complete and valid, read back independently of the writer
        assert schema.validate_file(path) == [], path
    assert temporaries(tmp_path) == []


def test_a_sample_interrupted_while_writing_keeps_the_previous_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "samples"
    out.mkdir()
    victim = out / "uis1_00002.xosc"
    victim.write_bytes(GOOD)
    failing_replace(monkeypatch, lambda target: target == victim)
    result = _sample(out)
    assert result.exit_code == 1 and str(victim) in result.output, result.output
    assert victim.read_bytes() == GOOD
    monkeypatch.undo()
    written = [p for p in _xosc_files(out) if p != victim]
    assert [p.name for p in written] == ["uis1_00000.xosc", "uis1_00001.xosc"]
    for path in written:
        assert schema.validate_file(path) == [], path
    assert temporaries(tmp_path) == []


def test_save_interrupted_keeps_the_previous_model(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    output = tmp_path / "flat.xmi"
    output.write_bytes(GOOD)
    failing_replace(monkeypatch, lambda target: target == output)
    result = invoke(["flatten", str(EXAMPLES / "uis2-concrete.xmi"), "-o", str(output)])
    assert result.exit_code == 1 and "No space left on device" in result.output
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []


def test_an_interrupt_during_an_atomic_write_removes_the_temporary_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Ctrl-C is not an OSError: it must still clean up, and still reach the caller.
    output = tmp_path / "out.bin"
    output.write_bytes(GOOD)

    def interrupted(source: object, target: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write_atomically(output, b"new")
    assert output.read_bytes() == GOOD
    assert temporaries(tmp_path) == []

"""Validation split over two processes (`sceml validate --jobs 2`) reports exactly what one process
reports: the same diagnostics, in the same order, naming the same model objects; and a child that
fails or a parent that is interrupted leaves no process behind."""

from __future__ import annotations

import os
import pickle
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

import scemlmodel as scm
from sceml.cli.validate import validate as validate_command
from sceml.diagnostics import Diagnostic
from sceml.model.loading import load
from sceml.validation import split
from sceml.validation.engine import validate

REPO = Path(__file__).resolve().parents[2]
FILES = sorted([*(REPO / "examples").rglob("*.xmi"), *(REPO / "tests").rglob("*.xmi")])

needs_fork = pytest.mark.skipif(not hasattr(os, "fork"), reason="splitting needs fork")


def _said(found: list[Diagnostic]) -> list[tuple[object, ...]]:
    return [(d.severity, d.code, d.message, d.fragment, d.path, d.file, d.line) for d in found]


@pytest.fixture
def always_split(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Split every scenario, however small, into parts of one object each (so that both
    processes take some), and record the children forked."""
    monkeypatch.setattr(split, "SPLIT_FROM", 0)
    monkeypatch.setattr(split.Parts, "FEWEST", 1)
    monkeypatch.setattr(split, "processors", lambda: 2)
    children: list[int] = []
    real_fork = os.fork

    def fork() -> int:
        pid = real_fork()
        if pid:
            children.append(pid)
        return pid

    monkeypatch.setattr(os, "fork", fork)
    return children


def _reaped(pid: int) -> bool:
    try:
        os.waitpid(pid, os.WNOHANG)
    except ChildProcessError:
        return True
    return False


@needs_fork
def test_every_scenario_of_the_corpus_gets_the_same_report(always_split: list[int]) -> None:
    scenarios = 0
    with_findings = 0
    for path in FILES:
        try:
            document = load(path, read_only=True)
        except Exception:
            continue  # the unreadable files of the hostile corpus: nothing to validate
        if not isinstance(document.root, scm.Scenario):
            continue
        scenarios += 1
        alone = validate(document.root, document=document)
        forked = len(always_split)
        together = validate(document.root, document=document, jobs=2)
        assert len(always_split) == forked + 1, path  # it did split
        assert _said(together) == _said(alone), path
        # The same objects, not equal copies: the editor and `sceml review` use them.
        assert [d.element for d in together] == [d.element for d in alone], path
        assert all(a.element is b.element for a, b in zip(together, alone, strict=True)), path
        with_findings += bool(alone)
    assert scenarios > 100 and with_findings > 50  # the comparison covered real findings
    assert all(_reaped(pid) for pid in always_split)


@needs_fork
def test_a_child_that_fails_leaves_its_share_to_the_parent(
    always_split: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    document = load(REPO / "tests/validation/corpus" / _a_faulty_scenario(), read_only=True)
    alone = validate(document.root, document=document)
    assert alone

    def broken(*args: object, **options: object) -> bytes:
        raise MemoryError  # in the child, which inherits this patch

    monkeypatch.setattr(pickle, "dumps", broken)  # split imports it on use, before the fork
    together = validate(document.root, document=document, jobs=2)
    assert _said(together) == _said(alone)
    assert len(always_split) == 1 and _reaped(always_split[0])


@needs_fork
def test_the_parts_both_processes_took_are_put_back_in_order(
    always_split: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    document = load(REPO / "tests/validation/corpus" / _a_faulty_scenario(), read_only=True)
    alone = validate(document.root, document=document)
    parent = os.getpid()
    real_each, real_take = split.each_object, split.Parts.take

    def paced(*args: object, **options: object) -> object:
        # A part costs the child ten times what it costs the parent: both take some.
        time.sleep(0.01 if os.getpid() != parent else 0.001)
        return real_each(*args, **options)  # type: ignore[arg-type]

    taken: list[tuple[int, int]] = []

    def take(parts: split.Parts, *args: object) -> split.ByPart:
        done = real_take(parts, *args)  # type: ignore[arg-type]
        if os.getpid() == parent:
            taken.append((len(done), len(parts)))
        return done

    monkeypatch.setattr(split, "each_object", paced)
    monkeypatch.setattr(split.Parts, "take", take)
    together = validate(document.root, document=document, jobs=2)
    assert _said(together) == _said(alone)
    assert all(a.element is b.element for a, b in zip(together, alone, strict=True))
    ((mine, count),) = taken
    assert count > 50 and 0 < mine < count  # the parent took some parts, the child others


@needs_fork
def test_an_interrupted_parent_stops_its_child(
    always_split: list[int], monkeypatch: pytest.MonkeyPatch
) -> None:
    document = load(REPO / "examples" / "uis2-logical.xmi", read_only=True)

    def interrupted(*args: object, **options: object) -> list[Diagnostic]:
        raise KeyboardInterrupt

    monkeypatch.setattr(split, "through_modules", interrupted)
    with pytest.raises(KeyboardInterrupt):
        validate(document.root, document=document, jobs=2)
    assert len(always_split) == 1 and _reaped(always_split[0])


def test_only_a_large_scenario_on_two_processors_is_split(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(split, "processors", lambda: 2)
    scenario = scm.Scenario()
    scenario.nodes.extend(scm.EndNode(name=f"n{i}") for i in range(split.SPLIT_FROM - 1))
    assert not split.worth_splitting(scenario)
    scenario.nodes.append(scm.EndNode(name="last"))
    assert split.worth_splitting(scenario) == hasattr(os, "fork")
    assert not split.worth_splitting(scm.Library())
    monkeypatch.setattr(split, "processors", lambda: 1)
    assert not split.worth_splitting(scenario)


@needs_fork
def test_the_command_reports_the_same_with_one_or_two_jobs(always_split: list[int]) -> None:
    path = REPO / "tests/validation/corpus" / _a_faulty_scenario()
    runner = CliRunner()
    one = runner.invoke(validate_command, ["--jobs", "1", "--format", "json", str(path)])
    two = runner.invoke(validate_command, ["--jobs", "2", "--format", "json", str(path)])
    assert one.exit_code == two.exit_code == 1
    assert two.output == one.output
    assert len(always_split) == 1


def _a_faulty_scenario() -> str:
    """A corpus scenario with findings of several rules (checked by the tests using it)."""
    return "multi-levels.xmi"  # C001, M004, M006, P002, P003, P005, P006: root and node rules


@pytest.mark.skipif(not Path("/proc/self/status").exists(), reason="reads Linux's /proc")
def test_no_child_where_the_memory_could_not_hold_one(monkeypatch: pytest.MonkeyPatch) -> None:
    size = split._kilobytes(Path("/proc/self/status"), "VmRSS")
    monkeypatch.setattr(split, "_memory_groups", lambda: [])
    assert split.room_for_a_child()  # this machine has room for a test process's copy
    # A control group whose room left is smaller than this process: no child.
    monkeypatch.setattr(split, "_memory_groups", lambda: [(2 * size, size + size // 2)])
    assert not split.room_for_a_child()
    monkeypatch.setattr(split, "_memory_groups", lambda: [(4 * size, size)])
    assert split.room_for_a_child()
    monkeypatch.setattr(split, "processors", lambda: 2)
    monkeypatch.setattr(split, "room_for_a_child", lambda: False)
    scenario = scm.Scenario()
    scenario.nodes.extend(scm.EndNode(name=f"n{i}") for i in range(split.SPLIT_FROM))
    assert not split.worth_splitting(scenario)

"""Worker processes write the batch's files themselves (through a staging folder): a file that
cannot be written is still `cannot write`, and a worker lost mid-chunk leaves no file that the
run does not list and nothing staged."""

from __future__ import annotations

import errno
import operator
import os
import signal
import stat
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from sceml.cli.sample import sample
from sceml.errors import SaveError
from sceml.executors import Deferred, open_executor
from sceml.files.writing import open_folder, write_staged
from sceml.levels import batch
from sceml.levels.batch import BatchConfig, run_batch
from sceml.levels.sampling import Plan, values_at
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario

UIS2 = Path(__file__).resolve().parents[2] / "examples" / "uis2-logical.xmi"


def _everything(folder: Path) -> set[str]:
    """Every entry below `folder`, hidden ones and folders too, relative to it."""
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


def test_write_staged_replaces_the_file_and_leaves_nothing_staged(tmp_path: Path) -> None:
    staging = tmp_path / ".staging"
    staging.mkdir()
    target = tmp_path / "a.xosc"
    target.write_bytes(b"old")
    previous = os.umask(0o077)
    try:
        write_staged(target, b"new", staging)
    finally:
        os.umask(previous)
    assert target.read_bytes() == b"new"
    assert stat.S_IMODE(target.stat().st_mode) == 0o644  # as write_atomically leaves a file
    assert list(staging.iterdir()) == []


def test_write_staged_that_fails_keeps_the_old_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    staging = tmp_path / ".staging"
    staging.mkdir()
    target = tmp_path / "a.xosc"
    target.write_bytes(b"old")

    def refuse(*args: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "replace", refuse)
    with pytest.raises(SaveError) as raised:
        write_staged(target, b"new", staging)
    assert raised.value.file == str(target)
    assert raised.value.message == "cannot write: No space left on device"
    assert target.read_bytes() == b"old" and list(staging.iterdir()) == []


@pytest.mark.skipif(not hasattr(os, "O_TMPFILE"), reason="Linux's unnamed files")
def test_a_new_file_is_named_only_once_complete_and_never_staged(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    staging = tmp_path / ".staging"
    staging.mkdir()
    target = tmp_path / "a.xosc"
    seen: list[tuple[str, bool]] = []
    real_link = os.link

    def link(source: str, destination: Path, **options: object) -> None:
        # What a reader of the folder sees just before the file gets its name.
        seen.append((sorted(p.name for p in tmp_path.rglob("*")).__repr__(), target.exists()))
        real_link(source, destination, **options)  # type: ignore[arg-type]

    monkeypatch.setattr(os, "link", link)
    previous = os.umask(0o077)
    try:
        write_staged(target, b"x" * 100_000, staging)
    finally:
        os.umask(previous)
    assert seen == [("['.staging']", False)]  # no temporary name, in the folder or staged
    assert target.read_bytes() == b"x" * 100_000
    assert stat.S_IMODE(target.stat().st_mode) == 0o644
    assert list(staging.iterdir()) == []


def test_through_an_open_folder_the_writing_rule_holds(tmp_path: Path) -> None:
    """The workers write through a descriptor of the output folder (`open_folder`): new files,
    replaced files, links and what is never replaced fare as through the folder's path."""
    staging = tmp_path / ".staging"
    staging.mkdir()
    (tmp_path / "old.xosc").write_bytes(b"old")
    (tmp_path / "real.xosc").write_bytes(b"real")
    (tmp_path / "link.xosc").symlink_to(tmp_path / "real.xosc")
    os.mkfifo(tmp_path / "fifo.xosc")
    with open_folder(tmp_path) as handle:
        assert isinstance(handle, int)
        write_staged(tmp_path / "new.xosc", b"new", staging, handle)
        write_staged(tmp_path / "old.xosc", b"replaced", staging, handle)
        write_staged(tmp_path / "link.xosc", b"through the link", staging, handle)
        with pytest.raises(SaveError, match="FIFO"):
            write_staged(tmp_path / "fifo.xosc", b"never", staging, handle)
    assert (tmp_path / "new.xosc").read_bytes() == b"new"
    assert stat.S_IMODE((tmp_path / "new.xosc").stat().st_mode) == 0o644
    assert (tmp_path / "old.xosc").read_bytes() == b"replaced"
    assert (tmp_path / "link.xosc").is_symlink()  # the link stays a link
    assert (tmp_path / "real.xosc").read_bytes() == b"through the link"
    assert stat.S_ISFIFO(os.lstat(tmp_path / "fifo.xosc").st_mode)
    assert list(staging.iterdir()) == []


def test_without_unnamed_files_a_new_file_goes_through_staging(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("sceml.files.writing._unnamed_files", False)
    staging = tmp_path / ".staging"
    staging.mkdir()
    renamed: list[str] = []
    real_replace = os.replace

    def replace(source: Path, destination: Path) -> None:
        renamed.append(Path(source).parent.name)
        real_replace(source, destination)

    monkeypatch.setattr(os, "replace", replace)
    write_staged(tmp_path / "a.xosc", b"new", staging)
    assert renamed == [".staging"]
    assert (tmp_path / "a.xosc").read_bytes() == b"new" and list(staging.iterdir()) == []


def test_a_file_that_cannot_be_named_is_left_nowhere_and_reported(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    staging = tmp_path / ".staging"
    staging.mkdir()

    def refuse(*args: object, **options: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "link", refuse)
    monkeypatch.setattr(os, "replace", refuse)
    with pytest.raises(SaveError) as raised:
        write_staged(tmp_path / "a.xosc", b"new", staging)
    assert raised.value.message == "cannot write: No space left on device"
    assert _everything(tmp_path) == {".staging"}


@pytest.mark.parametrize("kind", ["local", "processes"])
def test_deferred_items_are_made_once_and_all_run(kind: str) -> None:
    made = []

    def make() -> list[int]:
        made.append(1)
        return [1, 2, 0, 4, 6]

    with open_executor(kind, workers=2) as executor:
        outcomes = list(executor.map_unordered(int, operator.floordiv, "12", Deferred(5, make)))
    assert made == [1]  # in this process, once
    by_item = {o.item: o for o in outcomes}
    assert [by_item[i].result for i in (0, 1, 3, 4)] == [12, 6, 3, 2]
    assert by_item[2].error == "ZeroDivisionError: integer division or modulo by zero"


@pytest.mark.parametrize("kind", ["local", "processes"])
def test_no_deferred_items_is_no_outcome(kind: str) -> None:
    with open_executor(kind, workers=2) as executor:
        assert list(executor.map_unordered(int, operator.add, "1", Deferred(0, list))) == []


def test_a_worker_that_cannot_write_makes_the_command_fail_cleanly(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def read_only(*args: object, **options: object) -> None:
        raise OSError(errno.EROFS, os.strerror(errno.EROFS))

    # The worker processes are forked from this one, so they inherit the refusal: no file can be
    # named, neither an unnamed one linked (`os.link`) nor a staged one renamed.
    monkeypatch.setattr(os, "link", read_only)
    monkeypatch.setattr(os, "replace", read_only)
    out = tmp_path / "out"
    arguments = [str(UIS2), "--strategy", "random", "--n", "20", "--workers", "2", "-o", str(out)]
    result = CliRunner().invoke(sample, [*arguments, "--executor", "processes"])
    assert result.exit_code == 1, result.output
    assert "cannot write: Read-only file system" in result.output
    assert f"{out}{os.sep}uis2_" in result.output  # names the file
    assert "Traceback" not in result.output
    assert not out.exists()  # made by the run, empty again: removed


def test_a_worker_lost_mid_chunk_leaves_only_the_files_of_written_samples(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = write_staged

    def die_on_the_third_file_of_sample_seven(path: Path, data: bytes, staging: Path) -> None:
        if path.name == "uis2_00007.xosc":
            os.kill(os.getpid(), signal.SIGKILL)  # files of samples 5 and 6 are in place
        real(path, data, staging)

    monkeypatch.setattr(batch, "write_staged", die_on_the_third_file_of_sample_seven)
    space = parameter_space(load_scenario(UIS2).root)
    indices = np.arange(40)
    rows = values_at(space, Plan("random", 40, seed=3), indices)
    config = BatchConfig(UIS2, tmp_path, space.paths, ("xosc",), stem="uis2")
    with open_executor("processes", workers=2) as executor:
        result = run_batch(config, indices, rows, executor=executor, chunk_size=5)
    by_index = {r.index: r for r in result.records}
    assert sorted(by_index) == list(range(40))
    assert by_index[7].status == "failed" and by_index[5].status == "failed"
    assert by_index[7].reason.startswith("lost: ")
    written = {name for r in result.records for name in r.files}
    assert _everything(tmp_path) == written  # no staging folder, no stray file

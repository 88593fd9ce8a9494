"""Batch work on every executor: the same files from the same seed, lost work named, Ctrl-C clean.

One `distributed.LocalCluster` with two worker processes serves the whole module; the test
that kills one of its workers runs last.
"""

from __future__ import annotations

import operator
import os
import signal
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from distributed import Client, LocalCluster

from sceml.cli.sample import sample
from sceml.executors import EXECUTORS, LocalExecutor, Outcome, ProcessExecutor, open_executor
from sceml.files.writing import write_atomically
from sceml.levels import batch
from sceml.levels.batch import BatchConfig, run_batch
from sceml.levels.manifest import read_manifest
from sceml.levels.sampling import Plan, values_at
from sceml.levels.space import ParameterSpace, parameter_space
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
UIS2 = EXAMPLES / "uis2-logical.xmi"


@pytest.fixture(scope="module")
def cluster() -> Iterator[LocalCluster]:
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as started:
        yield started


def _files(folder: Path) -> dict[str, bytes]:
    """Every file below `folder` (hidden ones too: a temporary file must not be left)."""
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir()) if p.is_file()}


def _sample(out: Path, *extra: str, n: int = 24, file_format: str = "both") -> str:
    arguments = [str(UIS2), "--strategy", "random", "--n", str(n), "--seed", "11"]
    arguments += ["--format", file_format, "-o", str(out), *extra]
    result = CliRunner().invoke(sample, arguments, catch_exceptions=False)
    assert result.exit_code == 0, result.output
    return result.output


def _uis2_rows(n: int) -> tuple[ParameterSpace, np.ndarray, np.ndarray]:
    space = parameter_space(load_scenario(UIS2).root)
    indices = np.arange(n)
    return space, indices, values_at(space, Plan("random", n, seed=3), indices)


def _config(out: Path, paths: tuple[str, ...]) -> BatchConfig:
    return BatchConfig(UIS2, out, paths, ("xosc",), stem="uis2")


@pytest.mark.parametrize("kind", EXECUTORS)
def test_every_executor_reports_each_item_and_a_failing_one_by_itself(
    kind: str, cluster: LocalCluster
) -> None:
    # Builtins, so that spawned Dask workers can import them: setup int("12") = 12, task 12 // x.
    scheduler = cluster.scheduler_address if kind == "dask" else None
    with open_executor(kind, workers=2, scheduler=scheduler) as executor:
        outcomes = list(executor.map_unordered(int, operator.floordiv, "12", [1, 2, 0, 4, 6]))
    by_item = {o.item: o for o in outcomes}
    assert sorted(by_item) == [0, 1, 2, 3, 4]
    assert [by_item[i].result for i in (0, 1, 3, 4)] == [12, 6, 3, 2]
    assert by_item[2] == Outcome(2, error="ZeroDivisionError: integer division or modulo by zero")


def test_a_two_worker_cluster_writes_the_bytes_of_a_local_run(
    tmp_path: Path, cluster: LocalCluster
) -> None:
    _sample(tmp_path / "local", "--executor", "local")
    _sample(tmp_path / "pool", "--executor", "processes", "--workers", "2")
    _sample(tmp_path / "dask", "--executor", "dask", "--scheduler", cluster.scheduler_address)
    local = _files(tmp_path / "local")
    assert len(local) == 2 * 24 + 2  # .xosc and .xmi per sample, manifest.csv and .json
    assert _files(tmp_path / "pool") == local
    assert _files(tmp_path / "dask") == local


def test_the_files_do_not_depend_on_the_chunks_or_their_order(
    tmp_path: Path, cluster: LocalCluster
) -> None:
    space, indices, rows = _uis2_rows(30)
    reference = run_batch(_config(tmp_path / "a", space.paths), indices, rows, workers=1)
    shuffled = np.random.default_rng(0).permutation(30)
    with open_executor("dask", scheduler=cluster.scheduler_address) as executor:
        again = run_batch(
            _config(tmp_path / "b", space.paths),
            indices[shuffled],
            rows[shuffled],
            executor=executor,
            chunk_size=1,
        )
    assert len(reference.records) == len(again.records) == 30
    assert _files(tmp_path / "a") == _files(tmp_path / "b")


def test_lost_samples_are_named_and_have_no_files(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    real = batch.produced_samples

    def lose_the_chunk_with_seven(state: batch.WorkerState, chunk: batch.Chunk) -> Iterator:  # type: ignore[type-arg]
        if 7 in chunk[0]:
            raise MemoryError("worker ran out of memory")
        yield from real(state, chunk)

    monkeypatch.setattr(batch, "produced_samples", lose_the_chunk_with_seven)
    space, indices, rows = _uis2_rows(20)
    with open_executor("local") as executor:
        result = run_batch(
            _config(tmp_path, space.paths), indices, rows, executor=executor, chunk_size=5
        )
    failed = sorted(r.index for r in result.records if r.status == "failed")
    assert failed == [5, 6, 7, 8, 9]
    assert {r.reason for r in result.records if r.status == "failed"} == {
        "lost: MemoryError: worker ran out of memory"
    }
    written = {name for r in result.records for name in r.files}
    assert set(_files(tmp_path)) == written and len(written) == 15


def test_a_sample_is_written_before_the_next_is_made_and_a_lost_chunk_leaves_none(
    tmp_path: Path, monkeypatch
) -> None:  # type: ignore[no-untyped-def]
    # Worker processes write each sample as it is produced, so the run's first file does not
    # wait for its chunk; a chunk lost part-way has its files removed. (UIS2's random samples
    # with seed 3: 5 and 6 are written, none skipped.)
    real = batch.produced_samples
    space, indices, rows = _uis2_rows(20)
    config = _config(tmp_path, space.paths)
    seen_before: dict[int, bool] = {}

    def lose_seven_after_writing_five_and_six(
        state: batch.WorkerState, chunk: batch.Chunk
    ) -> Iterator:  # type: ignore[type-arg]
        for index, produced in zip(chunk[0], real(state, chunk), strict=True):
            if index in (6, 7):
                seen_before[int(index)] = (tmp_path / config.file_name(index - 1, "xosc")).exists()
            if index == 7:
                seen = ", ".join(f"{i} {found}" for i, found in seen_before.items())
                (tmp_path / "seen").write_text(seen)
                raise MemoryError("worker ran out of memory")
            yield produced

    monkeypatch.setattr(batch, "produced_samples", lose_seven_after_writing_five_and_six)
    with open_executor("processes", workers=2) as executor:  # forked: they have the patch
        result = run_batch(config, indices, rows, executor=executor, chunk_size=5)
    # What the worker saw: the file of 5 before 6 was made, that of 6 before 7 was.
    assert (tmp_path / "seen").read_text() == "6 True, 7 True"
    failed = sorted(r.index for r in result.records if r.status == "failed")
    assert failed == [5, 6, 7, 8, 9]
    written = {name for r in result.records for name in r.files}
    assert set(_files(tmp_path)) - {"seen"} == written and len(written) == 15


def test_the_cli_names_lost_samples_and_keeps_them_in_the_manifest(
    tmp_path: Path, monkeypatch
) -> None:  # type: ignore[no-untyped-def]
    def lose_all(state: batch.WorkerState, chunk: batch.Chunk) -> Iterator:  # type: ignore[type-arg]
        raise OSError("disk of the worker is full")
        yield

    monkeypatch.setattr(batch, "produced_samples", lose_all)
    arguments = [str(UIS2), "--strategy", "random", "--n", "3", "-o", str(tmp_path)]
    result = CliRunner().invoke(sample, [*arguments, "--executor", "local"])
    assert result.exit_code == 1
    assert "0 written, 0 skipped, 3 failed" in result.output
    assert "samples lost with their worker: 0-2" in result.output
    rows = read_manifest(tmp_path)["samples"]
    assert [(r["index"], r["status"], r["files"]) for r in rows] == [
        (0, "failed", []),
        (1, "failed", []),
        (2, "failed", []),
    ]


@pytest.mark.parametrize("kind", ["processes", "dask"])
def test_ctrl_c_cancels_the_rest_and_leaves_only_recorded_files(
    kind: str, tmp_path: Path, cluster: LocalCluster
) -> None:
    space, indices, rows = _uis2_rows(400)
    done = []

    def interrupt_after_the_first_chunk(count: int) -> None:
        done.append(count)
        raise KeyboardInterrupt

    scheduler = cluster.scheduler_address if kind == "dask" else None
    with open_executor(kind, workers=2, scheduler=scheduler) as executor:
        result = run_batch(
            _config(tmp_path, space.paths),
            indices,
            rows,
            executor=executor,
            chunk_size=4,
            progress=interrupt_after_the_first_chunk,
        )
    assert result.interrupted
    assert len(result.records) == 4 and done == [4]
    time.sleep(0.2)  # nothing may arrive after the run returned
    assert set(_files(tmp_path)) == {name for r in result.records for name in r.files}


def test_ctrl_c_while_files_are_written_finishes_them_first(tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    real = write_atomically
    sent = []

    def ctrl_c_then_write(path: Path, data: bytes) -> None:
        if not sent:
            sent.append(path.name)
            os.kill(os.getpid(), signal.SIGINT)  # as a terminal's Ctrl-C, mid-write
        real(path, data)

    monkeypatch.setattr(batch, "write_atomically", ctrl_c_then_write)
    space, indices, rows = _uis2_rows(40)
    with open_executor("local") as executor:
        result = run_batch(
            _config(tmp_path, space.paths), indices, rows, executor=executor, chunk_size=8
        )
    assert result.interrupted and sent == ["uis2_00000.xosc"]
    assert [r.index for r in result.records] == list(range(8))  # the chunk being written
    assert set(_files(tmp_path)) == {name for r in result.records for name in r.files}


def test_without_dask_the_executor_option_says_how_to_install_it(
    tmp_path: Path, monkeypatch
) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setitem(sys.modules, "distributed", None)  # `import distributed` now fails
    arguments = [str(UIS2), "--n", "2", "-o", str(tmp_path / "out"), "--executor", "dask"]
    result = CliRunner().invoke(sample, arguments)
    assert result.exit_code == 2
    assert "pip install 'sceml[dask]'" in result.output
    assert not (tmp_path / "out").exists()
    scheduler_alone = CliRunner().invoke(sample, [*arguments[:-2], "--scheduler", "tcp://x:1"])
    assert scheduler_alone.exit_code == 2
    assert "needs the dask executor" in scheduler_alone.output


def test_a_worker_killed_mid_run_loses_no_sample_silently(
    tmp_path: Path, cluster: LocalCluster
) -> None:
    space, indices, rows = _uis2_rows(240)
    run_batch(_config(tmp_path / "reference", space.paths), indices, rows, workers=1)
    reference = _files(tmp_path / "reference")
    with Client(cluster) as watcher:
        before = watcher.run(os.getpid)
    victim = min(before.values())
    killed = []

    def kill_a_worker(count: int) -> None:
        if not killed:
            os.kill(victim, signal.SIGKILL)
            killed.append(victim)

    out = tmp_path / "out"
    with open_executor("dask", scheduler=cluster.scheduler_address) as executor:
        result = run_batch(
            _config(out, space.paths),
            indices,
            rows,
            executor=executor,
            chunk_size=3,
            progress=kill_a_worker,
        )
        executor.client.wait_for_workers(2, timeout=30)  # the nanny restarts the killed one
        after = executor.client.run(os.getpid)
    assert victim not in after.values()
    assert sorted(r.index for r in result.records) == list(range(240))
    on_disk = _files(out)
    for record in result.records:
        # Retried samples are written exactly as a local run writes them; lost ones are named.
        if record.status == "failed":
            assert record.reason.startswith("lost: ") and not record.files
        else:
            assert record.status == "written"
            assert all(on_disk[name] == reference[name] for name in record.files)
    assert set(on_disk) == {name for r in result.records for name in r.files}


@pytest.mark.skipif(not hasattr(os, "sched_getaffinity"), reason="Linux's CPU affinity")
def test_the_default_pool_has_a_worker_per_processor_this_process_may_use(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A container's cpuset or `taskset` leaves fewer processors than the machine has.
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {3})
    assert isinstance(open_executor("processes"), LocalExecutor)
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 2, 5})
    pool = open_executor("processes")
    assert isinstance(pool, ProcessExecutor) and pool.parallelism == 3
    assert open_executor("processes", workers=2).parallelism == 2  # asked for: as asked

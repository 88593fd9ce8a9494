"""Scale-out benchmark (issue 18): files/s of `sceml sample` work per executor, and the costs
that bound a bigger cluster.

    .venv/bin/python benchmarks/scale_out.py [--n 10000] [--workers 2] [--tasks 2000] [--out DIR]

`--out` is where the files go (default: the system's temporary folder); a tmpfs such as
/dev/shm takes the disk out of the figures, so that they show the executors' own costs.

All figures come from one run on this machine, through the library (`run_batch`), UIS2
sampled at random into N XSD-checked .xosc files:

1. local: every sample in this process.
2. processes: a local pool of W processes (the default executor).
3. dask: a `distributed.LocalCluster` of W worker processes, one thread each, default chunks.
   The cluster's start is timed separately; the run includes sending the payload and each
   worker's setup (load, flatten, XSD, first full export), as a real run does.
4. Per-task overhead of the dask executor: T tasks that do nothing (task = operator.add) on the
   same cluster, and the same N samples again in chunks of one sample.
5. The caller's share: writing N files of that size atomically, nothing else. Only the caller
   writes, so this is the ceiling of any cluster feeding one caller.
"""

from __future__ import annotations

import argparse
import operator
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent
LOGICAL = REPO / "examples" / "uis2-logical.xmi"


def timed_run(
    executor, n: int, chunk_size: int | None = None, base: str | None = None
) -> tuple[float, int, int]:  # type: ignore[no-untyped-def]
    """Seconds, files and bytes of one sampling run of n samples on `executor`."""
    from sceml.levels.batch import BatchConfig, run_batch
    from sceml.levels.sampling import Plan, values_at
    from sceml.levels.space import parameter_space
    from sceml.model.loading import load_scenario

    space = parameter_space(load_scenario(LOGICAL).root)
    indices = np.arange(n)
    rows = values_at(space, Plan("random", n, seed=7), indices)
    with tempfile.TemporaryDirectory(prefix="sceml-scale-", dir=base) as folder:
        config = BatchConfig(LOGICAL, Path(folder), space.paths, ("xosc",), stem="uis2")
        started = time.perf_counter()
        result = run_batch(config, indices, rows, executor=executor, chunk_size=chunk_size)
        elapsed = time.perf_counter() - started
        files = [Path(folder) / name for r in result.records for name in r.files]
        size = sum(p.stat().st_size for p in files)
    return elapsed, len(files), size


def noop_tasks(executor, count: int) -> float:  # type: ignore[no-untyped-def]
    """Seconds for `count` tasks that do nothing but return."""
    started = time.perf_counter()
    outcomes = list(executor.map_unordered(int, operator.add, "0", list(range(count))))
    elapsed = time.perf_counter() - started
    assert all(o.error is None for o in outcomes)
    return elapsed


def write_floor(n: int, size: int, base: str | None = None) -> float:
    """Seconds to write n files of `size` bytes atomically, as the caller does."""
    from sceml.files.writing import write_atomically

    data = b"x" * size
    with tempfile.TemporaryDirectory(prefix="sceml-write-", dir=base) as folder:
        started = time.perf_counter()
        for i in range(n):
            write_atomically(Path(folder) / f"f_{i:05d}.xosc", data)
        return time.perf_counter() - started


def line(label: str, seconds: float, files: int) -> None:
    print(f"  {label:<44} {seconds:7.2f} s  {files / seconds:7.0f} files/s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=10_000)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--tasks", type=int, default=2000)
    parser.add_argument("--out", default=None, help="folder for the files [default: temp]")
    args = parser.parse_args()
    from sceml.executors import open_executor

    n, w, out = args.n, args.workers, args.out
    where = out or tempfile.gettempdir()
    print(
        f"UIS2, random, N = {n}, W = {w} workers, {os.cpu_count()} CPUs, "
        f"Python {sys.version.split()[0]}, files in {where}"
    )
    with open_executor("local") as local:
        seconds, files, size = timed_run(local, n, base=out)
    per_file = size / max(files, 1)
    line("local (in-process)", seconds, files)
    local_rate = files / seconds
    with open_executor("processes", workers=w) as pool:
        seconds, files, _ = timed_run(pool, n, base=out)
    line(f"processes ({w} workers)", seconds, files)

    started = time.perf_counter()
    with open_executor("dask", workers=w) as dask:
        print(f"  dask LocalCluster start: {time.perf_counter() - started:.2f} s")
        seconds, files, _ = timed_run(dask, n, base=out)
        line(f"dask LocalCluster ({w} workers, default chunks)", seconds, files)
        dask_rate = files / seconds
        small = min(n, 2000)
        chunked, small_files, _ = timed_run(dask, small, base=out)
        single, _, _ = timed_run(dask, small, chunk_size=1, base=out)
        line(f"dask, {small} samples, default chunks", chunked, small_files)
        line(f"dask, {small} samples, one sample per task", single, small_files)
        noop = noop_tasks(dask, args.tasks)
    per_task_noop = noop / args.tasks
    per_task_extra = (single - chunked) / small
    print(
        f"  dask overhead per task: {per_task_noop * 1e3:.2f} ms for an empty task "
        f"({args.tasks} tasks, {args.tasks / noop:.0f} tasks/s through one client), "
        f"{per_task_extra * 1e3:.2f} ms more per sample when each sample is its own task"
    )
    floor = write_floor(n, int(per_file), out)
    line(f"caller writing {n} files of {per_file / 1024:.1f} KiB only", floor, n)

    # On paper: 100 workers, each as fast as one local process here.
    demand = 100 * local_rate
    caller = n / floor
    print(
        f"  100 workers would produce {demand:.0f} files/s ({demand * per_file / 2**20:.0f} MiB/s "
        f"to the caller); the caller writes at most {caller:.0f} files/s; with default chunks "
        f"the scheduler handles {demand / 256:.0f} tasks/s"
    )
    print(f"  two-worker cluster vs local: {dask_rate / local_rate:.2f}x")


if __name__ == "__main__":
    main()

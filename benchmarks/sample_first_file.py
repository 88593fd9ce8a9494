"""How soon `sceml sample` writes its first file, and what stands before it (issue 31).

    git archive <commit> src generated | tar -x -C /tmp/before
    python benchmarks/sample_first_file.py [--before /tmp/before/src:/tmp/before/generated]
        [--n 2000] [--rounds 7] [--large 100000]

Runs `sceml sample examples/uis2-logical.xmi --strategy random --n N --workers 2` into a folder
on /dev/shm (so that the disk's noise stays out), from this checkout and, with `--before`, from
another tree (PYTHONPATH), in turns. Per run:

- the wall time from the command's start to its first .xosc file (polled), the figure issue 31
  sets a goal for (< 0.3 s);
- the CPU path to that file, which the load of a shared machine stretches least: the caller's
  CPU milliseconds when its worker processes fork and when it hands them the first chunks, a
  worker's CPU for its setup and from there to its first file, and the longest chain of them
  (max(chunks sent, fork + setup) + first file), which is the wall time on two idle cores.
  The command runs in this script's own wrapper (`--child`), which wraps functions of
  `sceml.levels.batch` and `sceml.executors` to read the CPU clock; it changes nothing else.

With `--large N`, also the wall time to the first file of an N-sample run (stopped then): what
drawing values before the first chunk costs grows with N. `python -c pass` is the anchor of the
same rounds. Medians of the rounds; the load average at the start and the end.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
LOGICAL = REPO / "examples" / "uis2-logical.xmi"
MAIN = "import sys; sys.argv[0] = 'sceml'; from sceml.cli import main; main()"


def _cpu_ms() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return (usage.ru_utime + usage.ru_stime) * 1000


def child(arguments: list[str]) -> None:
    """Run `sceml` with CPU marks written to stderr as `P fork chunks`, `S setup`, `W first`."""
    import sceml.cli
    import sceml.executors as executors
    import sceml.levels.batch as batch

    marks: dict[str, float] = {}
    pool = executors.ProcessPoolExecutor

    class MarkedPool(pool):  # type: ignore[misc, valid-type]
        def __init__(self, *args: object, **kwargs: object) -> None:
            marks["fork"] = _cpu_ms()
            super().__init__(*args, **kwargs)

    executors.ProcessPoolExecutor = MarkedPool  # type: ignore[misc]
    chunks, setup, written = batch._chunks, batch.setup_worker, batch.write_sample

    def marked_chunks(*args, **kwargs):  # type: ignore[no-untyped-def]
        made = chunks(*args, **kwargs)
        marks["chunks"] = _cpu_ms()
        return made

    def marked_setup(payload):  # type: ignore[no-untyped-def]
        state = setup(payload)
        os.write(2, f"S {_cpu_ms():.1f}\n".encode())
        return state

    def marked_write(*args, **kwargs):  # type: ignore[no-untyped-def]
        record = written(*args, **kwargs)
        if not marks.get("written"):
            marks["written"] = 1
            os.write(2, f"W {_cpu_ms():.1f}\n".encode())
        return record

    batch._chunks, batch.setup_worker, batch.write_sample = (
        marked_chunks,
        marked_setup,
        marked_write,
    )
    parent = os.getpid()

    def report() -> None:
        if os.getpid() == parent:
            os.write(2, f"P {marks['fork']:.1f} {marks['chunks']:.1f}\n".encode())

    import atexit

    atexit.register(report)
    sys.argv = ["sceml", *arguments]
    sceml.cli.main()


def _command(n: int, out: Path, marked: bool) -> list[str]:
    start = [sys.executable, __file__, "--child"] if marked else [sys.executable, "-c", MAIN]
    options = ["--strategy", "random", "--n", str(n), "--seed", "1", "--workers", "2"]
    return [*start, "sample", str(LOGICAL), *options, "-o", str(out)]


def cpu_path(env: dict[str, str], n: int) -> tuple[float, float, float, float, float]:
    """(fork, chunks sent, worker setup, first file after setup, the chain) in CPU ms."""
    base = Path(tempfile.mkdtemp(dir="/dev/shm"))
    try:
        done = subprocess.run(
            _command(n, base / "out", True), env=env, capture_output=True, text=True, check=True
        )
    finally:
        shutil.rmtree(base)
    fork = sent = 0.0
    setups, firsts = [], []
    for line in done.stderr.splitlines():
        kind, *numbers = line.split()
        if kind == "P":
            fork, sent = float(numbers[0]), float(numbers[1])
        elif kind == "S":
            setups.append(float(numbers[0]))
        elif kind == "W":
            firsts.append(float(numbers[0]))
    setup, first = min(setups), min(firsts)
    return fork, sent, setup, first - setup, max(sent, fork + setup) + first - setup


def first_file(env: dict[str, str], n: int) -> float:
    """Wall seconds from the start of `sceml sample` to its first file; the run is then stopped."""
    base = Path(tempfile.mkdtemp(dir="/dev/shm"))
    out = base / "out"
    started = time.perf_counter()
    process = subprocess.Popen(
        _command(n, out, False),
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    try:
        while time.perf_counter() - started < 120:
            if out.is_dir() and any(entry.name.endswith(".xosc") for entry in os.scandir(out)):
                return time.perf_counter() - started
            time.sleep(0.001)
        raise SystemExit("no file within 120 s")
    finally:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        shutil.rmtree(base, ignore_errors=True)


def anchor() -> float:
    started = time.perf_counter()
    subprocess.run([sys.executable, "-c", "pass"], check=True)
    return time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--before", help="PYTHONPATH of another tree, run in turns with this one")
    parser.add_argument("--n", type=int, default=2000)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--large", type=int, default=0, help="also an N-sample run's first file")
    args = parser.parse_args()
    envs = {"this tree": dict(os.environ)}
    if args.before:
        envs = {"before": {**os.environ, "PYTHONPATH": args.before}, **envs}
    paths: dict[str, list[tuple[float, ...]]] = {name: [] for name in envs}
    walls: dict[str, list[float]] = {name: [] for name in envs}
    large: dict[str, list[float]] = {name: [] for name in envs}
    anchors = []
    print(f"load average {_load()} at the start; {args.rounds} rounds, N = {args.n}")
    for number in range(args.rounds):
        anchors.append(anchor())
        names = list(envs) if number % 2 == 0 else list(reversed(envs))
        for name in names:
            walls[name].append(first_file(envs[name], args.n))
            paths[name].append(cpu_path(envs[name], args.n))
            if args.large:
                large[name].append(first_file(envs[name], args.large))
    print(f"anchor, python -c pass: {statistics.median(anchors):.3f} s wall")
    for name in envs:
        fork, sent, setup, first, chain = (
            statistics.median(run[k] for run in paths[name]) for k in range(5)
        )
        runs = ", ".join(f"{w:.2f}" for w in walls[name])
        print(
            f"{name}: first file after {statistics.median(walls[name]):.3f} s wall (runs {runs}); "
            f"CPU ms: caller at the fork {fork:.0f}, chunks sent {sent:.0f}, worker setup "
            f"{setup:.0f}, then its first file {first:.1f}; chain {chain:.0f}"
        )
        if args.large:
            print(
                f"  N = {args.large}: first file after {statistics.median(large[name]):.2f} s wall"
            )
    print(f"load average {_load()} at the end")


def _load() -> str:
    return " ".join(f"{value:.1f}" for value in os.getloadavg())


if __name__ == "__main__":
    if sys.argv[1:2] == ["--child"]:
        child(sys.argv[2:])
    else:
        main()

"""The same commands from two source trees, side by side: what a change did to whole processes.

    git archive <commit> src | tar -x -C /tmp/before
    python benchmarks/before_after.py /tmp/before/src [--rounds 7] [--scale 10000]
        [--samples 2000] [--only NAME ...]

"before" runs the commands with PYTHONPATH set to the given `src` folder (it is found before the
editable install), "after" with this checkout; both with this interpreter and environment, the
runs interleaved (process_cpu.py), with `python -c pass` as the anchor of the same rounds.
Each command runs as the console script runs it (`sceml.cli.main`). Commands: `sceml --help`,
`sceml validate` of UIS1, UIS2 and of a generated scenario of `--scale` nodes
(scale_scenarios.py, on the real map; 0: left out), `sceml simulate` of UIS1 and UIS2 (their
preview pages), and `sceml sample` of UIS2 (random, `--samples` files, 2 workers) with its time
to the first file (the earliest file's modification time).

Printed per command: the medians of CPU seconds (user + system of the process and its
children, as GNU time counts them) and of wall seconds, before and after, and after / before.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from process_cpu import Run, interleaved, load_average, median_cpu, median_wall
from scale_scenarios import write

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"
MAIN = "import sys; sys.argv[0] = 'sceml'; from sceml.cli import main; main()"


def sample_run(env: dict[str, str], out: Path, samples: int) -> tuple[Run, float]:
    """One `sceml sample` run into `out`: its Run and the seconds to its first file."""
    logical = EXAMPLES / "uis2-logical.xmi"
    command = [sys.executable, "-c", MAIN, "sample", str(logical), "--strategy", "random"]
    command += ["--n", str(samples), "--seed", "1", "--format", "xosc", "--workers", "2"]
    command += ["-o", str(out)]
    wall, started = time.time(), time.perf_counter()
    before = os.times()
    subprocess.run(command, env=env, capture_output=True, check=True)
    after = os.times()
    elapsed = time.perf_counter() - started
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    first = min(f.stat().st_mtime_ns for f in out.glob("*.xosc")) / 1e9 - wall
    return Run(elapsed, cpu), first


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("before", type=Path, help="the other tree's src folder")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--scale", type=int, default=10000, help="nodes (0: no such file)")
    parser.add_argument("--samples", type=int, default=2000, help="files (0: no sample run)")
    parser.add_argument("--only", action="append", default=[], help="commands whose name has it")
    args = parser.parse_args()
    plain = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE",)}
    envs = {"before": {**plain, "PYTHONPATH": str(args.before.resolve())}, "after": plain}
    print(f"{args.rounds} rounds, load average {load_average()} at the start")
    with tempfile.TemporaryDirectory() as temporary:
        page = str(Path(temporary) / "preview.html")
        cases = {
            "sceml --help": ["--help"],
            "sceml validate UIS1": ["validate", str(EXAMPLES / "uis1-concrete.xmi")],
            "sceml validate UIS2": ["validate", str(EXAMPLES / "uis2-concrete.xmi")],
            "sceml simulate UIS1": ["simulate", str(EXAMPLES / "uis1-concrete.xmi"), "-o", page],
            "sceml simulate UIS2": ["simulate", str(EXAMPLES / "uis2-concrete.xmi"), "-o", page],
        }
        if args.scale:
            scale = write(args.scale, Path(temporary))
            cases[f"sceml validate {args.scale} nodes"] = ["validate", str(scale)]
        cases = {k: v for k, v in cases.items() if not args.only or any(o in k for o in args.only)}
        print(
            f"{'command':30s} {'CPU before':>10s} {'after':>7s} {'after/before':>12s}"
            f" {'wall before':>11s} {'after':>7s} {'after/before':>12s}"
        )
        anchor = [sys.executable, "-c", "pass"]
        for name, arguments in cases.items():
            command = [sys.executable, "-c", MAIN, *arguments]
            runs = interleaved(
                {"before": command, "after": command, "python -c pass": anchor},
                args.rounds,
                env=plain,
                envs=envs,
            )
            _row(name, runs["before"], runs["after"])
            _row("  python -c pass (anchor)", runs["python -c pass"], runs["python -c pass"])
        if args.samples and (not args.only or any(o in "sceml sample" for o in args.only)):
            _samples(envs, Path(temporary), args.rounds, args.samples)
    print(f"load average {load_average()} at the end")


def _row(name: str, before: list[Run], after: list[Run]) -> None:
    cpu_b, cpu_a = median_cpu(before), median_cpu(after)
    wall_b, wall_a = median_wall(before), median_wall(after)
    print(
        f"{name:30s} {cpu_b:10.3f} {cpu_a:7.3f} {cpu_a / cpu_b:12.2f}"
        f" {wall_b:11.3f} {wall_a:7.3f} {wall_a / wall_b:12.2f}"
    )


def _samples(envs: dict[str, dict[str, str]], folder: Path, rounds: int, samples: int) -> None:
    runs: dict[str, list[tuple[Run, float]]] = {"before": [], "after": []}
    for number in range(max(3, rounds // 2)):
        for tree in ("before", "after") if number % 2 == 0 else ("after", "before"):
            out = folder / f"{tree}-{number}"
            runs[tree].append(sample_run(envs[tree], out, samples))
            shutil.rmtree(out)
    _row(
        f"sceml sample N={samples}, whole",
        [r for r, _ in runs["before"]],
        [r for r, _ in runs["after"]],
    )
    before = statistics.median(first for _, first in runs["before"])
    after = statistics.median(first for _, first in runs["after"])
    print(
        f"{'  ... wall to the first file':30s} {'':10s} {'':7s} {'':12s} {before:11.3f} {after:7.3f} {after / before:12.2f}"
    )


if __name__ == "__main__":
    main()

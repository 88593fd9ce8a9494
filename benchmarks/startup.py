"""Whole-process time of short commands, beside the interpreter's own start, in one run.

    python benchmarks/startup.py [--runs 15]

Each command runs as a fresh process (as a user or CI script runs it), with bytecode caching on,
after one warm-up run that writes the caches. Prints the median wall time of each and its ratio
to `python -c pass`, so a noisy machine shows in both. The target for `sceml validate` of UIS1 is
under 0.25 s (issue 17).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
UIS1 = REPO / "examples" / "uis1-concrete.xmi"
COMMANDS = {
    "python -c pass": [sys.executable, "-c", "pass"],
    "sceml --help": [sys.executable, "-m", "sceml.cli", "--help"],
    "sceml info UIS1": [sys.executable, "-m", "sceml.cli", "info", str(UIS1)],
    "sceml validate UIS1": [sys.executable, "-m", "sceml.cli", "validate", str(UIS1)],
}


def median_seconds(command: list[str], runs: int, env: dict[str, str]) -> float:
    subprocess.run(command, env=env, capture_output=True, check=True)  # warm-up: writes .pyc
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(command, env=env, capture_output=True, check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15, help="runs per command (default 15)")
    runs = parser.parse_args().runs
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    base = None
    for name, command in COMMANDS.items():
        seconds = median_seconds(command, runs, env)
        base = base or seconds
        print(f"{name:22s} {seconds * 1000:7.0f} ms  {seconds / base:5.1f}x python")


if __name__ == "__main__":
    main()

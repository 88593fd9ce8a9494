"""Timing whole processes side by side on a noisy machine: shared by the benchmark scripts.

Each round runs every command once, in an order that rotates from round to round, so a burst
of load from other jobs falls on the subject and its anchor alike; the figures are medians of
the rounds. Nothing here is timed by the test suite.
"""

from __future__ import annotations

import statistics
import subprocess
import time
from collections.abc import Mapping, Sequence


def interleaved(
    commands: Mapping[str, Sequence[str]],
    rounds: int,
    env: Mapping[str, str] | None = None,
    envs: Mapping[str, Mapping[str, str]] | None = None,
) -> dict[str, list[float]]:
    """Wall seconds of each command per round, the commands taken in turn; one warm-up each
    first (it writes the bytecode caches, as any second run of a command finds them). `envs`:
    a command's own environment, by name, instead of `env`."""
    names = list(commands)
    chosen = {name: (envs or {}).get(name, env) for name in names}
    for name in names:
        _run(commands[name], chosen[name])
    seconds: dict[str, list[float]] = {name: [] for name in names}
    for round_number in range(rounds):
        shift = round_number % len(names)
        for name in names[shift:] + names[:shift]:
            seconds[name].append(_run(commands[name], chosen[name]))
    return seconds


def median(values: Sequence[float]) -> float:
    return statistics.median(values)


def _run(command: Sequence[str], env: Mapping[str, str] | None) -> float:
    started = time.perf_counter()
    done = subprocess.run(list(command), env=env, capture_output=True)
    elapsed = time.perf_counter() - started
    if done.returncode not in (0, 1):  # 1: the command found errors, which is still a run
        raise SystemExit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr!r}")
    return elapsed

"""CPU seconds of whole processes, taken in turn with their anchors: for a machine shared by others.

On a busy machine a process's wall time is mostly waiting for a core, and the anchor's wait
is not the subject's; the CPU time the kernel charges the process (user + system, from
`wait4`, as GNU time reports it) counts only its own work. It is not free of the load either
(caches and frequency are shared), so the subject and its anchors still run in turn, round by
round, in an order that rotates (as side_by_side.py does for wall time), and the figures are
medians. Nothing here is timed by the test suite.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass


@dataclass(frozen=True)
class Run:
    """One process: wall seconds from start to reaped, CPU seconds (user + system)."""

    wall: float
    cpu: float


def interleaved(
    commands: Mapping[str, Sequence[str]],
    rounds: int,
    env: Mapping[str, str] | None = None,
    envs: Mapping[str, Mapping[str, str]] | None = None,
) -> dict[str, list[Run]]:
    """Each command's runs, one per round, the commands taken in turn; one warm-up each first
    (it writes the bytecode caches). `envs`: a command's own environment, by name."""
    names = list(commands)
    chosen = {name: (envs or {}).get(name, env) for name in names}
    for name in names:
        run(commands[name], chosen[name])
    runs: dict[str, list[Run]] = {name: [] for name in names}
    for round_number in range(rounds):
        shift = round_number % len(names)
        for name in names[shift:] + names[:shift]:
            runs[name].append(run(commands[name], chosen[name]))
    return runs


def run(command: Sequence[str], env: Mapping[str, str] | None = None) -> Run:
    """Run `command` to its end, its output discarded; exit status 0 or 1 (findings) expected."""
    started = time.perf_counter()
    process = subprocess.Popen(
        list(command), env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    assert process.stderr is not None
    errors = process.stderr.read()
    _, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - started
    process.returncode = os.waitstatus_to_exitcode(status)
    process.stderr.close()
    if process.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(command)} failed ({process.returncode}):\n{errors!r}")
    return Run(wall, usage.ru_utime + usage.ru_stime)


def median_cpu(runs: Sequence[Run]) -> float:
    return statistics.median(r.cpu for r in runs)


def median_wall(runs: Sequence[Run]) -> float:
    return statistics.median(r.wall for r in runs)


def load_average() -> str:
    """The 1-minute load average now, for the figures' caption."""
    return f"{os.getloadavg()[0]:.1f}"

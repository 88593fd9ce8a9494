"""How many processors this process may use: what sizes its pools of workers."""

from __future__ import annotations

import os


def processors() -> int:
    """The processors this process may run on: its CPU affinity (a container's cpuset,
    `taskset`), not every processor the machine has, where the system says (Linux); more
    workers than that would only queue for them."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1

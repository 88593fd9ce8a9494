"""How many samples or runs a command may be asked for: what this machine's memory and disk hold.

A count is checked before anything is allocated: `--n 1e9` would ask numpy for gigabytes of
indices and the disk for a billion files, a grid of two 800,001-level ranges for 640 billion
samples. The estimate is deliberately simple (bytes per sample in memory, a file size on disk)
and the refusal says what the request would take beside what is free.
"""

from __future__ import annotations

import os
import re
import shutil
from pathlib import Path

from ..errors import ArgumentError, LoadError
from ..files.safefiles import read_input
from .paths import LevelArgumentError

#: What one sample holds in memory while a run lasts: its values, its row in the manifest and the
#: bookkeeping of its task. Measured at about 1 KB on the examples; counted generously.
SAMPLE_MEMORY_BYTES = 2048

#: At most this share of the memory free now may be asked for.
MEMORY_SHARE = 0.5

# Whole numbers as people type them for counts: 1000, 1_000, 1e6, 2^20.
_COUNT = re.compile(r"(\d[\d_]*)|(\d+)[eE](\d+)|(\d+)\^(\d+)")
_MAX_DIGITS = 30  # a count beyond 10^30 is refused by its size below anyway


def parse_count(text: str) -> int:
    """A count typed as `1000`, `1e6` or `2^20` (a whole number); ArgumentError otherwise."""
    found = _COUNT.fullmatch(text.strip())
    if found is None:
        raise ArgumentError(f"{text!r} is not a whole number (e.g. 1000, 1e6 or 2^20)")
    plain, mantissa, exponent, base, power = found.groups()
    if plain is not None:
        digits = plain.replace("_", "")
        if len(digits) > _MAX_DIGITS:
            raise ArgumentError(f"{text!r} is too large a count")
        return int(digits)
    if mantissa is not None:
        if int(exponent) > _MAX_DIGITS:
            raise ArgumentError(f"{text!r} is too large a count")
        return int(int(mantissa) * 10 ** int(exponent))
    if int(power) * max(1, len(base)) > 4 * _MAX_DIGITS:
        raise ArgumentError(f"{text!r} is too large a count")
    return int(int(base) ** int(power))


def check_count(
    count: int,
    what: str,
    *,
    memory_each: int,
    disk_each: int = 0,
    folder: Path | None = None,
    hint: str = "",
) -> None:
    """Refuse (LevelArgumentError) `count` items of `what` when they would not fit.

    Each takes `memory_each` bytes while the command runs and `disk_each` bytes in `folder`.
    The message says how much the request would take and how much is free.
    """
    memory = count * memory_each
    disk = count * disk_each
    free_memory = available_memory()
    problems = []
    if memory > free_memory * MEMORY_SHARE:
        problems.append(
            f"about {amount(memory)} of memory (available: {amount(free_memory)}, of which at "
            "most half is used)"
        )
    if disk and folder is not None:
        free_disk = free_space(folder)
        if disk > free_disk:
            problems.append(f"about {amount(disk)} of disk (free in {folder}: {amount(free_disk)})")
    if problems:
        raise LevelArgumentError(
            f"{count:,} {what} would take " + " and ".join(problems) + (f"; {hint}" if hint else "")
        )


def available_memory() -> int:
    """Bytes of memory this process may still use: what the system has available (free, and
    caches it would give back), or the process's address space limit if that is lower."""
    free = _system_available()
    try:
        import resource

        limit, _ = resource.getrlimit(resource.RLIMIT_AS)
    except (ImportError, OSError, ValueError):
        return free
    return free if limit == resource.RLIM_INFINITY else min(free, limit)


def _system_available() -> int:
    # Linux says what it could give (MemAvailable, page cache included); elsewhere the free
    # pages are the estimate, or a generous guess where even those are not told.
    try:
        for line in read_input("/proc/meminfo", max_bytes=1 << 16).decode().splitlines():
            name, _, value = line.partition(":")
            if name == "MemAvailable":
                return int(value.split()[0]) * 1024
    except (OSError, LoadError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return 8 * 2**30


def free_space(folder: Path) -> int:
    """Free bytes on the file system that holds `folder` (or its nearest existing parent)."""
    for candidate in [folder, *folder.absolute().parents]:
        try:
            return shutil.disk_usage(candidate).free
        except OSError:
            continue
    return 0


def amount(size: int) -> str:
    """Bytes for people: 512 bytes, 3.2 MiB, 4.66 TiB."""
    value = float(size)
    for unit in ("bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"):
        if value < 1024 or unit == "EiB":
            return f"{size} bytes" if unit == "bytes" else f"{value:.3g} {unit}"
        value /= 1024
    raise AssertionError("unreachable")

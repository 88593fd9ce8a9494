"""What writing a batch's files costs, by way of writing them (issue 17).

    .venv/bin/python benchmarks/write_schemes.py [--n 3000] [--rounds 5] [--dir DIR] [--size BYTES]

Writes N files of SIZE bytes (default 26,600: one UIS2 .xosc) into a new folder under DIR
(default: the system's temporary folder) in one process, once per scheme and round; the order
of the schemes rotates every round and each figure is the median of the rounds, because the
disk of a shared machine is noisy. Schemes:

- plain: open, write, close; nothing guards against a half-written file (the floor's write).
- atomic: `sceml.files.writing.write_atomically`: a temporary file beside the target (mkstemp), chmod,
  rename; what every SceML command writes with.
- staged: `sceml.files.writing.write_staged`: a file of the target's name in a staging folder inside the
  output folder, then a rename into place; what the batch's worker processes write with.
- tmpfile: Linux `O_TMPFILE` (a file with no name until it is complete) and `linkat` through
  /proc/self/fd. It cannot replace an existing file, so a batch would still need a second
  scheme for reruns into the same folder; measured to see whether that is worth it.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from sceml.files.writing import write_atomically, write_staged

Scheme = Callable[[Path, int, bytes], None]


def plain(folder: Path, index: int, data: bytes) -> None:
    with open(folder / f"f_{index:06d}.xosc", "wb") as stream:
        stream.write(data)


def atomic(folder: Path, index: int, data: bytes) -> None:
    write_atomically(folder / f"f_{index:06d}.xosc", data)


def staged(folder: Path, index: int, data: bytes) -> None:
    write_staged(folder / f"f_{index:06d}.xosc", data, folder / ".staging")


def tmpfile(folder: Path, index: int, data: bytes) -> None:
    handle = os.open(folder, os.O_TMPFILE | os.O_WRONLY, 0o644)
    try:
        os.write(handle, data)
        # dst_dir_fd makes Python call linkat(..., AT_SYMLINK_FOLLOW), which links the open file.
        where = os.open(folder, os.O_RDONLY)
        try:
            os.link(f"/proc/self/fd/{handle}", f"f_{index:06d}.xosc", dst_dir_fd=where)
        finally:
            os.close(where)
    finally:
        os.close(handle)


SCHEMES: dict[str, Scheme] = {
    "plain": plain,
    "atomic": atomic,
    "staged": staged,
    "tmpfile": tmpfile,
}


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--n", type=int, default=3_000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--dir", type=Path, default=None)
    parser.add_argument("--size", type=int, default=26_600)
    args = parser.parse_args()
    data = (b"<x/>\n" * (args.size // 5 + 1))[: args.size]
    names = list(SCHEMES)
    times: dict[str, list[float]] = {name: [] for name in names}
    print(
        f"{args.n} files of {args.size} bytes, {args.rounds} rounds, under {args.dir or tempfile.gettempdir()}"
    )
    for number in range(args.rounds):
        for name in names[number % len(names) :] + names[: number % len(names)]:
            folder = Path(tempfile.mkdtemp(prefix="sceml-writes-", dir=args.dir))
            (folder / ".staging").mkdir()
            write = SCHEMES[name]
            started = time.perf_counter()
            for index in range(args.n):
                write(folder, index, data)
            times[name].append((time.perf_counter() - started) / args.n)
            shutil.rmtree(folder)
    floor = statistics.median(times["plain"])
    for name in names:
        each = statistics.median(times[name])
        print(f"{name:8s} {each * 1e3:.3f} ms per file ({each / floor:.2f}x plain)")


if __name__ == "__main__":
    main()

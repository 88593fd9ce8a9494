"""What writing a batch's files costs, by way of writing them (issue 17).

    .venv/bin/python benchmarks/write_schemes.py [--n 3000] [--rounds 5] [--dir DIR] [--size BYTES]
        [--writers K]

Writes N files of SIZE bytes (default 26,600: one UIS2 .xosc) into a new folder under DIR
(default: the system's temporary folder), once per scheme and round, by K processes at once
(default 1; `sceml sample`'s workers are K processes writing into one folder), each taking
every K-th file; the order of the schemes rotates every round and each figure is the median of
the rounds' wall time per file, because the disk of a shared machine is noisy. Schemes:

- plain: open, write, close; nothing guards against a half-written file (the floor's write).
- atomic: `sceml.files.writing.write_atomically`: a temporary file beside the target (mkstemp), chmod,
  rename; what every SceML command writes with.
- renamed: a file of the target's name in a staging folder inside the output folder, then a
  rename into place: what `write_staged` does where the system makes no unnamed files, and for
  a file that exists already.
- staged: `sceml.files.writing.write_staged`, what the batch's worker processes write with: on
  Linux, a new file is made unnamed (`O_TMPFILE`) in its folder and linked under its name once
  complete (`linkat` through /proc/self/fd).

With several writers, the renames queue on the folder's lock and, from another folder, on the
file system's rename lock; an unnamed file takes the folder's lock once.
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

from sceml.files import writing
from sceml.files.writing import write_atomically, write_staged

Scheme = Callable[[Path, int, bytes], None]


def plain(folder: Path, index: int, data: bytes) -> None:
    with open(folder / f"f_{index:06d}.xosc", "wb") as stream:
        stream.write(data)


def atomic(folder: Path, index: int, data: bytes) -> None:
    write_atomically(folder / f"f_{index:06d}.xosc", data)


def staged(folder: Path, index: int, data: bytes) -> None:
    write_staged(folder / f"f_{index:06d}.xosc", data, folder / ".staging")


def renamed(folder: Path, index: int, data: bytes) -> None:
    unnamed, writing._unnamed_files = writing._unnamed_files, False
    try:
        write_staged(folder / f"f_{index:06d}.xosc", data, folder / ".staging")
    finally:
        writing._unnamed_files = unnamed


SCHEMES: dict[str, Scheme] = {
    "plain": plain,
    "atomic": atomic,
    "renamed": renamed,
    "staged": staged,
}


def write_all(write: Scheme, folder: Path, n: int, data: bytes, writers: int) -> None:
    """Every file, by `writers` forked processes each writing every `writers`-th one."""
    if writers == 1:
        for index in range(n):
            write(folder, index, data)
        return
    children = []
    for first in range(writers):
        child = os.fork()
        if child == 0:
            try:
                for index in range(first, n, writers):
                    write(folder, index, data)
            finally:
                os._exit(0)
        children.append(child)
    for child in children:
        os.waitpid(child, 0)


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--n", type=int, default=3_000)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--dir", type=Path, default=None)
    parser.add_argument("--size", type=int, default=26_600)
    parser.add_argument("--writers", type=int, default=1)
    args = parser.parse_args()
    data = (b"<x/>\n" * (args.size // 5 + 1))[: args.size]
    names = list(SCHEMES)
    times: dict[str, list[float]] = {name: [] for name in names}
    print(
        f"{args.n} files of {args.size} bytes by {args.writers} process(es), {args.rounds} rounds, "
        f"under {args.dir or tempfile.gettempdir()}"
    )
    for number in range(args.rounds):
        for name in names[number % len(names) :] + names[: number % len(names)]:
            folder = Path(tempfile.mkdtemp(prefix="sceml-writes-", dir=args.dir))
            (folder / ".staging").mkdir()
            write = SCHEMES[name]
            started = time.perf_counter()
            write_all(write, folder, args.n, data, args.writers)
            times[name].append((time.perf_counter() - started) / args.n)
            shutil.rmtree(folder)
    floor = statistics.median(times["plain"])
    for name in names:
        each = statistics.median(times[name])
        print(f"{name:8s} {each * 1e3:.3f} ms per file ({each / floor:.2f}x plain)")


if __name__ == "__main__":
    main()

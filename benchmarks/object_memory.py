"""Where a loaded model's memory goes: bytes per model object, by the line that allocated them.

    python benchmarks/object_memory.py [--nodes 10000] [--top 12]

On a `scale_scenarios.py` scenario of `--nodes` nodes (the real map, every node kind, valid),
in fresh processes:

- ours: `sceml.model.loading.load` of the file, peak resident memory (VmHWM, Linux) of the process,
  with pyecore's full objects and `read_only=True` (`sceml validate`'s lighter objects);
- the anchor: the same file parsed with lxml, peak resident memory of that process;
- each less what its process holds after its imports alone (the load's and the parse's own).

Then, in this process, tracemalloc over each load: the Python bytes that stay allocated once it
returns (the parse tree is gone by then), per model object, grouped by the source line that
allocated them. lxml's own tree is C memory, which tracemalloc does not see; that is why the
anchor is a whole process. Issue 31's goal: at 208k nodes, at most 2x lxml's memory.
"""

from __future__ import annotations

import argparse
import gc
import subprocess
import sys
import tempfile
import tracemalloc
from pathlib import Path

from scale_scenarios import write

from sceml.model.loading import load
from sceml.model.traversal import all_contents

# VmHWM, not ru_maxrss: a child's ru_maxrss starts from its parent's (this process's) peak.
PEAK = (
    "import sys; {body}; "
    "print(next(l.split()[1] for l in open('/proc/self/status') if l.startswith('VmHWM')))"
)
PROGRAMS = {
    "python + lxml import": PEAK.format(body="import lxml.etree"),
    "python + sceml loading import": PEAK.format(body="from sceml.model.loading import load"),
    "lxml parse (anchor)": PEAK.format(body="from lxml import etree; etree.parse(sys.argv[1])"),
    "sceml.model.loading.load (ours)": PEAK.format(
        body="from sceml.model.loading import load; load(sys.argv[1])"
    ),
    "... read_only=True": PEAK.format(
        body="from sceml.model.loading import load; load(sys.argv[1], read_only=True)"
    ),
}


def peak_megabytes(program: str, path: Path) -> float:
    """Peak resident memory, in MB, of a fresh process running `program` on `path`."""
    done = subprocess.run(
        [sys.executable, "-c", program, str(path)], capture_output=True, text=True, check=True
    )
    return int(done.stdout.split()[-1]) / 1024  # VmHWM is in kB


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nodes", type=int, default=10000)
    parser.add_argument("--top", type=int, default=12, help="allocating lines shown")
    parser.add_argument("--load", choices=["full", "read-only"], help=argparse.SUPPRESS)
    parser.add_argument("file", nargs="?", type=Path, help=argparse.SUPPRESS)
    arguments = parser.parse_args(argv)
    if arguments.load:  # one load, in this fresh process (see below)
        kept_by_load(arguments.file, arguments.load == "read-only", arguments.top)
        return
    with tempfile.TemporaryDirectory() as temporary:
        path = write(arguments.nodes, Path(temporary))
        print(f"{path.name}: {path.stat().st_size / 1e6:.1f} MB")
        peaks = {name: peak_megabytes(program, path) for name, program in PROGRAMS.items()}
        for name, megabytes in peaks.items():
            print(f"  peak RSS {name:<24} {megabytes:8.1f} MB")
        imports = peaks["python + sceml loading import"]
        anchor = peaks["lxml parse (anchor)"] - peaks["python + lxml import"]
        for name in ("sceml.model.loading.load (ours)", "... read_only=True"):
            ours = peaks[name] - imports
            print(
                f"  above the imports: {name} {ours:.1f} MB, lxml {anchor:.1f} MB, "
                f"{ours / anchor:.2f}x"
            )
        # Each load in a process of its own: CPython shares a class's attribute-key tables
        # between instances, so a load's figure depends on what the process made before it.
        sys.stdout.flush()  # before the children's lines, when stdout is a pipe
        for mode in ("full", "read-only"):
            subprocess.run(
                [sys.executable, __file__, "--load", mode, "--top", str(arguments.top), str(path)],
                check=True,
            )


def kept_by_load(path: Path, read_only: bool, top: int) -> None:
    """Print the Python bytes a load keeps, per model object, by the line that allocated them."""
    gc.collect()
    tracemalloc.start(1)
    document = load(path, read_only=read_only)
    gc.collect()
    snapshot = tracemalloc.take_snapshot()
    tracemalloc.stop()
    objects = 1 + sum(1 for _ in all_contents(document.root))
    total = sum(stat.size for stat in snapshot.statistics("filename"))
    print(
        f"\nload(read_only={read_only}): {objects} model objects; Python bytes kept by the "
        f"load: {total / 1e6:.1f} MB, {total / objects:.0f} B per model object"
    )
    print(f"{'B/object':>9} {'blocks/object':>13}  allocated at")
    for stat in snapshot.statistics("lineno")[:top]:
        frame = stat.traceback[0]
        where = frame.filename.split("site-packages/")[-1]
        print(f"{stat.size / objects:>9.0f} {stat.count / objects:>13.2f}  {where}:{frame.lineno}")
    del document


if __name__ == "__main__":
    main()

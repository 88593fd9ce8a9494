"""Benchmark: load a large scenario XMI with pyecore's decoder, with SceML's reader, and with EMF.

Builds each scenario with the builder API (many actors, forks into parallel chains, joins), saves
it with sceml.io, then in one run times `sceml.io.load` through pyecore's own decoder
(`SafeXMIResource.fast_decoding = False`) and through the fast reader (sceml.xmi_reader, the
default), and the EMF harness of tests/emf (its `load` mode reports its own load time, JVM start
excluded). It also times a deep copy of the loaded model with pyecore's setters (SetterCopier)
and with the direct copier (Copier). Each figure is the best of `--repeat` runs, and the
ratios compare figures measured side by side, since these machines are shared and noisy.

`--validate N` also builds a scenario of N nodes and runs `sceml validate` on it in a fresh
process, reporting its wall time and peak resident memory (issue 17: under 20 s and 1 GB for
about 208k nodes). Needs javac, java and /usr/share/java/eclipse-emf-*.jar.

    .venv/bin/python benchmarks/xmi_load.py [--sizes 10000,50000] [--repeat 3] [--validate 208000]
"""

from __future__ import annotations

import argparse
import gc
import os
import re
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from sceml import io
from sceml.build import ScenarioBuilder, lane
from sceml.collector import collector_paused
from sceml.copying import Copier, SetterCopier

REPO = Path(__file__).resolve().parents[1]
HARNESS = REPO / "tests" / "emf" / "java" / "SceMLHarness.java"
ECORE = REPO / "metamodel" / "scemlmodel.ecore"
JARS = [f"/usr/share/java/eclipse-emf-{name}.jar" for name in ("common", "ecore", "ecore-xmi")]
KINDS = ["Accelerate", "KeepVelocity", "TimeElapsed", "Decelerate", "DriveDistance"]
SCEML = Path(sys.executable).with_name("sceml")


def build(nodes: int, actors: int = 50, chain: int = 8) -> ScenarioBuilder:
    """A scenario of about `nodes` action nodes: blocks of parallel chains merged by joins."""
    builder = ScenarioBuilder("Large", level="concrete", max_duration=600)
    people = [
        builder.actor("Car", f"car{i}", ego=i == 0, start=lane(1, 1 + i % 3, 5.0 * i), speed=5)
        for i in range(actors)
    ]
    previous, made, block = builder.root, 0, 0
    while made < nodes:
        ends = []
        for branch in range(4):  # a fork into four chains, merged by one join
            actor = people[(block * 4 + branch) % actors]
            steps = [builder.add(KINDS[(made + k) % len(KINDS)], actor) for k in range(chain)]
            made += chain
            builder.chain(previous, *steps)
            ends.append(steps[-1])
        previous = builder.join_all(*ends) if block % 2 else builder.join_one(*ends)
        block += 1
    builder.flow(previous, builder.end)
    return builder


def compile_harness(folder: Path) -> str:
    """Compile the harness into `folder`; return the classpath to run it."""
    classpath = os.pathsep.join(JARS)
    subprocess.run(["javac", "-d", str(folder), "-cp", classpath, str(HARNESS)], check=True)
    return os.pathsep.join([str(folder), classpath])


def best_of(repeat: int, run: Callable[[], object]) -> float:
    """The shortest of `repeat` timed runs; what a run leaves is collected before the next."""
    times = []
    for _ in range(repeat):
        gc.collect()
        started = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - started)
        del result
    gc.collect()
    return min(times)


def load_with(path: Path, fast: bool) -> io.Document:
    """Load `path` through the fast reader or through pyecore's decoder."""
    io.SafeXMIResource.fast_decoding = fast
    try:
        return io.load(path)
    finally:
        io.SafeXMIResource.fast_decoding = True


def emf_load(path: Path, classpath: str) -> tuple[int, float]:
    """EMF's own load time of `path` (seconds, JVM start excluded) and its object count."""
    result = subprocess.run(
        ["java", "-cp", classpath, "SceMLHarness", "load", str(ECORE), str(path)],
        capture_output=True,
        text=True,
        check=True,
    )
    found = re.search(r"LOADED (\d+) objects in ([\d.]+) ms", result.stdout)
    assert found, result.stdout
    return int(found.group(1)), float(found.group(2)) / 1000


def copy_with(make: type[Copier], document: io.Document) -> object:
    """A deep copy of the loaded model, references mapped into the copy, with the collector
    paused as flattening pauses it."""
    with collector_paused():
        copier = make()
        duplicate = copier.copy(document.root)
        copier.copy_references()
    return duplicate


def measure(nodes: int, folder: Path, classpath: str, repeat: int) -> None:
    """Print load times (pyecore, fast reader, EMF) and copy times for one size."""
    path = io.save(build(nodes).scenario, folder / f"large-{nodes}.xmi")
    pyecore_s = best_of(repeat, lambda: load_with(path, fast=False))
    fast_s = best_of(repeat, lambda: load_with(path, fast=True))
    runs = [emf_load(path, classpath) for _ in range(repeat)]
    emf_objects, emf_s = runs[0][0], min(seconds for _, seconds in runs)
    document = load_with(path, fast=True)
    count = 1 + sum(1 for _ in document.root.eAllContents())
    setters_s = best_of(repeat, lambda: copy_with(SetterCopier, document))
    direct_s = best_of(repeat, lambda: copy_with(Copier, document))
    size_mb = path.stat().st_size / 1e6
    print(f"{nodes:>6} nodes, {count} objects ({emf_objects} in EMF), {size_mb:.1f} MB:")
    print(
        f"    load: pyecore decoder {pyecore_s:.2f} s, fast reader {fast_s:.2f} s, "
        f"EMF {emf_s:.2f} s; fast/EMF {fast_s / emf_s:.2f}x, fast/pyecore {fast_s / pyecore_s:.2f}x"
    )
    print(
        f"    copy: setters {setters_s:.2f} s, direct {direct_s:.2f} s; "
        f"direct/setters {direct_s / setters_s:.2f}x"
    )


def validate_fresh(nodes: int, folder: Path) -> None:
    """Print the wall time and peak memory of `sceml validate` on `nodes` nodes, fresh process."""
    path = io.save(build(nodes).scenario, folder / f"validate-{nodes}.xmi")
    started = time.perf_counter()
    process = subprocess.Popen(
        [str(SCEML), "validate", str(path)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    _, status, usage = os.wait4(process.pid, 0)  # this child's own peak, not every child's
    wall_s = time.perf_counter() - started
    errors = process.stderr.read().decode() if process.stderr else ""
    print(
        f"{nodes:>6} nodes, {path.stat().st_size / 1e6:.1f} MB: sceml validate in a fresh process "
        f"{wall_s:.1f} s, peak RSS {usage.ru_maxrss / 1024:.0f} MB, "
        f"exit {os.waitstatus_to_exitcode(status)}{' ' + errors.strip() if errors else ''}"
    )


def main() -> int:
    """Run the benchmark."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--sizes", default="10000,50000", help="action node counts, comma-separated"
    )
    parser.add_argument("--repeat", type=int, default=3, help="runs per figure (the best counts)")
    parser.add_argument(
        "--validate", type=int, default=0, help="also validate a scenario of this many nodes"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        if args.sizes:
            classpath = compile_harness(folder / "classes")
            for size in (int(s) for s in args.sizes.split(",")):
                measure(size, folder, classpath, args.repeat)
        if args.validate:
            validate_fresh(args.validate, folder)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Benchmark: load the same large scenario XMI (10k and 50k nodes) with pyecore and with Eclipse EMF.

Builds each scenario with the builder API (many actors, forks into parallel chains, joins), saves
it with sceml.io, then in one run times `sceml.io.load` and the EMF harness of tests/emf (its
`load` mode reports its own load time, JVM start excluded; the wall time of the whole java
process is shown too). Needs javac, java and /usr/share/java/eclipse-emf-*.jar.

    .venv/bin/python benchmarks/xmi_load.py [--sizes 10000,50000]
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from sceml import io
from sceml.build import ScenarioBuilder, lane

REPO = Path(__file__).resolve().parents[1]
HARNESS = REPO / "tests" / "emf" / "java" / "SceMLHarness.java"
ECORE = REPO / "metamodel" / "scemlmodel.ecore"
JARS = [f"/usr/share/java/eclipse-emf-{name}.jar" for name in ("common", "ecore", "ecore-xmi")]
KINDS = ["Accelerate", "KeepVelocity", "TimeElapsed", "Decelerate", "DriveDistance"]


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


def measure(nodes: int, folder: Path, classpath: str) -> None:
    """Print pyecore and EMF load times for one size."""
    path = io.save(build(nodes).scenario, folder / f"large-{nodes}.xmi")
    started = time.perf_counter()
    document = io.load(path)
    pyecore_s = time.perf_counter() - started
    count = 1 + sum(1 for _ in document.root.eAllContents())
    started = time.perf_counter()
    result = subprocess.run(
        ["java", "-cp", classpath, "SceMLHarness", "load", str(ECORE), str(path)],
        capture_output=True,
        text=True,
        check=True,
    )
    wall_s = time.perf_counter() - started
    found = re.search(r"LOADED (\d+) objects in ([\d.]+) ms", result.stdout)
    assert found, result.stdout
    emf_s = float(found.group(2)) / 1000
    size_mb = path.stat().st_size / 1e6
    print(
        f"{nodes:>6} nodes, {count} objects ({int(found.group(1))} in EMF), {size_mb:.1f} MB: "
        f"pyecore {pyecore_s:.2f} s, EMF {emf_s:.2f} s (java wall {wall_s:.2f} s), "
        f"pyecore/EMF {pyecore_s / emf_s:.1f}x"
    )


def main() -> int:
    """Run the benchmark."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--sizes", default="10000,50000", help="action node counts, comma-separated"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        classpath = compile_harness(folder / "classes")
        for size in (int(s) for s in args.sizes.split(",")):
            measure(size, folder, classpath)
    return 0


if __name__ == "__main__":
    sys.exit(main())

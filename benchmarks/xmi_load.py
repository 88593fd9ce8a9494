"""Benchmark: load a large scenario XMI with SceML (Python) and with Eclipse EMF, like with like.

Builds each scenario with the builder API (many actors, forks into parallel chains, joins; every
node with its parameters, so the file is valid, which is checked before anything is timed) and
saves it with sceml.model. Then, side by side in one run:

- cold, whole process: a fresh `python -c "sceml.model.loading.load(FILE)"` against a fresh `java EmfLoad
  ECORE FILE 1` (benchmarks/java/EmfLoad.java: EMF's XMI resource, the metamodel registered
  first), the runs interleaved, medians; and the load alone inside those same processes (each
  prints its own load time), without the interpreter's or the JVM's start;
- warm, in one process: the best of `--repeat` loads in this process against the best of
  `--repeat` loads in one JVM after its first (JIT-compiled by then);
- pyecore's own decoder (`SafeXMIResource.fast_decoding = False`) warm, and a deep copy of the
  loaded model with pyecore's setters (SetterCopier) and with the direct copier (Copier).

Issue 31's goal: at most 1.5x EMF at 50k nodes, with process start.

`--validate N` also builds a scenario of N nodes and runs `sceml validate` on it in fresh
processes (`--validate-rounds`), reporting wall and CPU time, the time from the summary line to
the process's end, and peak resident memory, beside a fresh `python -c` lxml parse of the same
file (the anchor), the runs interleaved. Needs javac, java and
/usr/share/java/eclipse-emf-*.jar.

    .venv/bin/python benchmarks/xmi_load.py [--sizes 10000,50000] [--repeat 5] [--validate 208000]
"""

from __future__ import annotations

import argparse
import gc
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from sceml.model.build import ScenarioBuilder, lane
from sceml.model.collector import collector_paused
from sceml.model.copying import Copier, SetterCopier
from sceml.model.documents import Document
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.model.xmiresource import SafeXMIResource

REPO = Path(__file__).resolve().parents[1]
EMF_LOAD = REPO / "benchmarks" / "java" / "EmfLoad.java"
ECORE = REPO / "metamodel" / "scemlmodel.ecore"
JARS = [f"/usr/share/java/eclipse-emf-{name}.jar" for name in ("common", "ecore", "ecore-xmi")]
#: Each kind with the parameters a concrete scenario needs (DriveDistance: distance and speed).
KINDS: list[tuple[str, dict[str, float]]] = [
    ("Accelerate", {"targetSpeed": 12.0, "rate": 2.0}),
    ("KeepVelocity", {"duration": 2.0}),
    ("TimeElapsed", {"duration": 1.0}),
    ("Decelerate", {"targetSpeed": 5.0, "rate": 2.0}),
    ("DriveDistance", {"distance": 30.0, "speed": 8.0}),
]
# Ends as `sceml` ends (sceml.cli.end_now): without the interpreter's collection of the model.
PYTHON_LOAD = (
    "import sys, time; from pathlib import Path; from sceml.model.loading import load; "
    "from sceml.cli import end_now; "
    "t = time.perf_counter(); load(Path(sys.argv[1])); print(time.perf_counter() - t); "
    "end_now(0)"
)
SCEML = Path(sys.executable).with_name("sceml")


def build(nodes: int, actors: int = 50, chain: int = 8) -> ScenarioBuilder:
    """A scenario of about `nodes` action nodes: blocks of parallel chains merged by joins."""
    # A simulator town: this measures loading; validate_scale.py runs the map rules.
    builder = ScenarioBuilder("Large", map="Town03", level="concrete", max_duration=600)
    people = [
        builder.actor("Car", f"car{i}", ego=i == 0, start=lane(1, 1 + i % 3, 5.0 * i), speed=5)
        for i in range(actors)
    ]
    previous, made, block = builder.root, 0, 0
    while made < nodes:
        ends = []
        for branch in range(4):  # a fork into four chains, merged by one join
            actor = people[(block * 4 + branch) % actors]
            kinds = [KINDS[(made + k) % len(KINDS)] for k in range(chain)]
            steps = [builder.add(kind, actor, **values) for kind, values in kinds]
            made += chain
            builder.chain(previous, *steps)
            ends.append(steps[-1])
        previous = builder.join_all(*ends)  # a JoinOne would leave chains running on
        block += 1
    builder.flow(previous, builder.end)
    return builder


def compile_harness(folder: Path) -> str:
    """Compile EmfLoad into `folder`; return the classpath to run it."""
    classpath = os.pathsep.join(JARS)
    subprocess.run(["javac", "-d", str(folder), "-cp", classpath, str(EMF_LOAD)], check=True)
    return os.pathsep.join([str(folder), classpath])


def saved_valid(nodes: int, path: Path) -> Path:
    """Save the scenario of `nodes` nodes to `path`, after checking it has no errors."""
    from sceml.diagnostics import Severity
    from sceml.validation import validate

    scenario = build(nodes).scenario
    errors = [d for d in validate(scenario) if d.severity is Severity.ERROR]
    if errors:
        raise SystemExit(f"the {nodes}-node scenario has {len(errors)} errors, e.g. {errors[0]}")
    return save(scenario, path)


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


def load_with(path: Path, fast: bool) -> Document:
    """Load `path` through the fast reader or through pyecore's decoder."""
    SafeXMIResource.fast_decoding = fast
    try:
        return load(path)
    finally:
        SafeXMIResource.fast_decoding = True


def emf_loads(path: Path, classpath: str, times: int) -> tuple[int, list[float]]:
    """The object count and EMF's own time of each of `times` loads in one JVM (seconds)."""
    result = subprocess.run(
        ["java", "-cp", classpath, "EmfLoad", str(ECORE), str(path), str(times)],
        capture_output=True,
        text=True,
        check=True,
    )
    loads = re.findall(r"LOAD ([\d.]+) (\d+)", result.stdout)
    assert len(loads) == times, result.stdout
    return int(loads[0][1]), [float(ms) / 1000 for ms, _ in loads]


def cold(path: Path, classpath: str, rounds: int) -> dict[str, float]:
    """Medians of fresh processes, interleaved: whole process and the load alone, both ways."""
    commands = {
        "python": [sys.executable, "-c", PYTHON_LOAD, str(path)],
        "emf": ["java", "-cp", classpath, "EmfLoad", str(ECORE), str(path), "1"],
    }
    whole: dict[str, list[float]] = {name: [] for name in commands}
    inside: dict[str, list[float]] = {name: [] for name in commands}
    for number in range(rounds):
        for name in list(commands)[number % 2 :] + list(commands)[: number % 2]:
            started = time.perf_counter()
            done = subprocess.run(commands[name], capture_output=True, text=True, check=True)
            whole[name].append(time.perf_counter() - started)
            text = done.stdout.split()
            inside[name].append(float(text[-1]) if name == "python" else float(text[1]) / 1000)
    figures = {f"{name} whole": statistics.median(v) for name, v in whole.items()}
    figures.update({f"{name} load": statistics.median(v) for name, v in inside.items()})
    return figures


def copy_with(make: type[Copier], document: Document) -> object:
    """A deep copy of the loaded model, references mapped into the copy, with the collector
    paused as flattening pauses it."""
    with collector_paused():
        copier = make()
        duplicate = copier.copy(document.root)
        copier.copy_references()
    return duplicate


def measure(nodes: int, folder: Path, classpath: str, repeat: int) -> None:
    """Print cold and warm load times (Python, EMF), pyecore's decoder and copy times."""
    path = saved_valid(nodes, folder / f"large-{nodes}.xmi")
    figures = cold(path, classpath, repeat)
    emf_objects, emf_runs = emf_loads(path, classpath, repeat + 1)
    emf_warm = min(emf_runs[1:])
    fast_s = best_of(repeat, lambda: load_with(path, fast=True))
    pyecore_s = best_of(repeat, lambda: load_with(path, fast=False))
    document = load_with(path, fast=True)
    count = 1 + sum(1 for _ in document.root.eAllContents())
    setters_s = best_of(repeat, lambda: copy_with(SetterCopier, document))
    direct_s = best_of(repeat, lambda: copy_with(Copier, document))
    size_mb = path.stat().st_size / 1e6
    py_whole, emf_whole = figures["python whole"], figures["emf whole"]
    py_load, emf_load = figures["python load"], figures["emf load"]
    print(f"{nodes:>6} nodes, {count} objects ({emf_objects} in EMF), {size_mb:.1f} MB, valid:")
    print(
        f"    cold, whole process: Python {py_whole:.2f} s, EMF {emf_whole:.2f} s: "
        f"{py_whole / emf_whole:.2f}x (medians of {repeat} fresh processes each, interleaved)"
    )
    print(
        f"    cold, the load alone: Python {py_load:.2f} s, EMF {emf_load:.2f} s: "
        f"{py_load / emf_load:.2f}x (same processes)"
    )
    print(
        f"    warm, best of {repeat} in one process: Python {fast_s:.2f} s, EMF {emf_warm:.2f} s: "
        f"{fast_s / emf_warm:.2f}x; pyecore's decoder {pyecore_s:.2f} s"
    )
    print(
        f"    copy: setters {setters_s:.2f} s, direct {direct_s:.2f} s; "
        f"direct/setters {direct_s / setters_s:.2f}x"
    )


#: The anchor of `--validate`: the interpreter, lxml and a parse of the same file.
LXML_PARSE = "import sys; from lxml import etree; etree.parse(sys.argv[1])"


def run_timed(command: list[str], folder: Path) -> tuple[float, float, float, float, int]:
    """Wall seconds, seconds from the last line of stdout (the summary) to the exit, CPU
    seconds (user + system), peak resident MB and exit status of one fresh process.

    The peak comes from GNU time, which starts the command from its own small process: a child
    this script started directly would report this script's own peak (Linux keeps the
    high-water mark of the memory a vforked child starts in), and this script has just built
    and validated the whole scenario.
    """
    usage_file = folder / "usage.txt"
    timed = ["/usr/bin/time", "-o", str(usage_file), "-f", "%U %S %M", *command]
    started = time.perf_counter()
    process = subprocess.Popen(timed, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    last_line = started
    assert process.stdout is not None
    for _ in process.stdout:  # the summary is the last line `sceml validate` writes
        last_line = time.perf_counter()
    status = process.wait()
    ended = time.perf_counter()
    user, system, peak_kb = usage_file.read_text().split()[-3:]
    after = ended - last_line if last_line > started else 0.0
    return ended - started, after, float(user) + float(system), int(peak_kb) / 1024, status


def validate_fresh(nodes: int, folder: Path, rounds: int) -> None:
    """Print wall time, time after the summary and peak memory of `sceml validate` on `nodes`
    nodes in fresh processes, beside an lxml parse of the same file, the runs interleaved."""
    path = saved_valid(nodes, folder / f"validate-{nodes}.xmi")
    commands = {
        "sceml validate": [str(SCEML), "validate", str(path)],
        "lxml parse": [sys.executable, "-c", LXML_PARSE, str(path)],
    }
    runs: dict[str, list[tuple[float, float, float, float, int]]] = {n: [] for n in commands}
    for number in range(rounds):
        for name in list(commands)[number % 2 :] + list(commands)[: number % 2]:
            runs[name].append(run_timed(commands[name], folder))
    ours, anchor = runs["sceml validate"], runs["lxml parse"]
    wall, after, cpu, peak = (statistics.median(run[i] for run in ours) for i in range(4))
    anchor_wall, _, anchor_cpu, anchor_peak = (
        statistics.median(run[i] for run in anchor) for i in range(4)
    )
    print(
        f"{nodes:>6} nodes, {path.stat().st_size / 1e6:.1f} MB, valid, fresh processes "
        f"(medians of {rounds}, interleaved):\n"
        f"    sceml validate {wall:.2f} s ({cpu:.2f} CPU s), of which after the summary "
        f"{after:.2f} s; peak RSS {peak:.0f} MB; exit {sorted({run[4] for run in ours})}\n"
        f"    lxml parse {anchor_wall:.2f} s ({anchor_cpu:.2f} CPU s), peak RSS "
        f"{anchor_peak:.0f} MB: ours {wall / anchor_wall:.1f}x the time, "
        f"{cpu / anchor_cpu:.1f}x the CPU, {peak / anchor_peak:.2f}x the memory"
    )


def main() -> int:
    """Run the benchmark."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--sizes", default="10000,50000", help="action node counts, comma-separated"
    )
    parser.add_argument("--repeat", type=int, default=5, help="runs per figure (default 5)")
    parser.add_argument(
        "--validate", type=int, default=0, help="also validate a scenario of this many nodes"
    )
    parser.add_argument(
        "--validate-rounds", type=int, default=1, help="fresh processes each for --validate"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        if args.sizes:
            classpath = compile_harness(folder / "classes")
            for size in (int(s) for s in args.sizes.split(",")):
                measure(size, folder, classpath, args.repeat)
        if args.validate:
            validate_fresh(args.validate, folder, args.validate_rounds)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""How validation scales, as a user runs it: `sceml validate` of 1k, 10k and 50k-node scenarios.

    python benchmarks/validate_scale.py [--sizes 1000 10000 50000] [--rounds 5]

The scenarios come from `scale_scenarios.py`: valid concrete scenarios on the real map
(maps/intersection.xodr, so the map rules run) with every node kind but OpaqueAction and actors
spread over the lanes; each is checked to have no errors before anything is timed. Each round
runs, in turn (the order rotates), as fresh processes:

- ours: `sceml validate FILE`, the whole process (start, imports, load, validate, print, exit);
- the anchor: `python -c` parsing the same file with lxml (the interpreter, the XML library and
  the parse any reader of the file pays).

Printed: the medians of the rounds and their ratio; then, in one process, load and validate
seconds of each size (best of the rounds) and how long expanding the module uses alone takes.
Issue 31's goals: under 1 s whole process at 10k nodes, under 5 s at 50k.

    python benchmarks/validate_scale.py --cpu [--before OTHER/src] [--file F.xmi ...]

`--cpu` measures what a loaded machine moves least instead: CPU seconds (user + system) and
peak resident memory of each process, from GNU time (`/usr/bin/time`, which starts the command
from its own small process, so the peak is the command's), in interleaved rounds of `sceml
validate` and the lxml parse, and, with `--before`, of `sceml validate` run from another
tree's sources (`PYTHONPATH`, e.g. `git archive <commit> src | tar -x -C /tmp/before`).
`--file` times existing files (such as `seeded_faults.py`'s) instead of generating them.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from scale_scenarios import write
from side_by_side import interleaved, median

from sceml.model.loading import load
from sceml.modules.expansion import expansion
from sceml.validation import validate

SCEML = str(Path(sys.executable).with_name("sceml"))
PARSE = "import sys; from lxml import etree; etree.parse(sys.argv[1])"


def in_process(path: Path, rounds: int) -> tuple[float, float, float]:
    """Best load, validate and expansion seconds of `rounds` runs in this process."""
    loads, validations, expansions = [], [], []
    for _ in range(rounds):
        started = time.perf_counter()
        document = load(path)
        loaded = time.perf_counter()
        validate(document.root, document=document)
        validated = time.perf_counter()
        expansion(document.root)
        expanded = time.perf_counter()
        loads.append(loaded - started)
        validations.append(validated - loaded)
        expansions.append(expanded - validated)
    return min(loads), min(validations), min(expansions)


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 50000])
    parser.add_argument("--rounds", type=int, default=5, help="rounds (default 5)")
    parser.add_argument("--cpu", action="store_true", help="CPU seconds and peak memory instead")
    parser.add_argument("--before", type=Path, help="with --cpu: another tree's src folder too")
    parser.add_argument("--file", type=Path, action="append", help="with --cpu: existing files")
    arguments = parser.parse_args(argv)
    if arguments.cpu:
        cpu_rounds(arguments)
        return
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    with tempfile.TemporaryDirectory() as temporary:
        files = {size: write(size, Path(temporary)) for size in arguments.sizes}
        print(
            f"{'nodes':>7} {'MB':>5} {'sceml validate s':>17} {'lxml parse s':>13}"
            f" {'ratio':>6}   in-process: {'load s':>6} {'validate s':>10} {'expansion s':>11}"
        )
        for path in files.values():
            commands = {
                "ours": [SCEML, "validate", str(path)],
                "anchor": [sys.executable, "-c", PARSE, str(path)],
            }
            seconds = interleaved(commands, arguments.rounds, env)
            ours, anchor = median(seconds["ours"]), median(seconds["anchor"])
            nodes = len(load(path).root.nodes)
            load_s, validate_s, expansion_s = in_process(path, arguments.rounds)
            megabytes = path.stat().st_size / 1e6
            print(
                f"{nodes:>7} {megabytes:>5.1f} {ours:>17.2f} {anchor:>13.3f} {ours / anchor:>6.1f}"
                f"   {'':11} {load_s:>6.2f} {validate_s:>10.2f} {expansion_s:>11.2f}"
            )


#: The command `sceml validate` runs, as a `python -c` program, so that PYTHONPATH can choose
#: the tree (the console script of this environment would import this tree's sources).
VALIDATE = "import sys; sys.argv[0] = 'sceml'; from sceml.cli import main; main()"


def cpu_rounds(arguments: argparse.Namespace) -> None:
    """Print CPU seconds and peak memory of `sceml validate` beside an lxml parse (and beside
    another tree's `sceml validate` with --before), medians of interleaved rounds."""
    env = {
        k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "PYTHONPATH")
    }
    with tempfile.TemporaryDirectory() as temporary:
        files = arguments.file or [write(size, Path(temporary)) for size in arguments.sizes]
        for path in files:
            commands = {
                "sceml validate": ([sys.executable, "-c", VALIDATE, "validate", path.name], env),
                "lxml parse": ([sys.executable, "-c", PARSE, path.name], env),
            }
            if arguments.before is not None:
                before_env = {**env, "PYTHONPATH": str(arguments.before.resolve())}
                commands["before"] = (
                    [sys.executable, "-c", VALIDATE, "validate", path.name],
                    before_env,
                )
            runs: dict[str, list[tuple[float, float]]] = {name: [] for name in commands}
            names = list(commands)
            for number in range(arguments.rounds):
                shift = number % len(names)
                for name in names[shift:] + names[:shift]:
                    command, command_env = commands[name]
                    runs[name].append(_cpu_and_peak(command, command_env, path.parent))
            print(
                f"{path.name} ({path.stat().st_size / 1e6:.1f} MB), medians of {arguments.rounds} "
                f"interleaved rounds, load average now {os.getloadavg()[0]:.1f}:"
            )
            anchor_cpu, anchor_peak = (
                statistics.median(r[i] for r in runs["lxml parse"]) for i in (0, 1)
            )
            for name, measured in runs.items():
                cpu, peak = (statistics.median(r[i] for r in measured) for i in (0, 1))
                each = ", ".join(f"{r[0]:.2f}" for r in measured)
                print(
                    f"    {name:<15} {cpu:6.2f} CPU s ({each}), peak {peak:7.1f} MB: "
                    f"{cpu / anchor_cpu:5.1f}x the parse's CPU, {peak / anchor_peak:4.2f}x its memory"
                )


def _cpu_and_peak(command: list[str], env: dict[str, str], folder: Path) -> tuple[float, float]:
    """User + system CPU seconds and peak resident MB of one fresh process, from GNU time."""
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as usage:
        timed = ["/usr/bin/time", "-o", usage.name, "-f", "%U %S %M", *command]
        done = subprocess.run(timed, cwd=folder, env=env, capture_output=True)
        if done.returncode not in (0, 1):  # 1: the file has errors, which is still a run
            raise SystemExit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr!r}")
        user, system, peak_kb = usage.read().split()[-3:]
    return float(user) + float(system), int(peak_kb) / 1024


if __name__ == "__main__":
    main()

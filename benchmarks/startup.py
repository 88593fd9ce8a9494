"""CPU and wall time of short commands beside the interpreter's own start, in one run.

    python benchmarks/startup.py [--rounds 21] [--only NAME ...] [--before TREE]

Each command runs as a fresh process, as a user or a CI script runs it (`sceml` is the installed
console script), bytecode caches written by one warm-up run. The anchors, measured in the same
rounds and interleaved with the subjects: `python -c pass` (the interpreter alone) and
`python -c "import lxml.etree"` (the interpreter and the XML library any reader of these files
needs). Also measured: the import of click, of pyecore, of the generated classes (with
pyecore) and of numpy alone (with OpenBLAS's default threads, and with the one thread `sceml`
asks for): what `sceml` cannot start without, and what reading a map needs.

Two figures per command, medians of the rounds (process_cpu.py): CPU seconds (user + system,
as GNU time reports them: the process's own work, which a busy machine does not stretch much)
and wall seconds (what a user waits, which on a shared machine is mostly waiting for a core).
Each is printed with its ratio to `python -c pass` of the same rounds. Issue 31's goals:
`sceml validate` of UIS1 and `sceml --help` within 4x the bare interpreter; `sceml simulate`
of UIS1 and UIS2 (run, preview page written) under 0.35 s. The ratio to the lxml anchor (the
issue's anchor column) is printed beside the ratio to `python -c pass`.

`--before TREE`: each `sceml` command also runs from another source tree, as "NAME, before",
interleaved with the rest: TREE holds that tree's `src` and `generated` (`git archive <commit>
src generated | tar -x -C TREE`), put first on PYTHONPATH. Both trees' commands then run
through `python -c` and `sceml.cli.main` (the console script's entry point), so that the two
start the same way.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from process_cpu import interleaved, load_average, median_cpu, median_wall

REPO = Path(__file__).resolve().parents[1]
UIS1 = REPO / "examples" / "uis1-concrete.xmi"
UIS2 = REPO / "examples" / "uis2-concrete.xmi"
PAGE = Path(tempfile.gettempdir()) / f"sceml-startup-{os.getpid()}-preview.html"
PYTHON = sys.executable
SCEML = str(Path(sys.executable).with_name("sceml"))
MAIN = "import sys; sys.argv[0] = 'sceml'; from sceml.cli import main; main()"
ANCHORS = {
    "python -c pass": [PYTHON, "-c", "pass"],
    'python -c "import lxml.etree"': [PYTHON, "-c", "import lxml.etree"],
}
SUBJECTS = {
    'python -c "import click"': [PYTHON, "-c", "import click"],
    'python -c "import pyecore.ecore"': [PYTHON, "-c", "import pyecore.ecore"],
    'python -c "import scemlmodel"': [PYTHON, "-c", "import scemlmodel"],
    'python -c "import numpy"': [PYTHON, "-c", "import numpy"],
    'python -c "import numpy", 1 BLAS thread': [PYTHON, "-c", "import numpy"],
    "sceml --help": [SCEML, "--help"],
    "sceml info UIS1": [SCEML, "info", str(UIS1)],
    "sceml validate UIS1": [SCEML, "validate", str(UIS1)],
    "sceml validate UIS2": [SCEML, "validate", str(UIS2)],
    "sceml simulate UIS1": [SCEML, "simulate", str(UIS1), "-o", str(PAGE)],
    "sceml simulate UIS2": [SCEML, "simulate", str(UIS2), "-o", str(PAGE)],
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=21, help="rounds (default 21)")
    parser.add_argument(
        "--only", action="append", default=[], metavar="NAME", help="subjects whose name has NAME"
    )
    parser.add_argument(
        "--before",
        type=Path,
        default=None,
        metavar="TREE",
        help="also run each sceml command from TREE/src and TREE/generated",
    )
    options = parser.parse_args()
    subjects = {
        name: command
        for name, command in SUBJECTS.items()
        if not options.only or any(part in name for part in options.only)
    }
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    # What `sceml` asks of OpenBLAS (sceml.cli.blas_threads), for numpy's import alone.
    envs = {'python -c "import numpy", 1 BLAS thread': {**env, "OPENBLAS_NUM_THREADS": "1"}}
    if options.before is not None:
        subjects, envs = _with_before(subjects, envs, env, options.before.resolve())
    load = load_average()
    try:
        runs = interleaved({**ANCHORS, **subjects}, options.rounds, env, envs)
    finally:
        PAGE.unlink(missing_ok=True)
    bare_cpu, bare_wall = median_cpu(runs["python -c pass"]), median_wall(runs["python -c pass"])
    lxml_cpu = median_cpu(runs['python -c "import lxml.etree"'])
    print(f"{options.rounds} rounds, load average {load} at the start, {load_average()} at the end")
    print(
        f"{'command':38s} {'CPU ms':>7s} {'x python':>9s} {'x lxml':>7s}"
        f" {'wall ms':>8s} {'x python':>9s}"
    )
    for name, measured in runs.items():
        cpu, wall = median_cpu(measured), median_wall(measured)
        print(
            f"{name:38s} {cpu * 1000:7.0f} {cpu / bare_cpu:9.1f} {cpu / lxml_cpu:7.1f}"
            f" {wall * 1000:8.0f} {wall / bare_wall:9.1f}"
        )


def _with_before(
    subjects: dict[str, list[str]],
    envs: dict[str, dict[str, str]],
    env: dict[str, str],
    tree: Path,
) -> tuple[dict[str, list[str]], dict[str, dict[str, str]]]:
    """Each sceml subject twice, this checkout's and TREE's, both through `python -c`."""
    before_env = {
        **env,
        "PYTHONPATH": os.pathsep.join([str(tree / "src"), str(tree / "generated")]),
    }
    paired: dict[str, list[str]] = {}
    for name, command in subjects.items():
        if command[0] != SCEML:
            paired[name] = command
            continue
        through_main = [PYTHON, "-c", MAIN, *command[1:]]
        paired[name] = through_main
        paired[f"{name}, before"] = through_main
        envs = {**envs, f"{name}, before": before_env}
    return paired, envs


if __name__ == "__main__":
    main()

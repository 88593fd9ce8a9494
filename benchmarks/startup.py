"""CPU and wall time of short commands beside the interpreter's own start, in one run.

    python benchmarks/startup.py [--rounds 21] [--only NAME ...]

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
of UIS1 and UIS2 (run, preview page written) under 0.35 s.
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
    options = parser.parse_args()
    subjects = {
        name: command
        for name, command in SUBJECTS.items()
        if not options.only or any(part in name for part in options.only)
    }
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    # What `sceml` asks of OpenBLAS (sceml.cli.blas_threads), for numpy's import alone.
    one_thread = {'python -c "import numpy", 1 BLAS thread': {**env, "OPENBLAS_NUM_THREADS": "1"}}
    load = load_average()
    try:
        runs = interleaved({**ANCHORS, **subjects}, options.rounds, env, one_thread)
    finally:
        PAGE.unlink(missing_ok=True)
    bare_cpu, bare_wall = median_cpu(runs["python -c pass"]), median_wall(runs["python -c pass"])
    print(f"{options.rounds} rounds, load average {load} at the start, {load_average()} at the end")
    print(f"{'command':34s} {'CPU ms':>7s} {'x python':>9s} {'wall ms':>8s} {'x python':>9s}")
    for name, measured in runs.items():
        cpu, wall = median_cpu(measured), median_wall(measured)
        print(
            f"{name:34s} {cpu * 1000:7.0f} {cpu / bare_cpu:9.1f} "
            f"{wall * 1000:8.0f} {wall / bare_wall:9.1f}"
        )


if __name__ == "__main__":
    main()

"""Whole-process time of short commands beside the interpreter's own start, in one run.

    python benchmarks/startup.py [--rounds 21]

Each command runs as a fresh process, as a user or a CI script runs it (`sceml` is the installed
console script), bytecode caches written by one warm-up run. The anchors, measured in the same
rounds and interleaved with the subjects: `python -c pass` (the interpreter alone) and
`python -c "import lxml.etree"` (the interpreter and the XML library any reader of these files
needs). Also measured: the import of click, of pyecore, of the generated classes (with
pyecore) and of numpy alone: what `sceml` cannot start without, and what reading a map needs. Prints medians and each one's ratio to both anchors. Issue 31's goals: `sceml validate`
of UIS1 and `sceml --help` within 4x the bare interpreter; `sceml simulate` of UIS1 and UIS2
(run, preview page written) under 0.35 s.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from side_by_side import interleaved, median

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
    "sceml --help": [SCEML, "--help"],
    "sceml info UIS1": [SCEML, "info", str(UIS1)],
    "sceml validate UIS1": [SCEML, "validate", str(UIS1)],
    "sceml simulate UIS1": [SCEML, "simulate", str(UIS1), "-o", str(PAGE)],
    "sceml simulate UIS2": [SCEML, "simulate", str(UIS2), "-o", str(PAGE)],
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=21, help="rounds (default 21)")
    rounds = parser.parse_args().rounds
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    try:
        seconds = interleaved({**ANCHORS, **SUBJECTS}, rounds, env)
    finally:
        PAGE.unlink(missing_ok=True)
    bare = median(seconds["python -c pass"])
    lxml = median(seconds['python -c "import lxml.etree"'])
    print(f"{'command':34s} {'median ms':>9s} {'x python':>9s} {'x lxml':>7s}  ({rounds} rounds)")
    for name, values in seconds.items():
        figure = median(values)
        print(f"{name:34s} {figure * 1000:9.0f} {figure / bare:9.1f} {figure / lxml:7.1f}")


if __name__ == "__main__":
    main()

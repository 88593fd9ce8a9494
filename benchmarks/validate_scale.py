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
"""

from __future__ import annotations

import argparse
import os
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
    arguments = parser.parse_args(argv)
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


if __name__ == "__main__":
    main()

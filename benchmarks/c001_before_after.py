"""C001's conflicts on a scenario's expanded graph: another tree's `simultaneity.py` against
this checkout's, in one process, on the same graph, in turns.

    git archive <commit> src | tar -x -C /tmp/before
    python benchmarks/c001_before_after.py /tmp/before/src FILE.xmi [--rounds 9]

FILE is loaded and validated once (the caches filled), its module uses expanded once
(`Context.flat`); then each round times `conflicts(nodes, flows)` of the other tree and of this
one, and a whole validation of FILE as the anchor. Both must find the same conflicts (checked
first). Printed: medians of `time.process_time()` (CPU seconds), after / before, each against
the anchor, and the load average. The collector is off, as `sceml validate` has it. Only the
module's functions are taken from the other tree (the text before its rule's `@constraint`),
run against this checkout's model and helpers.
"""

from __future__ import annotations

import argparse
import gc
import os
import statistics
import time
import types
from collections.abc import Callable
from pathlib import Path

from sceml.model.loading import load
from sceml.validation import simultaneity, validate
from sceml.validation.context import Context
from sceml.validation.limits import Limits


def other_tree(src: Path) -> types.ModuleType:
    """The functions of `src`'s sceml/validation/simultaneity.py, without registering its rule."""
    path = src / "sceml" / "validation" / "simultaneity.py"
    text = path.read_text(encoding="utf-8")
    module = types.ModuleType("simultaneity_before")
    module.__package__ = "sceml.validation"  # its relative imports read this checkout's modules
    exec(compile(text[: text.index("@constraint(")], str(path), "exec"), module.__dict__)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("before", type=Path, help="the other tree's src folder")
    parser.add_argument("file", type=Path, help="a scenario with module uses")
    parser.add_argument("--rounds", type=int, default=9, help="rounds (default 9)")
    arguments = parser.parse_args()
    before = other_tree(arguments.before)
    gc.disable()
    document = load(arguments.file)
    scenario = document.root
    validate(scenario, document=document)
    flat = Context(scenario, document, Limits()).flat()
    assert flat is not None, f"{arguments.file} has no module uses to expand"
    nodes, flows = flat.nodes, flat.flows()
    assert before.conflicts(nodes, flows) == simultaneity.conflicts(nodes, flows)
    subjects: dict[str, Callable[[], object]] = {
        "before": lambda: before.conflicts(nodes, flows),
        "after": lambda: simultaneity.conflicts(nodes, flows),
        "validation (anchor)": lambda: validate(scenario, document=document),
    }
    times: dict[str, list[float]] = {name: [] for name in subjects}
    for _ in range(arguments.rounds):
        for name, work in subjects.items():
            start = time.process_time()
            work()
            times[name].append(time.process_time() - start)
    median = {name: statistics.median(values) for name, values in times.items()}
    anchor = median["validation (anchor)"]
    print(
        f"{arguments.file.name}: C001 conflicts on the expanded graph ({len(nodes)} nodes), "
        f"medians of {arguments.rounds} rounds, load average {os.getloadavg()[0]:.1f}"
    )
    for name in ("before", "after"):
        print(
            f"    {name:7s} {median[name]:.4f} CPU s  {100 * median[name] / anchor:4.1f} % of validation"
        )
    print(
        f"    after / before {median['after'] / median['before']:.2f}; validation (anchor) {anchor:.3f} CPU s"
    )


if __name__ == "__main__":
    main()

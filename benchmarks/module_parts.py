"""What validating a scenario's module uses costs, part by part, beside the whole validation.

    python benchmarks/module_parts.py FILE.xmi [--rounds 5]

In one process, FILE loaded once and validated once first (the map read, the caches filled),
then for each round, in turn: a whole validation (`sceml.validation.validate`, the anchor), the
expansion's steps on their own (the builder wiring every flow of the scenario, the bound copies
of every use, the result, the self-containment walk, letting the copies go), the
through-modules pass with runs shared per binding and with every rule run on every use
(`engine.through_modules(share=False)`, the copy path), and C001's conflicts on the expanded
graph. Printed: medians of `time.process_time()` (CPU seconds), each with its share of the
whole validation, and the load average. The collector is off, as `sceml validate` has it.

Use files of `scale_scenarios.py` or `seeded_faults.py`: they have a use of the library's
CrossingManeuver per 21 nodes.
"""

from __future__ import annotations

import argparse
import gc
import os
import statistics
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import TypeVar

import scemlmodel as scm
from sceml.model.collector import collector_paused
from sceml.model.loading import load
from sceml.modules import expansion as expanding
from sceml.validation import engine, validate
from sceml.validation.context import Context
from sceml.validation.limits import Limits
from sceml.validation.simultaneity import conflicts

T = TypeVar("T")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("file", type=Path, help="a scenario with module uses")
    parser.add_argument("--rounds", type=int, default=5, help="rounds (default 5)")
    arguments = parser.parse_args()
    gc.disable()  # as `sceml validate` runs: the collector off
    document = load(arguments.file)
    scenario = document.root
    uses = [node for node in scenario.nodes if isinstance(node, scm.ModuleUse)]
    times: dict[str, list[float]] = {}

    def timed(name: str, work: Callable[[], T]) -> T:
        start = time.process_time()
        result = work()
        times.setdefault(name, []).append(time.process_time() - start)
        return result

    def inline_all(builder: expanding._Builder) -> None:
        for use in uses:
            builder.inline(use, (), ())

    def through(context: Context, share: bool) -> list[object]:
        return list(engine.through_modules(context, document, share=share))

    def simultaneity(flat: expanding.Expansion) -> object:
        return conflicts(flat.nodes, flat.flows())

    validate(scenario, document=document)
    for _ in range(arguments.rounds):
        timed("validation (anchor)", partial(validate, scenario, document=document))
        with collector_paused():
            builder = timed(
                "expansion: builder, wiring every flow", partial(expanding._Builder, scenario)
            )
            timed("expansion: bound copies of the uses", partial(inline_all, builder))
            result = timed("expansion: result", builder.result)
            timed(
                "expansion: self-containment walk",
                partial(expanding._check_self_contained, result),
            )
            timed("expansion: letting the copies go", result.release)
        for share in (True, False):
            context = Context(scenario, document, Limits())
            flat = context.flat()
            assert flat is not None, f"{arguments.file} has no module uses to expand"
            label = "shared per binding" if share else "every rule on every use"
            timed(f"through-modules pass, {label}", partial(through, context, share))
            if share:
                timed("C001 conflicts, expanded graph", partial(simultaneity, flat))
            context.release()
    anchor = statistics.median(times["validation (anchor)"])
    print(
        f"{arguments.file.name}: {len(uses)} module uses, medians of {arguments.rounds} rounds, "
        f"load average {os.getloadavg()[0]:.1f}"
    )
    for name, values in times.items():
        median = statistics.median(values)
        print(f"    {name:46s} {median:7.3f} CPU s  {100 * median / anchor:5.1f} % of validation")


if __name__ == "__main__":
    main()

"""The per-node rules one at a time, in-process, beside an lxml parse of the same file.

    python benchmarks/node_rules.py FILE [--rounds 5] [--rules P007,P002,...]
    PYTHONPATH=/tmp/before/src python benchmarks/node_rules.py FILE   # another tree's rules

Loads FILE read-only (as `sceml validate` does), then for each rule runs its check on every
object of its metaclasses that one validation pass visits (`engine.objects`), `--rounds` times,
and prints the best CPU time of each; then `engine.each_object` with every rule over the same
objects. The anchor is lxml's parse of FILE, best of the same rounds, in the same process.
Run it from two trees in turns to compare them; the figures of one run are what to compare.
"""

from __future__ import annotations

import argparse
import gc
import time
from pathlib import Path

from lxml import etree

from sceml.model.loading import load
from sceml.validation import engine
from sceml.validation.context import Context
from sceml.validation.limits import Limits
from sceml.validation.registry import REGISTRY

RULES = "P007,P002,S009,S010,S011,S014,A001,A002,A003,A004,A005,L001,L002,L003,L005"


def best_cpu(run: object, rounds: int) -> float:
    """The least CPU seconds `run()` took over `rounds` calls."""
    best = float("inf")
    for _ in range(rounds):
        start = time.process_time()
        run()  # type: ignore[operator]
        best = min(best, time.process_time() - start)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file", type=Path)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--rules", default=RULES, help="codes without SCEML-, comma-separated")
    args = parser.parse_args()
    gc.freeze()
    gc.disable()  # as the console script runs a command's work
    anchor = best_cpu(lambda: etree.parse(str(args.file)), args.rounds)
    document = load(args.file, read_only=True)
    context = Context(document.root, document, Limits())
    objects = list(engine.objects(document.root, context))
    by_code = {rule.code: rule for rule in REGISTRY.rules()}
    total = 0.0
    for code in args.rules.split(","):
        rule = by_code[f"SCEML-{code}"]
        targets = [obj for obj in objects if rule in REGISTRY.rules_for(obj.eClass)]

        def run_all(rule: object = rule, targets: list[object] = targets) -> None:
            for obj in targets:
                list(rule.check(obj, context))  # type: ignore[attr-defined]

        spent = best_cpu(run_all, args.rounds)
        total += spent
        print(f"{code:6s} {len(targets):7d} runs {spent * 1000:8.1f} ms")
    print(f"{'sum':6s} {'':12s} {total * 1000:8.1f} ms")
    loop = best_cpu(lambda: list(engine.each_object(objects, context, document)), args.rounds)
    print(f"each_object, every rule, {len(objects)} objects: {loop * 1000:.1f} ms")
    print(f"anchor: lxml parse of the same file {anchor * 1000:.1f} ms")


if __name__ == "__main__":
    main()

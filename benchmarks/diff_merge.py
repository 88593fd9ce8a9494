"""Benchmark: `sceml diff` and `sceml merge` of two 10k-node scenarios and of UIS2, beside anchors.

Builds a large scenario with the builder of benchmarks/xmi_load.py (about `--nodes` action
nodes: parallel chains merged by joins), saves it as the base, and two edited versions: ours
(parameters of 1% of the nodes changed, some renamed, some moved) and theirs (other nodes'
parameters, nodes added with their flows). Then, in one run, the best of `--repeat`:

- anchors: loading the two files alone (sceml.model.loading.load), and `sceml --version` as a process start;
- diff: load both and compare (what `sceml diff` does before printing), and the comparison alone;
- merge: load the three and merge without validation, and with it (as `sceml merge` does).

The same for UIS2 (examples/uis2-logical.xmi, a coordinate changed on one side, a tolerance on
the other). Goal (issue 29): diff and merge of the 10k files under 1 s each; of UIS2 well under
the process start.

    .venv/bin/python benchmarks/diff_merge.py [--nodes 10000] [--repeat 3]
"""

from __future__ import annotations

import argparse
import gc
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from xmi_load import build

import scemlmodel as scm
from sceml.diff import compare_files, compare_models
from sceml.diff.merge import merge
from sceml.model import params
from sceml.model.loading import load_scenario
from sceml.model.saving import save

REPO = Path(__file__).resolve().parents[1]
SCEML = Path(sys.executable).with_name("sceml")


def best_of(repeat: int, run: Callable[[], object]) -> float:
    """The best of `repeat` timed runs, after one untimed run (caches, imports) and a collection."""
    run()
    gc.collect()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def scenario(path: Path) -> scm.Scenario:
    root = load_scenario(path).root
    assert isinstance(root, scm.Scenario)
    return root


def edit_copy(base: Path, name: str, edit: Callable[[scm.Scenario], None]) -> Path:
    model = scenario(base)
    edit(model)
    return save(model, base.with_name(name))


def actions(model: scm.Scenario) -> list[scm.ActionNode]:
    return [n for n in model.nodes if isinstance(n, scm.ActionNode)]


def ours_edit(model: scm.Scenario) -> None:
    nodes = actions(model)
    step = max(len(nodes) // 100, 1)
    for index, node in enumerate(nodes[::step]):
        if isinstance(node, scm.Accelerate | scm.Decelerate):
            node.targetSpeed = params.value(7.0 + index % 5)
        elif index % 3 == 0:
            node.name = f"{node.name}_renamed"
        else:
            node.diagramPosition = scm.DiagramPosition(x=float(index), y=10.0)


def theirs_edit(model: scm.Scenario) -> None:
    nodes = actions(model)
    step = max(len(nodes) // 100, 1)
    for node in nodes[step // 2 :: step]:
        if isinstance(node, scm.KeepVelocity):
            node.duration = params.value(9.0)
    # Ten new conditions, each after a node of the first block.
    for index, node in enumerate(nodes[:10]):
        added = scm.TimeElapsed(name=f"Wait_{index}", duration=params.value(1.0))
        added.referenceActor = node.referenceActor
        model.nodes.append(added)
        flow = next(f for f in model.flows if f.source is node)
        model.flows.append(scm.Flow(source=added, target=flow.target))
        flow.target = added


def compare_loaded(old: Path, new: Path, repeat: int) -> float:
    """The comparison alone, of two models loaded beforehand (and dropped afterwards)."""
    old_model, new_model = scenario(old), scenario(new)
    return best_of(repeat, lambda: compare_models(old_model, new_model))


def measure(label: str, files: tuple[Path, Path, Path], repeat: int) -> None:
    base, ours, theirs = files
    load_two = best_of(repeat, lambda: (scenario(base), scenario(ours)))
    load_three = best_of(repeat, lambda: (scenario(base), scenario(ours), scenario(theirs)))
    diff = best_of(repeat, lambda: compare_files(base, ours))
    compare_only = compare_loaded(base, ours, repeat)
    found = compare_files(base, ours)

    def merged(validate: bool) -> None:
        result = merge(scenario(base), scenario(ours), scenario(theirs), validate=validate)
        assert result.ok, result.conflicts[:3]

    merge_plain = best_of(repeat, lambda: merged(False))
    merge_checked = best_of(repeat, lambda: merged(True))
    print(f"\n{label}: {len(found.changes)} changes base -> ours")
    rows = [
        ("anchor: load 2 files", load_two),
        ("anchor: load 3 files", load_three),
        ("diff (load 2 + compare)", diff),
        ("  compare alone", compare_only),
        ("merge (load 3 + merge)", merge_plain),
        ("merge + validation", merge_checked),
    ]
    for name, seconds in rows:
        print(f"  {name:<26} {seconds:8.3f} s  {seconds / load_two:6.2f}x load 2")


def process_start(repeat: int) -> float:
    return best_of(
        repeat, lambda: subprocess.run([str(SCEML), "--version"], check=True, capture_output=True)
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nodes", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=3)
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        work = Path(folder)
        base = work / "large.xmi"
        builder = build(options.nodes)
        save(builder.scenario, base)
        large = (
            base,
            edit_copy(base, "ours.xmi", ours_edit),
            edit_copy(base, "theirs.xmi", theirs_edit),
        )
        shutil.copytree(REPO / "examples", work / "examples", ignore=shutil.ignore_patterns("*.py"))
        uis2 = work / "examples" / "uis2-logical.xmi"

        def turn(model: scm.Scenario) -> None:
            next(n for n in model.nodes if n.name == "TurnLeft_1").destination.x = params.value(
                -30.0
            )

        def tolerance(model: scm.Scenario) -> None:
            next(n for n in model.nodes if n.name == "TurnLeft_1").tolerance = params.value(5.0)

        small = (uis2, edit_copy(uis2, "ours.xmi", turn), edit_copy(uis2, "theirs.xmi", tolerance))
        start = process_start(options.repeat)
        print(f"anchor: `sceml --version` process start {start:.3f} s (best of {options.repeat})")
        measure(f"{len(builder.scenario.nodes):,} nodes", large, options.repeat)
        measure("UIS2", small, max(options.repeat, 5))
    return 0


if __name__ == "__main__":
    sys.exit(main())

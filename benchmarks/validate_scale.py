"""How validation scales: load and validate synthetic scenarios of 1k, 10k and 50k nodes.

    python benchmarks/validate_scale.py [--sizes 1000 10000 50000]

Each scenario has one actor per ~100 nodes. Every actor runs a long chain of segments: accelerate,
a fork into two conditions joined by a JoinAllFinished, a lane change, a use of a library module
(two nodes inside), and a deceleration. The scenario is concrete and valid, so every rule runs to
the end (module expansion included). Prints seconds per stage, microseconds per node, and how long
expanding the module uses alone takes (validation expands them once: bound copies of the modules'
internals, the scenario itself is not copied); the target (issue 17) is load plus validate of 10k
nodes under 1 s, growing about linearly.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import scemlmodel as scm
from sceml import io
from sceml.build import LibraryBuilder, ScenarioBuilder, lane
from sceml.diagnostics import Severity
from sceml.modules.expansion import expansion
from sceml.validation import validate

NODES_PER_ACTOR = 100
SEGMENT = 7  # scenario nodes per segment (see the module docstring)


def build_library() -> scm.Library:
    """One module: the bound road user waits a moment, then keeps its speed."""
    library = LibraryBuilder("Benchmark library")
    module = library.module("Pause")
    driver = module.role("driver", "FourWheeler")
    wait = module.parameter("wait", "s", 1.0)
    module.chain(
        module.in_port,
        module.add("TimeElapsed", driver, duration=wait),
        module.add("KeepVelocity", driver, duration=2.0),
        module.out_port,
    )
    return library.library


def build_scenario(nodes: int, pause: scm.ModuleDefinition) -> scm.Scenario:
    """A valid concrete scenario of about `nodes` nodes (root, end and joins included)."""
    # A simulator town: the map rules leave it alone (SCEML-R002, an info), as before they existed.
    b = ScenarioBuilder("Scale", map="Town03", level="concrete")
    actors = max(1, nodes // NODES_PER_ACTOR)
    segments = max(1, (nodes - 2) // (actors * SEGMENT))
    for index in range(actors):
        actor = b.actor(
            "Car", f"car{index}", ego=index == 0, start=lane(1, -1, 10.0 * index), speed=5.0
        )
        previous: scm.GraphElement = b.root
        for _ in range(segments):
            speed_up = b.add("Accelerate", actor, targetSpeed=12.0)
            waited = b.add("TimeElapsed", actor, duration=1.0)
            fast = b.add("SpeedCondition", actor, speed=11.0)
            change = b.add("LaneChange", actor, direction="left")
            use = b.use(pause, {"driver": actor}, {"wait": 2.0})
            slow_down = b.add("Decelerate", actor, targetSpeed=5.0)
            b.chain(previous, speed_up)
            b.flow(speed_up, waited)
            b.flow(speed_up, fast)
            b.chain(b.join_all(waited, fast), change, use, slow_down)
            previous = slow_down
        b.flow(previous, b.end)
    return b.scenario


def measure(nodes: int, folder: Path) -> tuple[int, float, float, float]:
    """Node count, load, validate and expansion seconds for one size."""
    library_file = folder / "library.xmi"
    if not library_file.exists():
        io.save(build_library(), library_file)
    pause = io.load_library(library_file).root.modules[0]
    path = io.save(build_scenario(nodes, pause), folder / f"scale-{nodes}.xmi")
    started = time.perf_counter()
    document = io.load(path)
    loaded = time.perf_counter()
    found = validate(document.root, document=document)
    validated = time.perf_counter()
    expansion(document.root)
    expanded = time.perf_counter()
    errors = [str(d) for d in found if d.severity is Severity.ERROR]
    if errors:
        raise SystemExit("benchmark scenario is invalid:\n" + "\n".join(errors[:5]))
    counts = len(document.root.nodes), loaded - started, validated - loaded
    return (*counts, expanded - validated)


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10000, 50000])
    arguments = parser.parse_args(argv)
    print(
        f"{'nodes':>7} {'load s':>8} {'validate s':>11} {'validate us/node':>17}"
        f" {'of which expansion s':>21}"
    )
    with tempfile.TemporaryDirectory() as temporary:
        for size in arguments.sizes:
            count, load_s, validate_s, expansion_s = measure(size, Path(temporary))
            per_node = validate_s / count * 1e6
            print(
                f"{count:>7} {load_s:>8.2f} {validate_s:>11.2f} {per_node:>17.1f}"
                f" {expansion_s:>21.2f}"
            )


if __name__ == "__main__":
    main()

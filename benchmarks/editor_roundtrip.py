"""How long one editor round trip takes: apply an op, validate, build the view, encode JSON.

    python benchmarks/editor_roundtrip.py [--runs 30]

Measured on UIS2 (examples/uis2-concrete.xmi) and on a synthetic 500-node scenario built like
benchmarks/validate_scale.py's. Prints the median milliseconds per round trip; the targets are
under 100 ms for UIS2 and under 300 ms for 500 nodes.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path

from sceml import io
from sceml.editor import EditorSession

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from validate_scale import build_library, build_scenario  # noqa: E402

TARGETS = {"UIS2": 100.0, "500 nodes": 300.0}


def round_trip_ms(session: EditorSession, runs: int) -> float:
    """Median milliseconds of a move op's full round trip, alternating two positions."""
    view = session.view()
    node = next(n["id"] for n in view["nodes"] if n["kind"] not in ("RootNode", "EndNode"))
    times = []
    for run in range(runs):
        op = {"op": "move", "positions": {node: {"x": float(run % 2), "y": 0.0}}}
        started = time.perf_counter()
        json.dumps(session.apply([op]))
        times.append((time.perf_counter() - started) * 1000)
    return statistics.median(times)


def synthetic(folder: Path, nodes: int) -> Path:
    """A saved scenario of about `nodes` nodes using a library module (see validate_scale)."""
    library_file = folder / "library.xmi"
    io.save(build_library(), library_file)
    pause = io.load_library(library_file).root.modules[0]
    return io.save(build_scenario(nodes, pause), folder / f"scale-{nodes}.xmi")


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=30)
    arguments = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        shutil.copytree(HERE.parent / "examples", folder / "examples")
        cases = {
            "UIS2": folder / "examples" / "uis2-concrete.xmi",
            "500 nodes": synthetic(folder, 500),
        }
        print(f"{'model':>10} {'nodes':>6} {'median ms':>10} {'target ms':>10}")
        for label, path in cases.items():
            session = EditorSession()
            count = len(session.open(path)["nodes"])
            median = round_trip_ms(session, arguments.runs)
            print(f"{label:>10} {count:>6} {median:>10.1f} {TARGETS[label]:>10.0f}")


if __name__ == "__main__":
    main()

"""How long one editor round trip takes: apply an op, validate, build the view, encode JSON.

    python benchmarks/editor_roundtrip.py [--runs 30]

Measured on UIS2 (examples/uis2-concrete.xmi) and on the valid 500-node scenario of
benchmarks/scale_scenarios.py (the one editor_browser.py opens), for a move, a parameter edit and a drop (a node added from the palette, no flows). Prints the median
milliseconds per round trip as the editor runs it (incremental validation) and, as the yardstick,
with a full validation every time; the targets are under 100 ms for UIS2 and under 300 ms for
500 nodes.

Then validation alone after one edit, full (`validate`) and incremental (what the editor runs,
sceml.validation.incremental) side by side on the same model after the same edit, in alternating
order: a parameter of one node (the common edit), a move (layout only), a node renamed
(names feed the graph-wide rules and the module expansion, so those run again), and a drop (the
expansion kept and patched, the graph-wide rules run on the scenario only: sceml.validation.kept). Prints the
medians, their ratio, and how many rule checks the incremental run ran and reused.
"""

from __future__ import annotations

import argparse
import json
import shutil
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

from sceml.editor import EditorSession
from sceml.validation import validate
from sceml.validation.incremental import IncrementalValidator

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from scale_scenarios import write  # noqa: E402

TARGETS = {"UIS2": 100.0, "500 nodes": 300.0}


class Target(NamedTuple):
    """What an edit works on: the first Accelerate node (by id) and its actor (by name)."""

    node: str
    actor: str


#: An edit: the ops of run number `run` on a target, alternating between two states (a drop
#: adds one more node each run).
Edit = Callable[[Target, int], list[dict[str, Any]]]
EDITS: dict[str, Edit] = {
    # As the palette drops it: a Stop of the actor in view, without flows.
    "drop": lambda target, run: [{"op": "add_node", "kind": "Stop", "actor": target.actor}],
    "parameter": lambda target, run: [
        {
            "op": "set_parameter",
            "node": target.node,
            "field": "targetSpeed",
            "value": {"type": "value", "value": 10.0 + run % 2},
        }
    ],
    "move": lambda target, run: [
        {"op": "move", "positions": {target.node: {"x": float(run % 2), "y": 0.0}}}
    ],
    "rename": lambda target, run: [
        {"op": "set", "node": target.node, "field": "name", "value": f"Renamed_{run % 2}"}
    ],
}


def first_accelerate(session: EditorSession) -> Target:
    """The first Accelerate node of the edited graph, and its actor."""
    node = next(n for n in session.view()["nodes"] if n["kind"] == "Accelerate")
    actor = next(f["value"] for f in node["fields"] if f["name"] == "referenceActor")
    return Target(node["id"], str(actor))


def round_trip_ms(session: EditorSession, edit: Edit, runs: int) -> tuple[float, float]:
    """Median milliseconds of an edit's whole round trip, alternating two states: as the editor
    runs it, and with the validator made to start over each time (a full validation)."""
    node = first_accelerate(session)
    validator = session.validator
    assert validator is not None
    incremental, full = [], []
    for run in range(2 * runs):
        if run % 2:
            validator.forget()
        started = time.perf_counter()
        json.dumps(session.apply(edit(node, run // 2)))
        (full if run % 2 else incremental).append((time.perf_counter() - started) * 1000)
    return statistics.median(incremental), statistics.median(full)


def validation_ms(session: EditorSession, edit: Edit, runs: int) -> tuple[float, float, int, int]:
    """Median ms of a full and of an incremental validation after the same edit; and the rule
    checks the incremental run ran and reused (the last run's)."""
    document = session.document
    assert document is not None
    validator = IncrementalValidator(document.root, document=document)
    validator.validate()
    node = first_accelerate(session)
    full, incremental = [], []
    for run in range(runs):
        session.apply(edit(node, run))  # the session validates too; that is not timed here
        validator.note(session.stack.done[-1].recorder.changes())
        # Alternate which goes first, so neither always runs on a warmer cache.
        if run % 2:
            expected, full_ms = timed(lambda: validate(document.root, document=document))
            found, incremental_ms = timed(validator.validate)
        else:
            found, incremental_ms = timed(validator.validate)
            expected, full_ms = timed(lambda: validate(document.root, document=document))
        if found != expected:
            raise SystemExit("the incremental run differs from the full run")
        full.append(full_ms)
        incremental.append(incremental_ms)
    stats = validator.stats
    return (
        statistics.median(full),
        statistics.median(incremental),
        stats.checks_run,
        (stats.checks_reused),
    )


def timed(run: Callable[[], object]) -> tuple[object, float]:
    started = time.perf_counter()
    result = run()
    return result, (time.perf_counter() - started) * 1000


def main(argv: list[str] | None = None) -> None:
    """Command-line entry point."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=30)
    arguments = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        shutil.copytree(HERE.parent / "examples", folder / "examples")
        shutil.copytree(HERE.parent / "maps", folder / "maps")
        cases = {
            "UIS2": folder / "examples" / "uis2-concrete.xmi",
            "500 nodes": write(500, folder / "scale"),
        }
        print("round trip (median ms): apply, validate, view, JSON")
        print(
            f"{'model':>10} {'nodes':>6} {'edit':>10} {'editor ms':>10}"
            f" {'full val. ms':>13} {'target ms':>10}"
        )
        for label, path in cases.items():
            for name in ("move", "parameter", "drop"):
                session = EditorSession()
                count = len(session.open(path, discard=True)["nodes"])
                editor, full = round_trip_ms(session, EDITS[name], arguments.runs)
                print(
                    f"{label:>10} {count:>6} {name:>10} {editor:>10.1f} {full:>13.1f}"
                    f" {TARGETS[label]:>10.0f}"
                )
        print()
        print("validation after one edit (median ms), full and incremental side by side")
        print(
            f"{'model':>10} {'edit':>10} {'full ms':>8} {'incr. ms':>9} {'ratio':>6}"
            f" {'checks run':>11} {'reused':>7}"
        )
        for label, path in cases.items():
            for name, edit in EDITS.items():
                session = EditorSession()
                session.open(path, discard=True)
                full, incremental, ran, reused = validation_ms(session, edit, arguments.runs)
                print(
                    f"{label:>10} {name:>10} {full:>8.2f} {incremental:>9.2f}"
                    f" {full / incremental:>6.1f} {ran:>11} {reused:>7}"
                )


if __name__ == "__main__":
    main()

"""What the change log costs an edit: 12 edits back to back at 500 nodes through the app.

    python benchmarks/editor_journal.py [--rounds 3] [--nodes 500]

The editor's web application runs in-process (Starlette's TestClient, no network) on the
500-node scenario of benchmarks/scale_scenarios.py. One round posts 12 edits back to back (a
parameter set, alternating between two values, as a user typing into one field) and times each
answer. Rounds alternate between the app as it is (every change logged in `.NAME.journal`
before its answer) and, as the anchor, the same app with the logging switched off (what the
editor did before: only the checkpoint, written when the edits pause). Both keep the checkpoint
thread; its pause (0.5 s) and patience (3 s) are raised here so that no checkpoint lands inside
a round of either kind and the figures compare the logging alone.

Prints the median and the slowest answer of each kind, their difference, the median time of
one log append (`EditorSession.record`) measured inside the app, and of one checkpoint (what
the log spares a burst of edits from waiting for), and how long opening the file and restoring
it with every logged change replayed takes (as after a SIGKILL at the end of the rounds).
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from starlette.testclient import TestClient

from sceml.editor import EditorSession, SessionOptions
from sceml.editor.app import create_app

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from scale_scenarios import write  # noqa: E402

EDITS = 12


def _accelerate(view: dict[str, Any]) -> str:
    return next(n["id"] for n in view["nodes"] if n["kind"] == "Accelerate")


def _round(client: TestClient, node: str, offset: int) -> list[float]:
    times = []
    for index in range(EDITS):
        speed = 10.0 + (index + offset) % 2
        body = {
            "ops": [
                {
                    "op": "set_parameter",
                    "node": node,
                    "field": "targetSpeed",
                    "value": {"type": "value", "value": speed},
                }
            ]
        }
        start = time.perf_counter()
        answer = client.post("/api/ops", json=body)
        times.append((time.perf_counter() - start) * 1000)
        assert answer.status_code == 200, answer.text
    return times


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--nodes", type=int, default=500)
    args = parser.parse_args(argv)
    folder = Path(tempfile.mkdtemp(prefix="sceml-journal-bench-"))
    try:
        path = write(args.nodes, folder / "scale")
        session = EditorSession(SessionOptions())
        session.open(path)
        app = create_app(session)
        api = app.state.api
        api.journal._quiet, api.journal._patience = 600.0, 600.0  # no checkpoint in a round
        client = TestClient(app, base_url="http://127.0.0.1")
        node = _accelerate(client.get("/api/view").json())
        record = session.record
        appends: list[float] = []

        def timed_record(*given: Any) -> bool:
            start = time.perf_counter()
            try:
                return record(*given)
            finally:
                appends.append((time.perf_counter() - start) * 1000)

        results: dict[str, list[float]] = {"with the log": [], "anchor: no log": []}
        _round(client, node, 0)  # warm up caches and the log's header
        for number in range(args.rounds * 2):
            logging = number % 2 == 1  # the anchor first: the first round pays for warming up
            session.record = timed_record if logging else (lambda *given: False)  # type: ignore[method-assign]
            kind = "with the log" if logging else "anchor: no log"
            results[kind] += _round(client, node, number)
        session.record = record  # type: ignore[method-assign]
        logged = session.journal_path.stat().st_size  # before the stop checkpoints and empties it
        # As after a SIGKILL now: a new session restores the file plus every logged change.
        start = time.perf_counter()
        again = EditorSession(SessionOptions())
        again.open(path)
        offer = again.recovery_offer
        assert offer is not None
        report = again.resolve_recovery(True)["replay"]
        restored = (time.perf_counter() - start) * 1000
        assert report["stopped"] is None, report
        api.journal.stop()
        checkpoints = []
        for _ in range(3):
            _round(client, node, 1)  # changes to checkpoint
            start = time.perf_counter()
            with api.lock:
                session.recover()
            checkpoints.append((time.perf_counter() - start) * 1000)
        print(
            f"{EDITS} edits back to back x {args.rounds} rounds each, {args.nodes} nodes, "
            "in-process (ms per answer)"
        )
        for kind, times in results.items():
            print(f"  {kind:16} median {statistics.median(times):7.1f}  max {max(times):7.1f}")
        difference = statistics.median(results["with the log"]) - statistics.median(
            results["anchor: no log"]
        )
        print(f"  difference of the medians: {difference:+.1f} ms per edit")
        print(
            f"  one log append (record), median: {statistics.median(appends):.3f} ms, "
            f"max {max(appends):.3f} ms, {len(appends)} appends"
        )
        print(
            f"  one checkpoint (the whole model as XMI), median of 3: "
            f"{statistics.median(checkpoints):.1f} ms"
        )
        print(f"  open and restore with {report['replayed']} changes replayed: {restored:.0f} ms")
        print(f"  the log after {len(appends) + EDITS} entries: {logged} bytes")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()

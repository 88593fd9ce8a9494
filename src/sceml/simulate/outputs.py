"""A run as files: the preview page, the trajectories as CSV and a JSON summary (timeline,
metrics, end)."""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path
from typing import Any

import scemlmodel as scm

from ..files.outputset import output_set
from ..files.writing import write_atomically
from .run import Run

CSV_COLUMNS = ("time", "actor", "x", "y", "heading", "speed")


def write_run(
    run: Run,
    scenario: scm.Scenario,
    scenario_file: Path,
    page: Path,
    csv_path: Path | None = None,
    json_path: Path | None = None,
) -> list[Path]:
    """Write the run's page (and, if asked, its CSV and JSON): all of them or, when one cannot
    be written, none (a CSV that fails must not leave the page of the run behind). The files
    written, page first."""
    from .page import preview_page  # matplotlib's helpers: loaded only for the page

    with output_set() as outputs:
        write_atomically(outputs.stage(page), preview_page(run, scenario, scenario_file).encode())
        if csv_path is not None:
            write_atomically(outputs.stage(csv_path), trajectories_csv(run).encode("utf-8"))
        if json_path is not None:
            text = json.dumps(summary(run), indent=2) + "\n"
            write_atomically(outputs.stage(json_path), text.encode("utf-8"))
    return [page, *(p for p in (csv_path, json_path) if p is not None)]


def trajectories_csv(run: Run) -> str:
    """One row per sample and actor: time (s), actor, x, y (m), heading (rad), speed (m/s)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(CSV_COLUMNS)
    for k, t in enumerate(run.times):
        for index, actor in enumerate(run.actors):
            x, y, heading, speed = run.states[index, k]
            writer.writerow(
                [f"{t:.3f}", actor.name, f"{x:.3f}", f"{y:.3f}", f"{heading:.4f}", f"{speed:.3f}"]
            )
    return buffer.getvalue()


def summary(run: Run) -> dict[str, Any]:
    """What the run found, as plain JSON data (no infinities: a missing value is null)."""
    return {
        "scenario": run.scenario,
        "preview": "kinematic preview, not a vehicle-dynamics simulation",
        "step": run.step,
        "end": {"reason": run.end_reason, "time": _number(run.end_time)},
        "actors": [
            {"name": a.name, "kind": a.kind, "ego": a.ego, "length": a.length, "width": a.width}
            for a in run.actors
        ],
        "timeline": [
            {
                "node": r.name,
                "kind": r.kind,
                "actor": r.actor,
                "started": _number(r.started),
                "finished": _number(r.finished),
                **({"note": r.note} if r.note else {}),
            }
            for r in run.timeline
        ],
        "metrics": [
            {
                "actors": [m.a, m.b],
                "min_distance": _number(m.min_distance),
                "min_distance_time": _number(m.min_distance_time),
                "min_ttc": _number(m.min_ttc),
                "min_ttc_time": _number(m.min_ttc_time),
                "pet": _number(m.pet),
                "pet_point": list(m.pet_point) if m.pet_point else None,
                "collision": m.collision,
                "collision_time": _number(m.collision_time),
            }
            for m in run.metrics
        ],
        "notes": list(run.notes),
    }


def _number(value: float | None) -> float | None:
    if value is None or not math.isfinite(value):
        return None
    return round(float(value), 4)

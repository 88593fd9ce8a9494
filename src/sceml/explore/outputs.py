"""What `sceml explore` writes: every run as CSV, the most critical concrete scenarios, plots."""

from __future__ import annotations

import csv
import io as text_io
import math
from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np

import scemlmodel as scm

from ..files.writing import write_atomically
from ..levels.apply import apply
from ..levels.xosc import XoscWriter
from ..model.saving import save
from ..simulate import Run
from .objective import NO_CONFLICT
from .search import Evaluation, Exploration

RESULT_COLUMNS = (
    "score",
    "min_distance",
    "min_ttc",
    "pet",
    "collision",
    "collision_time",
    "colliding",
    "end",
    "error",
)


def runs_csv(exploration: Exploration) -> str:
    """One row per run, in the order they were made: index, phase, values, what it measured."""
    buffer = text_io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("index", "phase", *exploration.space.paths, *RESULT_COLUMNS))
    for e in exploration.evaluations:
        writer.writerow((e.index, e.phase, *(f"{v:.6g}" for v in e.values), *_measured(e)))
    return buffer.getvalue()


def _measured(e: Evaluation) -> tuple[str, ...]:
    run = e.run
    if run is None:
        return ("", "", "", "", "", "", "", "", e.error)
    hits = [m for m in run.metrics if m.collision]
    first = min(hits, key=lambda m: m.collision_time or 0.0) if hits else None
    return (
        _number(e.score),
        _number(min((m.min_distance for m in run.metrics), default=None)),
        _number(_least(m.min_ttc for m in run.metrics)),
        _number(_least(m.pet for m in run.metrics)),
        "yes" if first else "no",
        _number(first.collision_time) if first else "",
        f"{first.a}-{first.b}" if first else "",
        run.end_reason,
        "",
    )


def _least(values: Iterable[float | None]) -> float | None:
    finite = [v for v in values if v is not None and math.isfinite(v)]
    return min(finite) if finite else None


def _number(value: float | None) -> str:
    return "" if value is None or not math.isfinite(value) else f"{value:.4g}"


def write_critical(
    exploration: Exploration,
    logical: scm.Scenario,
    logical_file: Path,
    out_dir: Path,
    top: int,
    osc_version: str,
    stage: Callable[[Path], Path] = Path,
) -> list[tuple[Evaluation, list[Path], str | None]]:
    """The `top` most critical runs as concrete .xmi and .xosc files: (run, files, problem).

    Each file is written under the name `stage` gives for it (e.g. `OutputSet.stage`); the
    files returned are the targets.
    """
    writer = XoscWriter(logical_file, osc_version)
    stem = logical_file.stem.removesuffix("-logical")
    written = []
    for rank, evaluation in enumerate(exploration.ranked()[:top], start=1):
        values = dict(zip(exploration.space.paths, evaluation.values, strict=True))
        concrete = apply(logical, values)
        base = out_dir / f"{stem}_critical_{rank:02d}"
        xmi = base.with_suffix(".xmi")
        save(concrete, stage(xmi), origin=logical_file)
        problem = writer.write(concrete, stage(base.with_suffix(".xosc")))
        files = [xmi] if problem else [xmi, base.with_suffix(".xosc")]
        written.append((evaluation, files, problem))
    return written


def plot_space(exploration: Exploration, path: Path) -> None:
    """Every pair of varied parameters as a scatter plot coloured by the score (PNG);
    collisions ringed in red. One parameter: the score against it."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    done = [e for e in exploration.evaluations if e.run is not None]
    values = np.array([e.values for e in done]) if done else np.empty((0, 0))
    scores = np.array([min(e.score, NO_CONFLICT) for e in done])
    crashed = np.array([_collided(e.run) for e in done], dtype=bool)
    paths = exploration.space.paths[:6]
    pairs = [(i, j) for i in range(len(paths)) for j in range(i + 1, len(paths))] or [(0, -1)]
    columns = min(3, len(pairs))
    rows = math.ceil(len(pairs) / columns)
    figure = Figure(figsize=(4.2 * columns, 3.6 * rows))
    FigureCanvasAgg(figure)
    finite = scores[scores < NO_CONFLICT] if scores.size else scores
    low, high = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 1.0)
    for n, (i, j) in enumerate(pairs):
        axes = figure.add_subplot(rows, columns, n + 1)
        if not done:
            continue
        y = values[:, j] if j >= 0 else scores
        shown = axes.scatter(values[:, i], y, c=scores, cmap="viridis_r", vmin=low, vmax=high, s=14)
        axes.scatter(
            values[crashed, i],
            y[crashed],
            facecolors="none",
            edgecolors="#d93025",
            s=40,
            linewidths=0.8,
            label="collision",
        )
        axes.set_xlabel(paths[i], fontsize=8)
        axes.set_ylabel(paths[j] if j >= 0 else exploration.metric, fontsize=8)
        axes.tick_params(labelsize=7)
        figure.colorbar(shown, ax=axes).set_label(exploration.metric, fontsize=8)
    figure.suptitle(
        f"{len(done)} runs, metric {exploration.metric} (yellow: more critical; red ring: "
        "collision)",
        fontsize=10,
    )
    figure.tight_layout()
    buffer = text_io.BytesIO()
    figure.savefig(buffer, format="png", dpi=110, metadata={"Software": None})
    write_atomically(path, buffer.getvalue())


def _collided(run: Run | None) -> bool:
    return run is not None and run.collided

"""Benchmark: simulated seconds per wall second of the preview player on UIS2 (issue 16).

Times `sceml.simulate.simulate` on examples/uis2-concrete.xmi (loaded once; the map is read
once per process and its lane centre lines are cached): the whole call, which flattens the
CrossingManeuver use every time, and the player alone on the already flattened scenario.
Both include the metrics of the three pairs of actors. Aim: at least 1000x real time.

    .venv/bin/python benchmarks/simulate_speed.py [--repeat 200] [--step 0.05]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from sceml.model.loading import load_scenario
from sceml.modules import flatten
from sceml.simulate import DEFAULT_STEP, simulate

REPO = Path(__file__).resolve().parents[1]
UIS2 = REPO / "examples" / "uis2-concrete.xmi"


def speed(scenario: object, repeat: int, step: float) -> tuple[float, float]:
    """Simulated seconds of one run, and wall seconds per run (best of three batches)."""
    run = simulate(scenario, UIS2, step=step)  # type: ignore[arg-type]
    best = float("inf")
    for _ in range(3):
        started = time.perf_counter()
        for _ in range(repeat):
            simulate(scenario, UIS2, step=step)  # type: ignore[arg-type]
        best = min(best, (time.perf_counter() - started) / repeat)
    return run.end_time, best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=200)
    parser.add_argument("--step", type=float, default=DEFAULT_STEP)
    options = parser.parse_args()
    scenario = load_scenario(UIS2).root
    for label, subject in (
        ("simulate(), module use flattened per call", scenario),
        ("player on the flattened scenario", flatten(scenario)),
    ):
        simulated, wall = speed(subject, options.repeat, options.step)
        print(
            f"UIS2, step {options.step:g} s, {label}: {simulated:.2f} s simulated in "
            f"{wall * 1000:.2f} ms: {simulated / wall:,.0f} simulated s per wall s"
        )


if __name__ == "__main__":
    main()

"""Benchmark: simulated seconds per wall second of the preview player on UIS2 (issues 16, 31).

Times `sceml.simulate.simulate` on examples/uis2-concrete.xmi (loaded once; the map is read
once per process and its lane centre lines are cached): the whole call, which flattens the
CrossingManeuver use every time, and the player alone on the already flattened scenario.
Both include the metrics of the three pairs of actors. Aim: at least 1000x real time.

With `--rounds R` (issue 31), whole processes too, R rounds taken in turn (side_by_side.py):
`sceml simulate` of UIS2 writing its preview page (aim: under 0.35 s) beside `python -c pass`,
and with `--esmini PATH`, esmini playing UIS2's export headless at the same step, start to
end, as the anchor the issue compares with (esmini is not needed otherwise).

    .venv/bin/python benchmarks/simulate_speed.py [--repeat 200] [--step 0.05]
        [--rounds 11 [--esmini /tmp/esmini/bin/esmini]]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from side_by_side import interleaved, median

from sceml.model.loading import load_scenario
from sceml.modules import flatten
from sceml.simulate import DEFAULT_STEP, simulate

REPO = Path(__file__).resolve().parents[1]
UIS2 = REPO / "examples" / "uis2-concrete.xmi"


def speed(scenario: object, repeat: int, step: float) -> tuple[float, float, float]:
    """Simulated seconds of one run, and wall and CPU seconds per run (best of three batches).

    On a shared machine the wall time includes waiting for a core; the CPU time of this
    process does not, and is what a run costs where it has a core to itself."""
    run = simulate(scenario, UIS2, step=step)  # type: ignore[arg-type]
    best, best_cpu = float("inf"), float("inf")
    for _ in range(3):
        started, cpu = time.perf_counter(), time.process_time()
        for _ in range(repeat):
            simulate(scenario, UIS2, step=step)  # type: ignore[arg-type]
        best = min(best, (time.perf_counter() - started) / repeat)
        best_cpu = min(best_cpu, (time.process_time() - cpu) / repeat)
    return run.end_time, best, best_cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=200)
    parser.add_argument("--step", type=float, default=DEFAULT_STEP)
    parser.add_argument("--rounds", type=int, default=0, help="whole-process rounds (0: none)")
    parser.add_argument("--esmini", type=Path, default=None, help="esmini, as the anchor")
    options = parser.parse_args()
    scenario = load_scenario(UIS2).root
    for label, subject in (
        ("simulate(), module use flattened per call", scenario),
        ("player on the flattened scenario", flatten(scenario)),
    ):
        simulated, wall, cpu = speed(subject, options.repeat, options.step)
        print(
            f"UIS2, step {options.step:g} s, {label}: {simulated:.2f} s simulated in "
            f"{wall * 1000:.2f} ms: {simulated / wall:,.0f} simulated s per wall s; "
            f"{cpu * 1000:.2f} ms CPU: {simulated / cpu:,.0f} per CPU s"
        )
    if options.rounds:
        simulated = speed(scenario, 1, options.step)[0]
        whole_processes(options.rounds, options.step, simulated, options.esmini)


def whole_processes(rounds: int, step: float, simulated: float, esmini: Path | None) -> None:
    """`sceml simulate` as a user runs it, beside the bare interpreter and esmini, in turn."""
    sceml = str(Path(sys.executable).with_name("sceml"))
    with tempfile.TemporaryDirectory() as folder:
        page, xosc = Path(folder) / "uis2-preview.html", Path(folder) / "uis2.xosc"
        commands = {
            "python -c pass": [sys.executable, "-c", "pass"],
            "sceml simulate UIS2 (page written)": [
                sceml,
                "simulate",
                str(UIS2),
                "-o",
                str(page),
                "--step",
                f"{step:g}",
            ],
        }
        if esmini is not None:
            subprocess.run(
                [sceml, "export", str(UIS2), "-o", str(xosc)], check=True, capture_output=True
            )
            commands["esmini UIS2's export, headless"] = [
                str(esmini),
                "--headless",
                "--osc",
                str(xosc),
                "--fixed_timestep",
                f"{step:g}",
                "--disable_log",
                "--disable_stdout",
            ]
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        seconds = interleaved(commands, rounds, env)
    bare = median(seconds["python -c pass"])
    print(f"{'whole process':36s} {'median ms':>9s} {'x python':>9s} {'x real time':>12s}")
    for name, values in seconds.items():
        wall = median(values)
        pace = f"{simulated / wall:12.1f}" if name != "python -c pass" else f"{'':12s}"
        print(f"{name:36s} {wall * 1000:9.0f} {wall / bare:9.1f} {pace}")


if __name__ == "__main__":
    main()

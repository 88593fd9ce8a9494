"""The same commands from two source trees, side by side: what a change did to whole processes.

    git archive <commit> src | tar -x -C /tmp/before
    python benchmarks/before_after.py /tmp/before/src [--rounds 7] [--scale 10000]

"before" runs the commands with PYTHONPATH set to the given `src` folder (it is found before the
editable install), "after" with this checkout; both with this interpreter and environment, the
runs interleaved (see side_by_side.py). Commands: `sceml --help`, `sceml validate` of UIS1 and
of a generated scenario of `--scale` nodes (scale_scenarios.py, on the real map), `sceml
simulate` of UIS2 (its preview page), and `sceml sample` of UIS2 (random, 2,000 files, 2
workers) with its time to the first file.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from scale_scenarios import write
from side_by_side import interleaved, median

REPO = Path(__file__).resolve().parents[1]
MAIN = "import sys; sys.argv[0] = 'sceml'; from sceml.cli import main; main()"


def sample_run(env: dict[str, str], out: Path) -> tuple[float, float]:
    """Whole seconds and seconds to the first file of one `sceml sample` run into `out`."""
    logical = REPO / "examples" / "uis2-logical.xmi"
    command = [sys.executable, "-c", MAIN, "sample", str(logical), "--strategy", "random"]
    command += ["--n", "2000", "--seed", "1", "--format", "xosc", "--workers", "2", "-o", str(out)]
    wall, started = time.time(), time.perf_counter()
    subprocess.run(command, env=env, capture_output=True, check=True)
    elapsed = time.perf_counter() - started
    first = min(f.stat().st_mtime_ns for f in out.glob("*.xosc")) / 1e9 - wall
    return elapsed, first


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("before", type=Path, help="the other tree's src folder")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--scale", type=int, default=10000)
    args = parser.parse_args()
    plain = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE",)}
    envs = {"before": {**plain, "PYTHONPATH": str(args.before.resolve())}, "after": plain}
    with tempfile.TemporaryDirectory() as temporary:
        scale = write(args.scale, Path(temporary))
        cases = {
            "sceml --help": ["--help"],
            "sceml validate UIS1": ["validate", str(REPO / "examples" / "uis1-concrete.xmi")],
            f"sceml validate {args.scale} nodes": ["validate", str(scale)],
            "sceml simulate UIS2": [
                "simulate",
                str(REPO / "examples" / "uis2-concrete.xmi"),
                "-o",
                str(Path(temporary) / "preview.html"),
            ],
        }
        print(f"{'command':32s} {'before s':>9s} {'after s':>8s} {'after/before':>13s}")
        for name, arguments in cases.items():
            command = [sys.executable, "-c", MAIN, *arguments]
            seconds = interleaved({"before": command, "after": command}, args.rounds, envs=envs)
            before, after = median(seconds["before"]), median(seconds["after"])
            print(f"{name:32s} {before:9.3f} {after:8.3f} {after / before:13.2f}")
        runs: dict[str, list[tuple[float, float]]] = {"before": [], "after": []}
        for number in range(max(3, args.rounds // 2)):
            for tree in ("before", "after") if number % 2 == 0 else ("after", "before"):
                out = Path(temporary) / f"{tree}-{number}"
                runs[tree].append(sample_run(envs[tree], out))
                shutil.rmtree(out)
        for label, column in (("sceml sample N=2000, whole", 0), ("  ... to the first file", 1)):
            before = statistics.median(r[column] for r in runs["before"])
            after = statistics.median(r[column] for r in runs["after"])
            print(f"{label:32s} {before:9.3f} {after:8.3f} {after / before:13.2f}")


if __name__ == "__main__":
    main()

"""Play every concrete example and the player-check scenarios in esmini; check and compare.

    python benchmarks/players_agreement.py --esmini /path/to/esmini [--osc-version 1.0 ...]
        [--keep DIR] [SCENARIO.xmi ...]

For each scenario (default: examples/*-concrete.xmi and tests/players/scenarios/*.xmi) and each
OpenSCENARIO version (default 1.0 and 1.3): export it as `sceml export` does, play it with
`esmini --headless --fixed_timestep 0.05`, check the run as `sceml check-run` does, run the
preview (`sceml simulate`) and compare the two (`sceml.players.compare`: node starts within
0.15 s, positions within 0.6 m, the same end). Prints a table; exit 1 when a run breaks the
scenario's meaning or the two disagree. The esmini run's wall time is printed beside the
preview's as the anchor measured in the same run. esmini is not part of SceML: pass your build.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

from sceml.export import build_xosc
from sceml.model.loading import load_scenario
from sceml.players import esmini
from sceml.players.check import check_scenario_run
from sceml.players.compare import compare
from sceml.simulate import simulate

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SCENARIOS = [
    *sorted((ROOT / "examples").glob("*-concrete.xmi")),
    *sorted((ROOT / "tests" / "players" / "scenarios").glob("*.xmi")),
]
STEP = 0.05


def row(path: Path, version: str, binary: str, folder: Path) -> tuple[str, bool]:
    """One line of the table for a scenario at a version, and whether it is clean."""
    scenario = load_scenario(path).root
    xosc = folder / f"{path.stem}-{version}.xosc"
    xosc.write_bytes(build_xosc(scenario, version=version, source_path=path, output_path=xosc).data)
    began = time.perf_counter()
    log, trace = esmini.play(binary, xosc, STEP)
    player_seconds = time.perf_counter() - began
    run = esmini.read(log, trace)
    report = check_scenario_run(path, run, version=version)
    began = time.perf_counter()
    preview = simulate(scenario, path, step=STEP)
    preview_seconds = time.perf_counter() - began
    result = compare(preview, report, run)
    clean = report.ok and result.agrees
    line = (
        f"| {path.stem} | {version} | {len(report.violations())} | "
        f"{result.worst_start:.2f} ({_short(result.worst_start_node)}) | "
        f"{result.worst_position:.2f} ({result.worst_position_actor} at "
        f"{result.worst_position_time:.2f} s) | {report.ending} | "
        f"{preview.end_reason} at {preview.end_time:.2f} s | {'yes' if result.agrees else 'NO'} | "
        f"{player_seconds * 1000:.0f} / {preview_seconds * 1000:.0f} ms |"
    )
    return line, clean


def _short(name: str) -> str:
    return name if len(name) <= 34 else "…" + name[-33:]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("scenarios", nargs="*", type=Path, help="concrete scenarios (.xmi)")
    parser.add_argument("--esmini", help="the esmini binary (default: $ESMINI, else the PATH)")
    parser.add_argument(
        "--osc-version", action="append", dest="versions", choices=("1.0", "1.1", "1.2", "1.3")
    )
    parser.add_argument("--keep", type=Path, help="keep exports, logs and CSVs in this folder")
    arguments = parser.parse_args(argv)
    binary = esmini.find(arguments.esmini)
    if binary is None:
        print("esmini not found: pass --esmini PATH or set $ESMINI", file=sys.stderr)
        return 2
    scenarios = [p.resolve() for p in arguments.scenarios] or DEFAULT_SCENARIOS
    versions = arguments.versions or ["1.0", "1.3"]
    print(
        "| scenario | OSC | check-run violations | worst node start apart (s) | "
        "worst position apart (m) | esmini stopped by | preview ended by | agree | "
        "wall time esmini / preview |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    clean = True
    with tempfile.TemporaryDirectory(prefix="sceml-players-") as temporary:
        folder = (arguments.keep or Path(temporary)).resolve()
        folder.mkdir(parents=True, exist_ok=True)
        for path in scenarios:
            for version in versions:
                line, ok = row(path, version, binary, folder)
                clean &= ok
                print(line, flush=True)
    return 0 if clean else 1


if __name__ == "__main__":
    sys.exit(main())

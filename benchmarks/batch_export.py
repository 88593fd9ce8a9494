"""Batch export benchmark (issues 6 and 17): `sceml sample` against scenariogeneration and the floor.

    .venv/bin/python benchmarks/batch_export.py [--n 5000] [--workers W] [--rounds R] [--keep DIR]
        [--before SRC]

Four figures, all on this machine in one run, each the median of R rounds (default 3) taken in
turn (the order rotates every round), because this machine is shared and its disk is noisy:

1. ours: `sceml sample examples/uis2-logical.xmi --strategy random --n N --format xosc
   --workers W`: N concrete UIS2 scenarios, each flattened, checked (parameter and plausibility
   rules), exported, XSD validated (its sampled values against their XSD types, which under
   XSD 1.0 decides the document's validity: docs/levels.md) and written so that no
   half-written file can be seen. The
   whole command as a subprocess (`sceml.cli.main`, as the `sceml` script runs it), timed from
   outside: Python's start-up and imports, loading and validating the logical scenario, drawing
   the values, starting W worker processes, and writing manifest.csv and manifest.json at the
   end are all inside the time. Only the N .xosc files are counted.
2. scenariogeneration 0.16.7's ScenarioGenerator writing an N-file cartesian sweep of a
   hand-written UIS2-like scenario (3 entities, init, 12 events with conditions, like our UIS2
   export; 27 KB per file against our 26.6 KB), without validation and without a manifest.
   Also the whole process as a subprocess, also counting its N .xosc files. Benchmark-only
   dependency; serial here (see 3).
3. scenariogeneration again, with its `number_of_parallel_writings` = W (it writes the files
   from W processes; on this machine it has been slower than its serial mode).
4. The floor, as issue 17 defines it: what it physically takes to produce the same files, i.e.
   lxml serialise, XSD validate and write each file (plain `open`/`write`/`close`, no rename,
   no check of any kind) in one process per core (W processes), and (issue 31) as a whole
   process like the others: Python's start, importing lxml and the XSD loader, compiling the
   XSD and parsing the documents (those of an untimed run of ours) are inside its time.

Each figure also says how long the run took to its first file and how fast it wrote from the
first file to the last (the files' modification times): the part that start-up does not
explain; and how many CPU seconds the run used, its own and its worker processes' (user +
system, as GNU time counts them): on a machine shared with other jobs the wall times are
mostly waiting for a core, and files per CPU second is the figure that load stretches least
(it does not credit ours for using two cores, only for the work each file costs).

With `--before SRC` (e.g. `/tmp/before/src:/tmp/before/generated`, from `git archive <commit>
src generated`), a fifth run in the same rounds is ours from that tree (PYTHONPATH=SRC), so that
a change is measured against its starting point beside the same anchors. The load average is
printed with every round: this machine is shared.

Targets (issue 17): ours at least 5x scenariogeneration in files/s, and within 2x of the floor;
(issue 31) the first file within 0.3 s.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
LOGICAL = REPO / "examples" / "uis2-logical.xmi"

SCENARIOGENERATION_SCRIPT = textwrap.dedent(
    """
    import sys
    from scenariogeneration import ScenarioGenerator, xosc

    SIZES = [int(s) for s in sys.argv[2].split(",")]


    def speed(value):
        dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
        return xosc.AbsoluteSpeedAction(value, dynamics)


    def after(name, element):
        return xosc.ValueTrigger(
            f"after_{name}", 0, xosc.ConditionEdge.none,
            xosc.StoryboardElementStateCondition(
                xosc.StoryboardElementType.event, element, xosc.StoryboardElementState.completeState
            ),
        )


    def near(name, actor, x, y, radius):
        return xosc.EntityTrigger(
            f"near_{name}", 0, xosc.ConditionEdge.none,
            xosc.DistanceCondition(radius, xosc.Rule.lessThan, xosc.WorldPosition(x, y, 0, 0), freespace=False), actor,
        )


    def marker(name, trigger):
        event = xosc.Event(name, xosc.Priority.override)
        event.add_action(f"{name}_action", xosc.VariableSetAction("SceML_marker", name))
        event.add_trigger(trigger)
        return event


    def maneuver_group(actor, events):
        maneuver = xosc.Maneuver(f"{actor}_maneuver")
        for event in events:
            maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{actor}_group")
        group.add_actor(actor)
        group.add_maneuver(maneuver)
        return group


    class UIS2(ScenarioGenerator):
        def __init__(self):
            super().__init__()
            values = [[float(i) for i in range(size)] for size in SIZES]
            names = ["ego_speed", "target_speed", "radius", "car_speed"][: len(values)]
            self.parameters = dict(zip(names, values))
            self.naming = "numerical"
            self.number_of_parallel_writings = int(sys.argv[3])

        def scenario(self, **p):
            ego_speed = 3 + p.get("ego_speed", 0.0)
            target = 5 + p.get("target_speed", 0.0) / 10
            radius = 3 + p.get("radius", 0.0) / 10
            car_speed = 8 + p.get("car_speed", 0.0) / 10
            box = xosc.BoundingBox(1.8, 4.5, 1.5, 1.35, 0, 0.75)
            front = xosc.Axle(0.5, 0.6, 1.53, 2.7, 0.3)
            rear = xosc.Axle(0, 0.6, 1.53, 0, 0.3)
            entities = xosc.Entities()
            ego = xosc.Vehicle("vehicle.tesla.model3", xosc.VehicleCategory.car, box, front, rear, 69.4, 10, 10)
            ego.add_property("type", "ego_vehicle")
            entities.add_scenario_object("ego", ego)
            car = xosc.Vehicle("vehicle.audi.a2", xosc.VehicleCategory.car, box, front, rear, 69.4, 10, 10)
            entities.add_scenario_object("car", car)
            walker_box = xosc.BoundingBox(0.5, 0.5, 1.8, 0, 0, 0.9)
            walker = xosc.Pedestrian("walker.pedestrian.0001", 80, xosc.PedestrianCategory.pedestrian, walker_box)
            entities.add_scenario_object("pedestrian", walker)

            init = xosc.Init()
            for actor, road, lane, s, v in (("ego", "3", 1, 30, ego_speed), ("car", "1", 1, 30, 0), ("pedestrian", "4", 2, 1, 0)):
                init.add_init_action(actor, xosc.TeleportAction(xosc.LanePosition(s, 0, lane, road)))
                init.add_init_action(actor, speed(v))
            init.add_global_action(xosc.EnvironmentAction(xosc.Environment(
                "env", xosc.TimeOfDay(False, 2026, 1, 1, 12, 0, 0),
                xosc.Weather(xosc.FractionalCloudCover.zeroOktas,
                             precipitation=xosc.Precipitation(xosc.PrecipitationType.dry, 0)),
                xosc.RoadCondition(1.0),
            )))

            start = xosc.ValueTrigger("start", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(0, xosc.Rule.greaterThan))
            accelerate = xosc.Event("Accelerate_1", xosc.Priority.override)
            accelerate.add_action("accelerate", speed(target))
            accelerate.add_trigger(start)
            turn = xosc.Event("TurnLeft_1", xosc.Priority.override)
            turn.add_action("route", xosc.AcquirePositionAction(xosc.WorldPosition(-34, 1.75, 0, 3.14)))
            turn.add_trigger(after("accelerate", "Accelerate_1"))
            arrived = marker("TurnLeft_1_arrived", near("turn", "ego", -34, 1.75, 3))
            reached = marker("InLocationRadius_1", near("sync1", "ego", -34, 1.75, 3))
            sync2 = marker("InLocationRadius_2", near("sync2", "ego", -0.8, -0.8, radius))
            drive = xosc.Event("DriveDistance_1", xosc.Priority.override)
            drive.add_action("drive", speed(car_speed))
            drive.add_trigger(after("sync2", "InLocationRadius_2"))
            driven = marker("DriveDistance_1_done", xosc.EntityTrigger(
                "driven", 0, xosc.ConditionEdge.none, xosc.TraveledDistanceCondition(60), "car"))
            close = marker("InVehicleRadius_1", xosc.EntityTrigger(
                "close", 0, xosc.ConditionEdge.none,
                xosc.RelativeDistanceCondition(15, xosc.Rule.lessThan, xosc.RelativeDistanceType.euclidianDistance, "car", freespace=False),
                "pedestrian"))
            walk = xosc.Event("Accelerate_2", xosc.Priority.override)
            walk.add_action("walk", speed(1.5))
            walk.add_trigger(after("close", "InVehicleRadius_1"))
            cross = xosc.Event("Cross_1", xosc.Priority.override)
            cross.add_action("cross", xosc.AcquirePositionAction(xosc.WorldPosition(-10, 4.5, 0, 1.57)))
            cross.add_trigger(after("walk", "Accelerate_2"))
            crossed = marker("Cross_1_arrived", near("crossed", "pedestrian", -10, 4.5, 2))
            sync4 = marker("InLocationRadius_3", near("sync4", "pedestrian", -10, 4.5, 2))

            act = xosc.Act("UIS2_Act", start)
            act.add_maneuver_group(maneuver_group("ego", [accelerate, turn, arrived, reached, sync2]))
            act.add_maneuver_group(maneuver_group("car", [drive, driven]))
            act.add_maneuver_group(maneuver_group("pedestrian", [close, walk, cross, crossed, sync4]))
            story = xosc.Story("UIS2")
            story.add_act(act)
            stop = xosc.ValueTrigger("stop", 0, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(60, xosc.Rule.greaterThan), "stop")
            board = xosc.StoryBoard(init, stop)
            board.add_story(story)
            declarations = xosc.ParameterDeclarations()
            road = xosc.RoadNetwork(roadfile="../maps/intersection.xodr")
            return xosc.Scenario("UIS2", "bench", declarations, entities, board, road, xosc.Catalog(), osc_minor_version=3)


    UIS2().generate(sys.argv[1])
    """
)


def factors(n: int) -> list[int]:
    """Split n into up to four factors (10s where possible) for a cartesian sweep of n files."""
    sizes: list[int] = []
    while n % 10 == 0 and len(sizes) < 3 and n > 10:
        sizes.append(10)
        n //= 10
    return [n, *sizes]


@dataclass(frozen=True)
class Run:
    """One timed run: how long it took, and when its first and last files were written."""

    seconds: float
    files: int
    #: From the run's start to the first file (the files' modification times).
    before_first: float
    #: From the first file to the last.
    first_to_last: float
    #: CPU seconds of the process and of the processes it waited for (user + system).
    cpu: float = 0.0

    @property
    def rate(self) -> float:
        return self.files / self.seconds

    @property
    def steady_rate(self) -> float:
        return (self.files - 1) / self.first_to_last


def _run_of(started: float, seconds: float, files: list[Path], cpu: float) -> Run:
    """A Run from its start (wall clock), duration, files and CPU seconds."""
    times = [f.stat().st_mtime_ns / 1e9 for f in files]
    return Run(seconds, len(files), min(times) - started, max(times) - min(times), cpu)


def _children_cpu() -> float:
    """CPU seconds (user + system) of the child processes this process has waited for."""
    times = os.times()
    return times.children_user + times.children_system


def run_sceml(n: int, workers: int, out: Path, pythonpath: str | None = None) -> Run:
    """The whole `sceml sample` command, as a user runs it (from the tree at `pythonpath`, if
    given, instead of this checkout)."""
    command = [
        sys.executable,
        "-c",
        "from sceml.cli import main; main()",
        "sample",
        str(LOGICAL),
        "--strategy",
        "random",
        "--n",
        str(n),
        "--seed",
        "1",
        "--format",
        "xosc",
        "--workers",
        str(workers),
        "-o",
        str(out),
    ]
    env = dict(os.environ) if pythonpath is None else {**os.environ, "PYTHONPATH": pythonpath}
    wall, started, cpu = time.time(), time.perf_counter(), _children_cpu()
    done = subprocess.run(command, capture_output=True, text=True, check=True, env=env)
    elapsed = time.perf_counter() - started
    print("    sceml says:", done.stdout.strip().splitlines()[-1])
    return _run_of(wall, elapsed, sorted(out.glob("*.xosc")), _children_cpu() - cpu)


def run_scenariogeneration(n: int, out: Path, writers: int = 1) -> Run:
    """The whole scenariogeneration process; `writers` > 1: its number_of_parallel_writings."""
    script = out.parent / "sg_uis2.py"
    script.write_text(SCENARIOGENERATION_SCRIPT, encoding="utf-8")
    sizes = ",".join(str(s) for s in factors(n))
    wall, started, cpu = time.time(), time.perf_counter(), _children_cpu()
    command = [sys.executable, str(script), str(out), sizes, str(writers)]
    subprocess.run(command, check=True, capture_output=True)
    elapsed = time.perf_counter() - started
    return _run_of(wall, elapsed, sorted(out.rglob("*.xosc")), _children_cpu() - cpu)


FLOOR_SCRIPT = textwrap.dedent(
    """
    import multiprocessing, sys
    from pathlib import Path
    from lxml import etree
    from sceml.xosc import schema

    source, out, workers = Path(sys.argv[1]), Path(sys.argv[2]), int(sys.argv[3])
    files = sorted(source.glob("*.xosc"))
    trees = [etree.parse(str(f)) for f in files]
    version = schema.declared_version(trees[0])
    schema.is_valid_tree(trees[0], version)  # compiles the XSD once, before the processes fork


    def share(k):
        for source_file, tree in list(zip(files, trees))[k::workers]:
            data = etree.tostring(tree, xml_declaration=True, encoding="UTF-8")
            if not schema.is_valid_tree(tree, version):
                raise SystemExit(f"{source_file} fails the XSD")
            with open(out / source_file.name, "wb") as stream:
                stream.write(data)


    processes = [multiprocessing.get_context("fork").Process(target=share, args=(k,)) for k in range(workers)]
    for process in processes:
        process.start()
    for process in processes:
        process.join()
        if process.exitcode:
            sys.exit(1)
    """
)


def run_floor(source: Path, workers: int, out: Path) -> Run:
    """The floor for the documents in `source` on `workers` processes, as a whole process:
    Python's start, importing lxml and the XSD loader, compiling the XSD and parsing the
    documents are inside the time, as they are in ours."""
    out.mkdir()
    command = [sys.executable, "-c", FLOOR_SCRIPT, str(source), str(out), str(workers)]
    wall, started, cpu = time.time(), time.perf_counter(), _children_cpu()
    subprocess.run(command, check=True, capture_output=True)
    elapsed = time.perf_counter() - started
    return _run_of(wall, elapsed, sorted(out.glob("*.xosc")), _children_cpu() - cpu)


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--n", type=int, default=5_000, help="files per run (default 5000)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--rounds", type=int, default=3, help="rounds of the three (default 3)")
    parser.add_argument("--keep", type=Path, help="keep the outputs in this folder")
    parser.add_argument("--before", help="PYTHONPATH of another tree: ours from it too")
    args = parser.parse_args()
    base = args.keep or Path(tempfile.mkdtemp(prefix="sceml-bench-"))
    base.mkdir(parents=True, exist_ok=True)
    print(f"N = {args.n}, workers = {args.workers}, rounds = {args.rounds}, output under {base}")
    print(f"load average {_load()} at the start")

    # The floor writes the documents of an untimed sceml run, so that it makes the same files.
    source = base / "documents"
    run_sceml(args.n, args.workers, source)

    runs: dict[str, Callable[[Path], Run]] = {
        "ours": lambda out: run_sceml(args.n, args.workers, out),
        "scenariogeneration": lambda out: run_scenariogeneration(args.n, out),
        "scenariogeneration parallel": lambda out: run_scenariogeneration(
            args.n, out, args.workers
        ),
        "floor": lambda out: run_floor(source, args.workers, out),
    }
    if args.before:
        runs["ours before"] = lambda out: run_sceml(args.n, args.workers, out, args.before)
    done: dict[str, list[Run]] = {name: [] for name in runs}
    names = list(runs)
    for number in range(args.rounds):
        order = names[number % len(names) :] + names[: number % len(names)]
        for name in order:
            run = runs[name](base / f"{name.replace(' ', '-')}-{number}")
            if run.files != args.n:
                raise SystemExit(f"{name} wrote {run.files} files, not {args.n}")
            done[name].append(run)
            print(
                f"  round {number + 1}, {name}: {run.files} files in {run.seconds:.2f} s "
                f"({run.before_first:.2f} s to the first file, {run.first_to_last:.2f} s from "
                f"the first to the last; {run.cpu:.2f} CPU s; load {_load()})"
            )
    # Nothing is deleted before the end: on ext4 without a journal (this VM's disk), making a
    # file skips the inodes deleted in the last minute or more, one buffer lookup each, so a
    # deletion would slow down whichever run came next.
    if args.keep is None:
        shutil.rmtree(base)

    labels = {
        "ours": "ours, sceml sample (validated), whole process",
        "scenariogeneration": "scenariogeneration (no validation), whole process",
        "scenariogeneration parallel": "scenariogeneration, number_of_parallel_writings="
        f"{args.workers}, whole process",
        "floor": f"floor (start, parse, lxml serialise + XSD validate + plain write, {args.workers}"
        " processes), whole process",
        "ours before": f"ours from {args.before}, whole process",
    }
    rate = {name: statistics.median(r.rate for r in done[name]) for name in names}
    per_cpu = {name: statistics.median(r.files / r.cpu for r in done[name]) for name in names}
    for name in names:
        before = statistics.median(r.before_first for r in done[name])
        steady = statistics.median(r.steady_rate for r in done[name])
        print(
            f"{labels[name]}: {rate[name]:.0f} files/s "
            f"({before:.2f} s to the first file, then {steady:.0f} files/s; "
            f"{per_cpu[name]:.0f} files per CPU s)"
        )
    best = max(rate["scenariogeneration"], rate["scenariogeneration parallel"])
    print(f"ours / scenariogeneration's faster mode: {rate['ours'] / best:.2f}x (target >= 5)")
    best_cpu = max(per_cpu["scenariogeneration"], per_cpu["scenariogeneration parallel"])
    print(f"  ... in files per CPU second: {per_cpu['ours'] / best_cpu:.2f}x")
    print(f"floor / ours: {rate['floor'] / rate['ours']:.2f}x slower than the floor (target <= 2)")
    if args.before:
        print(
            f"before / scenariogeneration's faster mode: {rate['ours before'] / best:.2f}x; "
            f"ours / before: {rate['ours'] / rate['ours before']:.2f}x"
        )
    print(f"load average {_load()} at the end")


def _load() -> str:
    """The 1, 5 and 15-minute load averages."""
    return " ".join(f"{value:.1f}" for value in os.getloadavg())


if __name__ == "__main__":
    main()

"""How faithfully `sceml import` reads real OpenSCENARIO files (issue 24): the corpus table.

    python benchmarks/import_corpus.py DIR... [--esmini PATH] [--catalog-path DIR]
        [--allow DIR] [--csv per-file.csv] [--work DIR] [--timeout 60] [--constructs]

Every `.xosc` scenario below the DIRs (catalogs and ParameterValueDistributions are skipped) is
imported (`sceml import`, with the DIRs allowed), validated, and exported back at its own
version, in-process, each stage in a work folder; a model whose only errors are the original's
own is exported as a user told so would export it, with `--allow-implausible` (which writes
plausibility limits the file states, and nothing else). With `--esmini` the original and the
re-export are played headless at 0.05 s steps and compared:

- every event of the original starts within one step of the re-export's event of that name (or,
  when the re-export has no such name, of an unmatched re-export event start);
- every entity of the original stays within 0.5 m of its original trajectory (esmini's CSV,
  compared at the original's time stamps);
- the run ends at the same time (within one step).

It prints the stage table (play / import writes / exit 0 / validates clean / exports / plays
the same; exit 0 is `sceml import`'s exit code, which errors the original has too do not fail,
docs/import.md), the opaque rate (opaque nodes over the Actions and Conditions of the originals),
the errors the original does not deserve and those it has too,
with `--constructs` what the files use that metamodel 1.0 has no class for, and, with `--csv`,
one row per file with the reason a stage failed and, for a re-export that plays otherwise,
every difference (`differences`: the end, each event off by more than a step, each entity off
its path with the time it first is). A progress line per file goes to
stderr. Nothing is written into the DIRs. esmini plays with a fixed `--seed` (SEED), so that
the random traffic of a swarm or a sloppy driver is the same in the original and the re-export.
"""

from __future__ import annotations

import argparse
import bisect
import csv
import math
import re
import subprocess
import sys
import tempfile
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field, fields
from pathlib import Path

from lxml import etree

from sceml.errors import SceMLError
from sceml.export.names import sanitize
from sceml.files.safexml import hardened_parser
from sceml.importer import import_to_file
from sceml.importer.verdict import judge
from sceml.model.loading import load_scenario
from sceml.validation import validate

STEP = 0.05
#: esmini draws a new random seed per run unless given one: the original and the re-export
#: must draw the same random traffic (a swarm's vehicles, a sloppy driver: `controller_test`'s
#: original played twice differed by 831 m) to be compared.
SEED = 1
#: A trajectory may differ by this much (m) and still be the same run.
DISTANCE = 0.5
#: The line esmini logs when a storyboard element starts: `[12.300] [info] Name standbyState
#: -> startTransition -> runningState`.
_START = re.compile(r"^\[(?P<t>[0-9.]+)\] \[info\] (?P<name>.+?) standbyState -> startTransition")


@dataclass
class Run:
    """One esmini run: when each named element started, each entity's path, the last time."""

    starts: dict[str, float]
    paths: dict[str, list[tuple[float, float, float]]]
    end: float


@dataclass
class Row:
    """The stages one file reached, and why the first failing one failed."""

    file: str
    plays: bool | None = None
    writes: bool = False
    exit0: bool = False
    clean: bool = False
    exports: bool = False
    same: bool | None = None
    actions: int = 0
    opaque: int = 0
    #: Validation errors the original does not deserve (the import caused them), and those it
    #: has too (values it states, judged against the kind's limits or the map).
    undeserved: int = 0
    deserved: int = 0
    why: str = ""
    #: Every difference of the re-export's run (`differences`), for the per-file diagnosis.
    differences: str = ""
    #: Constructs of the original the metamodel lacks (`constructs`), with their counts.
    kinds: Counter[str] = field(default_factory=Counter)


def scenarios(folders: Sequence[Path]) -> Iterator[Path]:
    """The scenario files below the folders: no catalogs, no distributions."""
    for folder in folders:
        for path in sorted(folder.rglob("*.xosc")):
            try:
                root = etree.parse(str(path), hardened_parser()).getroot()
            except etree.XMLSyntaxError:
                yield path  # the import reports it
                continue
            if root.find("Storyboard") is not None:
                yield path


#: Position kinds SceML 1.0 has no class for.
POSITIONS = (
    "RoadPosition",
    "RelativeRoadPosition",
    "RelativeLanePosition",
    "RelativeObjectPosition",
    "RelativeWorldPosition",
    "RoutePosition",
    "TrajectoryPosition",
    "GeoPosition",
)
#: Elements counted as they are (tag -> label).
COUNTED = {
    "ObjectController": "controller: ObjectController (entity)",
    "AssignControllerAction": "controller: AssignControllerAction",
    "ActivateControllerAction": "controller: ActivateControllerAction",
    "OverrideControllerValueAction": "controller: OverrideControllerValueAction",
    "TraveledDistanceCondition": "condition: TraveledDistance",
    "TimeHeadwayCondition": "condition: TimeHeadway",
    "ParameterCondition": "condition: Parameter",
    "VariableCondition": "condition: Variable",
    "ParameterAction": "action: Parameter",
    "VariableAction": "action: Variable",
    "TrafficSignalCondition": "traffic signal: condition",
    "TrafficSignalControllerCondition": "traffic signal: controller condition",
    "TrafficSignalStateAction": "traffic signal: state action",
    "TrafficSignalControllerAction": "traffic signal: controller action",
    "FollowTrajectoryAction": "action: FollowTrajectory",
    "LaneOffsetAction": "action: LaneOffset",
    "SynchronizeAction": "action: Synchronize",
}


def constructs(root: etree._Element) -> Counter[str]:
    """What the metamodel 1.0 lacks, as used in one file: position kinds by where they are
    (start, destination, condition), controllers, TimeToCollision options, lane change targets,
    parameter and variable conditions, traffic signals, repeat counts."""
    found: Counter[str] = Counter()
    for position in root.iter("Position"):
        kind = next((c.tag for c in position if isinstance(c.tag, str)), "")
        if kind in POSITIONS:
            found[f"position: {kind} as {_use(position)}"] += 1
    for element in root.iter(*COUNTED):
        found[COUNTED[str(element.tag)]] += 1
    for ttc in root.iter("TimeToCollisionCondition"):
        distance = ttc.get("relativeDistanceType", "(1.0: alongRoute)")
        found[f"TimeToCollision: freespace={ttc.get('freespace')} distance={distance}"] += 1
    for change in root.iter("LaneChangeTarget"):
        target = next((c.tag for c in change if isinstance(c.tag, str)), "")
        value = next(iter(change)).get("value", "")
        found[f"lane change: {target} {value}"] += 1
    for event in root.iter("Event"):
        if int(event.get("maximumExecutionCount", "1") or 1) > 1:
            found["repeat: Event maximumExecutionCount > 1"] += 1
    for group in root.iter("ManeuverGroup"):
        if int(group.get("maximumExecutionCount", "1") or 1) > 1:
            found["repeat: ManeuverGroup maximumExecutionCount > 1"] += 1
    for act in root.iter("Act"):
        if act.find("StopTrigger/ConditionGroup") is not None:
            found["act StopTrigger"] += 1
    return found


def _use(position: etree._Element) -> str:
    ancestors = {a.tag for a in position.iterancestors()}
    if "Condition" in ancestors:
        return "condition"
    if "Init" in ancestors and "TeleportAction" in ancestors:
        return "start"
    return "destination or other action"


def play(esmini: Path, scenario: Path, work: Path, timeout: float) -> Run | str:
    """Play a file headless; its Run, or why it did not play."""
    log, trace = work / f"{scenario.stem}.log", work / f"{scenario.stem}.csv"
    command = [str(esmini), "--headless", "--osc", str(scenario), "--fixed_timestep", str(STEP)]
    command += ["--seed", str(SEED)]
    command += ["--logfile_path", str(log), "--csv_logger", str(trace)]
    try:
        done = subprocess.run(command, capture_output=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        return f"esmini still running after {timeout:g} s"
    if done.returncode != 0 or not trace.is_file():
        errors = [line for line in _lines(log) if "[error]" in line]
        return f"esmini exit {done.returncode}: {errors[-1][:120] if errors else ''}".strip()
    starts: dict[str, float] = {}
    for line in _lines(log):
        match = _START.match(line)
        if match is not None:
            starts.setdefault(match["name"], float(match["t"]))
    paths, end = _paths(trace)
    return Run(starts, paths, end)


def _lines(path: Path) -> list[str]:
    return path.read_text(errors="replace").splitlines() if path.is_file() else []


def _paths(trace: Path) -> tuple[dict[str, list[tuple[float, float, float]]], float]:
    """Each entity's (t, x, y) from esmini's CSV logger, and the last time stamp."""
    rows = list(csv.reader(trace.read_text(errors="replace").splitlines(), skipinitialspace=True))
    header = next((r for r in rows if r and r[0].startswith("Index")), None)
    if header is None:
        return {}, 0.0
    names = [i for i, h in enumerate(header) if h.endswith("Entity_Name [-]")]
    if not names:
        return {}, 0.0
    # The header names the entities of the first step only; entities added later (a swarm's
    # vehicles) follow in blocks as wide as the first one's. The header's last block ends in a
    # trailing comma, so its width is its `#1` columns, not what is left of the line.
    stride = sum(1 for h in header if h.startswith("#1 "))
    x = next(i for i, h in enumerate(header) if h.endswith("World_Position_X [m]")) - names[0]
    y = next(i for i, h in enumerate(header) if h.endswith("World_Position_Y [m]")) - names[0]
    paths: dict[str, list[tuple[float, float, float]]] = {}
    end = 0.0
    for row in rows[rows.index(header) + 1 :]:
        if len(row) < 3 or not row[0].strip().isdigit():
            continue
        end = float(row[1])
        for at in range(names[0], len(row) - max(x, y), stride):
            point = _point(row, at, x, y)
            if point is not None:
                paths.setdefault(row[at], []).append((end, *point))
    return paths, end


def _point(row: list[str], at: int, x: int, y: int) -> tuple[float, float] | None:
    """An entity's x and y in a CSV row, or None where the row has no entity there."""
    try:
        return float(row[at + x]), float(row[at + y])
    except ValueError:
        return None


def events(path: Path) -> list[str]:
    """The Event names of a scenario file."""
    root = etree.parse(str(path), hardened_parser()).getroot()
    return [str(e.get("name")) for e in root.iter("Event")]


def compare(original: Run, again: Run, ours: list[str], theirs: list[str]) -> str:
    """Why the re-export does not play the same (its first difference); empty when it does."""
    found = differences(original, again, ours, theirs)
    return found[0] if found else ""


def differences(original: Run, again: Run, ours: list[str], theirs: list[str]) -> list[str]:
    """Every way the re-export's run differs: the end, each event that starts at another time
    (earliest first), each entity off its path (worst first)."""
    found = []
    if abs(original.end - again.end) > STEP + 1e-9:
        found.append(f"ends at {again.end:g} s instead of {original.end:g} s")
    free = sorted(again.starts[n] for n in theirs if n in again.starts and n not in ours)
    late = []
    for name in sorted((n for n in ours if n in original.starts), key=original.starts.get):
        want = original.starts[name]
        got = again.starts.get(name) if name in theirs else _take(free, want)
        if got is None or abs(got - want) > STEP + 1e-9:
            shown = "never" if got is None else f"at {got:g} s"
            late.append(f"event {name} starts {shown} instead of {want:g} s")
    found.extend(late)
    off = []
    for entity, path in original.paths.items():
        # The export makes names safe for OpenSCENARIO (`ego jerk` -> `ego_jerk`).
        other = again.paths.get(entity, again.paths.get(sanitize(entity, entity)))
        if other is None:
            off.append((math.inf, f"entity {entity} is missing"))
            continue
        worst = max(_distance(point, other) for point in path)
        if worst > DISTANCE:
            off.append(
                (
                    worst,
                    f"entity {entity} is {worst:.2f} m off its original trajectory "
                    f"(first by 0.5 m at {_first_off(path, other):g} s)",
                )
            )
    found.extend(text for _, text in sorted(off, key=lambda item: -item[0]))
    return found


def _first_off(
    path: list[tuple[float, float, float]], other: list[tuple[float, float, float]]
) -> float:
    """When an entity first leaves its original path by more than DISTANCE."""
    return next((p[0] for p in path if _distance(p, other) > DISTANCE), math.nan)


def _take(free: list[float], want: float) -> float | None:
    """The unmatched start nearest `want`, removed from `free`."""
    if not free:
        return None
    at = bisect.bisect_left(free, want)
    best = min((i for i in (at - 1, at) if 0 <= i < len(free)), key=lambda i: abs(free[i] - want))
    return free.pop(best)


def _distance(point: tuple[float, float, float], path: list[tuple[float, float, float]]) -> float:
    """How far the other run's entity is from `point` at the same time (nearest time stamp)."""
    times = [p[0] for p in path]
    at = min(bisect.bisect_left(times, point[0]), len(path) - 1)
    _, x, y = path[at]
    return math.hypot(x - point[1], y - point[2])


def measure(path: Path, work: Path, options: argparse.Namespace) -> Row:
    """Every stage for one file."""
    row = Row(str(path))
    original = None
    if options.esmini is not None:
        original = play(options.esmini, path, work / "original", options.timeout)
        row.plays = isinstance(original, Run)
    tree = etree.parse(str(path), hardened_parser())
    row.kinds = constructs(tree.getroot())
    row.actions = sum(1 for _ in tree.getroot().iter("Action", "Condition", "PrivateAction"))
    row.actions -= sum(
        1 for a in tree.getroot().iter("PrivateAction") if a.getparent().tag == "Action"
    )
    model = work / "models" / f"{path.stem}.xmi"
    try:
        imported = import_to_file(
            path, model, catalog_paths=options.catalog_path, allow=options.allowed
        )
    except SceMLError as error:
        row.why = f"import: {error}"
        return row
    except Exception as error:  # noqa: BLE001 - a crash is what the table must show
        row.why = f"import crashed: {type(error).__name__}: {error}"
        return row
    row.writes = True
    row.opaque = imported.report.counts()["opaque"]
    document = load_scenario(model, allow=options.allowed)
    verdict = judge(validate(document.root, document=document))
    caused, deserved = verdict.caused_errors, verdict.original_errors
    row.undeserved, row.deserved = len(caused), len(deserved)
    # `sceml import`'s exit code: the original's own errors do not fail it (not --strict).
    row.exit0 = verdict.exit_code() == 0
    row.clean = not caused and not deserved
    if caused:
        row.why = f"validate: [{caused[0].code}] {caused[0].message}"
    elif deserved:
        row.why = f"validate, the original's too: [{deserved[0].code}] {deserved[0].message}"
    again = work / "exports" / path.parent.name / f"{path.stem}.xosc"
    again.parent.mkdir(parents=True, exist_ok=True)
    try:
        from sceml.export import export_to_file

        version = imported.report.needs_version or imported.report.version
        # As a user would: told by `sceml import` that the original breaks these limits too
        # (and nothing else), they export with --allow-implausible; never otherwise.
        implausible = not caused and bool(deserved)
        export_to_file(
            document.root,
            again,
            version=version,
            source_path=model,
            allow_implausible=implausible,
        )
    except SceMLError as error:
        row.why = row.why or f"export: {error}"
        return row
    row.exports = True
    if isinstance(original, Run):
        replayed = play(options.esmini, again, work / "again", options.timeout)
        if isinstance(replayed, str):
            row.same, row.why = False, f"re-export: {replayed}"
        else:
            found = differences(original, replayed, events(path), events(again))
            row.same, row.why = not found, row.why or (found[0] if found else "")
            row.differences = "; ".join(found)
    elif original is not None:
        row.why = row.why or f"original: {original}"
    return row


def table(rows: list[Row]) -> str:
    """The issue's stage table and the opaque rate."""
    played = [r for r in rows if r.plays] if any(r.plays is not None for r in rows) else rows
    lines = [f"{len(rows)} scenario files", "", "| stage | files |", "|---|---|"]
    if any(r.plays is not None for r in rows):
        lines.append(f"| play in esmini as they are | {len(played)} |")
    lines += [
        f"| `sceml import` writes a model | {sum(r.writes for r in rows)} |",
        f"| ... with exit 0 (no error the original does not deserve) | "
        f"{sum(r.exit0 for r in rows)} |",
        f"| the model validates with no errors | {sum(r.clean for r in rows)} |",
        f"| `sceml export` writes it back | {sum(r.exports for r in rows)} |",
    ]
    if any(r.plays is not None for r in rows):
        lines.append(
            f"| the re-export plays the same in esmini | {sum(bool(r.same) for r in rows)} |"
        )
    actions = sum(r.actions for r in rows if r.writes)
    opaque = sum(r.opaque for r in rows if r.writes)
    rate = 100.0 * opaque / actions if actions else 0.0
    lines += ["", f"opaque: {opaque} of {actions} actions and conditions ({rate:.1f}%)"]
    lines.append(
        f"errors the original does not deserve: {sum(r.undeserved for r in rows)} in "
        f"{sum(1 for r in rows if r.undeserved)} files; errors it has too: "
        f"{sum(r.deserved for r in rows)} in {sum(1 for r in rows if r.deserved)} files"
    )
    return "\n".join(lines) + "\n"


def growth(rows: list[Row]) -> str:
    """What the files use that metamodel 1.0 lacks: elements and files, most files first."""
    elements: Counter[str] = Counter()
    files: Counter[str] = Counter()
    for row in rows:
        elements.update(row.kinds)
        files.update(row.kinds.keys())
    lines = ["", "| construct (not in metamodel 1.0) | elements | files |", "|---|---|---|"]
    for name, count in sorted(files.items(), key=lambda item: (-item[1], item[0])):
        lines.append(f"| {name} | {elements[name]} | {count} |")
    return "\n".join(lines) + "\n"


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("dirs", nargs="+", type=Path, metavar="DIR")
    parser.add_argument("--esmini", type=Path, help="esmini binary: play and compare")
    parser.add_argument("--catalog-path", type=Path, action="append", default=[])
    parser.add_argument(
        "--allow",
        type=Path,
        action="append",
        default=[],
        help="another folder the files may read maps and catalogs from (the DIRs always)",
    )
    parser.add_argument("--csv", type=Path, help="write one row per file here")
    parser.add_argument("--work", type=Path, help="folder for models, exports, logs (temporary)")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per esmini run")
    parser.add_argument(
        "--constructs",
        action="store_true",
        help="also count what the files use that metamodel 1.0 lacks",
    )
    parser.add_argument(
        "--only",
        action="append",
        default=[],
        metavar="NAME",
        help="measure only the files whose name (without .xosc) is NAME; repeat for more",
    )
    options = parser.parse_args(argv)
    options.dirs = [d.resolve() for d in options.dirs]
    options.allowed = [*options.dirs, *(d.resolve() for d in options.allow)]
    with tempfile.TemporaryDirectory() as temporary:
        work = (options.work or Path(temporary)).resolve()
        for sub in ("original", "again", "models", "exports"):
            (work / sub).mkdir(parents=True, exist_ok=True)
        files = [
            path
            for path in scenarios(options.dirs)
            if not options.only or path.stem in options.only
        ]
        rows = []
        for number, path in enumerate(files, 1):
            print(f"[{number}/{len(files)}] {path}", file=sys.stderr, flush=True)
            rows.append(measure(path, work, options))
    print(table(rows), end="")
    if options.constructs:
        print(growth(rows), end="")
    if options.csv is not None:
        with options.csv.open("w", newline="") as out:
            writer = csv.writer(out)
            names = [f.name for f in fields(Row) if f.name != "kinds"]
            writer.writerow(names)
            for row in rows:
                writer.writerow([getattr(row, name) for name in names])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

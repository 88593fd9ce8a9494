"""esmini's log and CSV formats (esmini 3.6), read into a `PlayerRun`; and running esmini.

The log (`--logfile_path`) has a line per storyboard transition,
`[9.100] [info] X standbyState -> startTransition -> runningState`, the block of condition
values of a trigger that fired, and a warning per action esmini stops because another action
took its control domain. The CSV (`--csv_logger`) has a row per actor and time step with the
reference point, heading, speed and lane.
"""

from __future__ import annotations

import csv
import io
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np

from ..errors import LoadError
from ..export.names import SEPARATOR
from ..xosc import PLAYER_STEP
from .record import CutShort, EventRun, PlayerRun, Trace

NAME = "esmini"
_TIME = r"^\[(\d+\.\d+)\] \[\w+\] "
TRANSITION = re.compile(_TIME + r"(\S+) (\w+)State -> (\w+)Transition -> (\w+)State$")
TRIGGER_OPEN = re.compile(_TIME + r"Trigger /-+$")
TRIGGER_GROUP = re.compile(r"^\[\d+\.\d+\] \[\w+\] Group (\d+):$")
TRIGGER_VALUE = re.compile(r"^\[\d+\.\d+\] \[\w+\] (\S+): (true|false)$")
CONFLICT = re.compile(_TIME + r"Stopping object (\S+) (\S+) on conflicting (.+)$")
VERSION = re.compile(r"esmini GIT REV: (\S+)")
LOADING = re.compile(r"Loading \S+ \(v(\d+\.\d+)\)")
#: Wall-clock limit of one esmini run; the scenario's own time limit ends it long before.
WALL_LIMIT_SECONDS = 600
_ACTION = f"{SEPARATOR}action"


def read(log_path: Path, csv_path: Path | None) -> PlayerRun:
    """A run from esmini's log file and, if given, its CSV file."""
    run = parse_log(_text(log_path), str(log_path))
    if csv_path is not None:
        run.traces, step = parse_csv(_text(csv_path), str(csv_path))
        run.step = step or run.step
    return run


def _text(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8", errors="replace")
    except OSError as error:
        raise LoadError(f"cannot read {path}: {error.strerror}", file=str(path)) from None


def parse_log(text: str, file: str = "<log>") -> PlayerRun:
    """Event transitions, cut-short actions, the storyboard's stop and the trigger that stopped it."""
    run = PlayerRun(NAME)
    groups: list[list[tuple[str, bool]]] = []
    for line in text.splitlines():
        if found := VERSION.search(line):
            run.version = found.group(1)
        elif found := LOADING.search(line):
            run.osc_version = found.group(1)
        if TRIGGER_OPEN.match(line):
            groups = []
        elif TRIGGER_GROUP.match(line):
            groups.append([])
        elif (found := TRIGGER_VALUE.match(line)) and groups:
            groups[-1].append((found.group(1), found.group(2) == "true"))
        elif found := TRANSITION.match(line):
            _record(run, found, groups)
        elif found := CONFLICT.match(line):
            time, _, action, domains = found.groups()
            event = action[: action.rindex(_ACTION)] if _ACTION in action else action
            run.cut_short.append(CutShort(float(time), event, f"conflicting {domains}"))
    if run.version == "unknown" and not run.events:
        raise LoadError("this is not an esmini log (no version line, no transitions)", file=file)
    return run


def _record(run: PlayerRun, found: re.Match[str], groups: list[list[tuple[str, bool]]]) -> None:
    time, element, before, transition, after = found.groups()
    if element == "storyBoard":
        if after == "complete" and run.stop_time is None:
            run.stop_time, run.stop_how, run.stop_groups = float(time), transition, groups
        return
    event = run.events.setdefault(element, EventRun())
    if before == "standby" and transition == "start" and event.start is None:
        event.start = float(time)
    if after == "complete" and event.end is None and event.stopped is None:
        # An event stopped (with the storyboard, or by a conflict) has not finished by itself.
        if transition == "end":
            event.end = float(time)
        else:
            event.stopped = float(time)


def parse_csv(text: str, file: str = "<csv>") -> tuple[dict[str, Trace], float | None]:
    """Each actor's trace from esmini's CSV, and the time step between its rows."""
    lines = [line for line in text.splitlines() if line.strip()]
    header_at = next((i for i, line in enumerate(lines) if line.startswith("Index")), None)
    if header_at is None:
        raise LoadError("this is not an esmini CSV log (no 'Index' header row)", file=file)
    header = [cell.strip() for cell in lines[header_at].split(",")]
    columns = _columns(header)
    rows: dict[str, list[tuple[float, ...]]] = {}
    for line_number, cells in enumerate(
        csv.reader(io.StringIO("\n".join(lines[header_at + 1 :]))), start=header_at + 2
    ):
        cells = [cell.strip() for cell in cells]
        try:
            time = float(cells[1])
            for name_at, at in columns:
                name = cells[name_at]
                values = [float(cells[at[key]]) for key in _FIELDS]
                rows.setdefault(name, []).append((time, *values))
        except (IndexError, ValueError):
            raise LoadError(
                "a row of the CSV log cannot be read", file=file, line=line_number
            ) from None
    traces = {name: _trace(values) for name, values in rows.items()}
    times = next(iter(traces.values())).times if traces else np.array([])
    step = float(np.median(np.diff(times))) if len(times) > 1 else None
    return traces, step


_FIELDS = (
    "World_Position_X [m]",
    "World_Position_Y [m]",
    "World_Heading_Angle [rad]",
    "Current_Speed [m/s]",
    "lane_id",
)


def _columns(header: list[str]) -> list[tuple[int, dict[str, int]]]:
    """For each actor block `#n`: the column of its name and of each field read."""
    blocks: dict[str, dict[str, int]] = {}
    for index, title in enumerate(header):
        if found := re.match(r"#(\d+) (.+)$", title):
            blocks.setdefault(found.group(1), {})[found.group(2).strip()] = index
    result = []
    for block in blocks.values():
        if "Entity_Name [-]" in block and all(key in block for key in _FIELDS):
            result.append((block["Entity_Name [-]"], block))
    return result


def _trace(values: list[tuple[float, ...]]) -> Trace:
    data = np.array(values, dtype=float)
    return Trace(
        data[:, 0], data[:, 1], data[:, 2], data[:, 3], data[:, 4], data[:, 5].astype(np.int64)
    )


def find(given: str | None = None) -> str | None:
    """The esmini binary: `given`, else $ESMINI, else `esmini` on the PATH; None if none."""
    candidate = given or os.environ.get("ESMINI") or shutil.which("esmini")
    return candidate if candidate and Path(candidate).is_file() else None


def play(esmini: str, xosc: Path, timestep: float = PLAYER_STEP) -> tuple[Path, Path]:
    """Run esmini headless on `xosc` (in its folder); the log and CSV files it wrote beside it."""
    log_path = xosc.with_suffix(".log.txt")
    csv_path = xosc.with_suffix(".csv")
    command = [
        esmini,
        "--headless",
        "--osc",
        xosc.name,
        "--fixed_timestep",
        str(timestep),
        "--logfile_path",
        log_path.name,
        "--csv_logger",
        csv_path.name,
    ]
    subprocess.run(
        command, cwd=xosc.parent, capture_output=True, check=False, timeout=WALL_LIMIT_SECONDS
    )
    return log_path, csv_path

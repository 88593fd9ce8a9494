"""Play SceML scenarios' OpenSCENARIO exports in esmini and check the runs against SPEC §3.

    python scripts/esmini_check.py SCENARIO.xmi [...] --esmini /path/to/esmini
        [--osc-version 1.0 --osc-version 1.3] [--timestep 0.05] [--keep DIR]

For each scenario and version: export (as `sceml export` does) into a temporary folder, run
esmini headless with a fixed time step, read the storyboard transitions from its log and check
them against the flattened scenario graph:

  (a) a node's events start only after its predecessors finished: all of them (ordinary nodes,
      JoinAllFinished), or the first one (JoinOneFinished);
  (b) every node finishes: its finish event ends (endTransition) before the storyboard stops;
  (c) the storyboard is stopped by the end node's trigger (its predecessors finished, per its
      join policy), not by the maximum-duration time-out.

It prints a per-node timeline and a verdict, and exits with 1 if any run breaks a rule, 2 on a
usage error. esmini is not built here: pass the binary of a build you have (or set $ESMINI).
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

import scemlmodel as scm
from sceml import graph, io
from sceml.export import build_xosc
from sceml.export.names import SEPARATOR
from sceml.modules import flatten

#: `[9.100] [info] X standbyState -> startTransition -> runningState`
TRANSITION = re.compile(
    r"^\[(\d+\.\d+)\] \[\w+\] (\S+) (\w+)State -> (\w+)Transition -> (\w+)State$"
)
#: Lines of the block esmini prints when a trigger fires.
TRIGGER_OPEN = re.compile(r"^\[(\d+\.\d+)\] \[\w+\] Trigger /-+$")
TRIGGER_GROUP = re.compile(r"^\[\d+\.\d+\] \[\w+\] Group (\d+):$")
TRIGGER_VALUE = re.compile(r"^\[\d+\.\d+\] \[\w+\] (\S+): (true|false)$")
VERSION = re.compile(r"esmini GIT REV: (\S+)")
DEFAULT_VERSIONS = ("1.0", "1.3")
#: Wall-clock limit of one esmini run; the scenario's own time limit ends it long before.
WALL_LIMIT_SECONDS = 600


@dataclass
class EventRun:
    """When one event started and when it ended of its own accord (None: it did not)."""

    start: float | None = None
    end: float | None = None


@dataclass
class PlayerLog:
    """What esmini's log says about one run."""

    events: dict[str, EventRun] = field(default_factory=dict)
    #: Time and transition ("stop" or "end") of the storyboard's completion, if it completed.
    stop_time: float | None = None
    stop_how: str | None = None
    #: The trigger block printed last before the storyboard stopped: groups of (name, value).
    stop_groups: list[list[tuple[str, bool]]] = field(default_factory=list)
    version: str = "unknown"


@dataclass
class NodeRun:
    """One node of the flattened graph, its times in the run and what is wrong with it."""

    name: str
    kind: str
    after: list[str]
    one: bool
    start: float | None
    finish: float | None
    problems: list[str] = field(default_factory=list)
    #: Unfinished at the stop, but the end node did not wait for it (SPEC §3: join-one).
    pending: bool = False


@dataclass
class RunReport:
    """The result of checking one scenario at one version."""

    scenario: str
    version: str
    nodes: list[NodeRun]
    ending: str
    stop_time: float | None
    problems: list[str]
    player: str

    @property
    def ok(self) -> bool:
        """Whether the run keeps every rule."""
        return not self.problems and not any(node.problems for node in self.nodes)


def parse_log(text: str) -> PlayerLog:
    """Event transitions, the storyboard's stop and the trigger block that stopped it."""
    log = PlayerLog()
    groups: list[list[tuple[str, bool]]] = []
    for line in text.splitlines():
        if found := VERSION.search(line):
            log.version = found.group(1)
        if TRIGGER_OPEN.match(line):
            groups = []
        elif found := TRIGGER_GROUP.match(line):
            groups.append([])
        elif (found := TRIGGER_VALUE.match(line)) and groups:
            groups[-1].append((found.group(1), found.group(2) == "true"))
        elif found := TRANSITION.match(line):
            _record(log, found, groups)
    return log


def _record(log: PlayerLog, found: re.Match[str], groups: list[list[tuple[str, bool]]]) -> None:
    time, element, before, transition, after = found.groups()
    if element == "storyBoard" and after == "complete" and log.stop_time is None:
        log.stop_time, log.stop_how, log.stop_groups = float(time), transition, groups
        return
    run = log.events.setdefault(element, EventRun())
    if before == "standby" and transition == "start" and run.start is None:
        run.start = float(time)
    # An event stopped with the storyboard (stopTransition) has not finished by itself.
    if after == "complete" and transition == "end" and run.end is None:
        run.end = float(time)


def _stop_trigger(tree: etree._ElementTree) -> tuple[list[list[str]], set[str]]:
    """The StopTrigger's groups of condition names, and the names of its time-out conditions."""
    groups, timeouts = [], set()
    for group in tree.getroot().iterfind("Storyboard/StopTrigger/ConditionGroup"):
        names = [str(condition.get("name")) for condition in group.iterfind("Condition")]
        groups.append(names)
        for condition in group.iterfind("Condition"):
            if condition.find(".//SimulationTimeCondition") is not None:
                timeouts.add(str(condition.get("name")))
    return groups, timeouts


def _events_by_node(tree: etree._ElementTree, first_events: Iterable[str]) -> dict[str, list[str]]:
    """Every Event of the document under the node it belongs to (`<node>__<suffix>`)."""
    owners = {first: first for first in first_events}
    events: dict[str, list[str]] = {first: [] for first in owners}
    for element in tree.getroot().iter("Event"):
        name = str(element.get("name"))
        owner = owners.get(name.split(SEPARATOR, 1)[0])
        if owner is not None:
            events[owner].append(name)
    return events


def _required(times: list[float | None], one: bool) -> float | None:
    """When the predecessors with these finish times have finished (None: not yet)."""
    known = [t for t in times if t is not None]
    if one:
        return min(known, default=None)
    return max(known) if len(known) == len(times) else None


def check_run(
    flat: scm.Scenario,
    tree: etree._ElementTree,
    events_of: dict[str, tuple[str, str]],
    log: PlayerLog,
) -> tuple[list[NodeRun], str, list[str]]:
    """Check a run's log against the flattened graph: node timeline, ending, run-level problems."""
    stop = log.stop_time
    events = _events_by_node(tree, (first for first, _ in events_of.values()))
    finish: dict[str, float | None] = {}
    runs: dict[str, NodeRun] = {}
    order, _ = graph.topological_order(flat)
    for node in order:
        name = str(node.name)
        if isinstance(node, scm.RootNode):
            finish[name] = 0.0
            continue
        if isinstance(node, scm.EndNode):
            continue
        first, finish_event = events_of[name]
        starts = [log.events.get(e, EventRun()).start for e in events[first]]
        end = log.events.get(finish_event, EventRun()).end
        finish[name] = end if end is not None and (stop is None or end <= stop) else None
        runs[name] = NodeRun(
            name=name,
            kind=node.eClass.name,
            after=[str(p.name) for p in graph.predecessors(node)],
            one=isinstance(node, scm.JoinOneFinished),
            start=min((s for s in starts if s is not None), default=None),
            finish=finish[name],
        )
        _check_order(runs[name], finish)
    end_node = graph.end_node(flat)
    assert end_node is not None
    needed = _needed(end_node, finish)
    for name, run in runs.items():
        if run.finish is None and name not in needed:
            run.pending = True
        elif run.finish is None:
            run.problems.append("never finished" if run.start is not None else "never started")
    ending, problems = _check_end(end_node, tree, log, finish)
    return list(runs.values()), ending, problems


def _needed(end: scm.EndNode, finish: dict[str, float | None]) -> set[str]:
    """Names of the nodes the end node waits for: every predecessor, except that a join-one
    (or a join-one end node) waits only for the predecessor that finished first."""
    needed: set[str] = set()
    stack: list[scm.GraphElement] = [end]
    while stack:
        node = stack.pop()
        before = [p for p in graph.predecessors(node) if not isinstance(p, scm.RootNode)]
        one = isinstance(node, scm.JoinOneFinished) or (
            isinstance(node, scm.EndNode) and node.policy is scm.JoinPolicy.joinOne
        )
        done = [p for p in before if finish.get(str(p.name)) is not None]
        if one and done:
            before = [min(done, key=lambda p: finish[str(p.name)] or 0.0)]
        for predecessor in before:
            if str(predecessor.name) not in needed:
                needed.add(str(predecessor.name))
                stack.append(predecessor)
    return needed


def _check_order(run: NodeRun, finish: dict[str, float | None]) -> None:
    ready = _required([finish[p] for p in run.after], run.one)
    if run.start is not None:
        if ready is None:
            waits = "any" if run.one else "all"
            run.problems.append(
                f"started at {run.start:.2f} s before {waits} of its predecessors finished"
            )
        elif run.start < ready:
            run.problems.append(
                f"started at {run.start:.2f} s, before its activation at {ready:.2f} s"
            )


def _check_end(
    end: scm.EndNode, tree: etree._ElementTree, log: PlayerLog, finish: dict[str, float | None]
) -> tuple[str, list[str]]:
    """How the storyboard stopped, and what is wrong with that."""
    if log.stop_time is None:
        return "did not stop", ["the storyboard never completed"]
    if log.stop_how != "stop":
        return f"{log.stop_how}Transition", [
            "the storyboard completed by itself, not by its StopTrigger"
        ]
    one = end.policy is scm.JoinPolicy.joinOne
    ready = _required([finish[str(p.name)] for p in graph.predecessors(end)], one)
    groups, timeouts = _stop_trigger(tree)
    fired = [names for names, (_, group) in zip(groups, _held(log), strict=False) if group]
    by_timeout = any(set(names) & timeouts for names in fired)
    by_end = any(not set(names) & timeouts for names in fired)
    at = f"{log.stop_time:.2f} s"
    if by_end or (not fired and ready is not None and not by_timeout):
        if ready is None or ready > log.stop_time:
            return f"end node at {at}", [
                "the StopTrigger fired before the end node's predecessors finished"
            ]
        return f"end node at {at}", []
    if by_timeout:
        return f"time-out at {at}", [
            "stopped by the maximum-duration time-out, not by the end node"
        ]
    return f"unknown at {at}", ["cannot tell from the log which StopTrigger group fired"]


def _held(log: PlayerLog) -> list[tuple[int, bool]]:
    """For each printed group of the stopping trigger: its index and whether all of it held."""
    return [
        (index, bool(group) and all(v for _, v in group))
        for index, group in enumerate(log.stop_groups)
    ]


def run_esmini(esmini: str, xosc: Path, timestep: float) -> str:
    """Run esmini headless on `xosc` (in its folder) and return its log text."""
    log_path = xosc.with_suffix(".log.txt")
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
        xosc.with_suffix(".csv").name,
    ]
    subprocess.run(
        command, cwd=xosc.parent, capture_output=True, check=False, timeout=WALL_LIMIT_SECONDS
    )
    return log_path.read_text(encoding="utf-8", errors="replace") if log_path.exists() else ""


def check_scenario(
    path: Path, version: str, esmini: str, timestep: float, folder: Path
) -> RunReport:
    """Export `path` at `version` into `folder`, play it and check the run."""
    scenario = io.load_scenario(path).root
    flat = (
        flatten(scenario) if any(isinstance(n, scm.ModuleUse) for n in scenario.nodes) else scenario
    )
    xosc = folder / f"{path.stem}-{version}.xosc"
    document = build_xosc(scenario, version=version, source_path=path, output_path=xosc)
    xosc.write_bytes(document.data)
    log = parse_log(run_esmini(esmini, xosc, timestep))
    nodes, ending, problems = check_run(flat, document.tree, document.events_of, log)
    return RunReport(path.name, version, nodes, ending, log.stop_time, problems, log.version)


def _time(value: float | None) -> str:
    return "-" if value is None else f"{value:.2f}"


def format_report(report: RunReport) -> str:
    """A readable per-node timeline and the verdict of one run."""
    width = max([len(n.name) for n in report.nodes] + [4])
    lines = [
        f"{report.scenario}, OpenSCENARIO {report.version} (esmini {report.player})",
        f"  {'node':<{width}}  {'kind':<16} {'start':>7} {'finish':>7}  after",
    ]
    for node in report.nodes:
        policy = "first of " if node.one else ""
        lines.append(
            f"  {node.name:<{width}}  {node.kind:<16} {_time(node.start):>7} "
            f"{_time(node.finish):>7}  {policy}{', '.join(node.after)}"
        )
        lines.extend(f"    ! {problem}" for problem in node.problems)
        if node.pending:
            lines.append("    (still pending at the stop; the end node does not wait for it)")
    lines.append(f"  storyboard stopped by {report.ending}")
    lines.extend(f"    ! {problem}" for problem in report.problems)
    count = len(report.problems) + sum(len(n.problems) for n in report.nodes)
    lines.append(f"  verdict: {'OK' if report.ok else f'{count} violation(s)'}")
    return "\n".join(lines)


def summary_line(report: RunReport) -> str:
    """One line for the table of runs."""
    count = len(report.problems) + sum(len(n.problems) for n in report.nodes)
    return f"{report.scenario:<34} {report.version}  {report.ending:<24} violations: {count}"


def find_esmini(given: str | None) -> str | None:
    """The esmini binary: the option, else $ESMINI, else `esmini` on the PATH."""
    candidate = given or os.environ.get("ESMINI") or shutil.which("esmini")
    return candidate if candidate and Path(candidate).is_file() else None


def parse_arguments(argv: list[str] | None) -> argparse.Namespace:
    """The command line."""
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0] if __doc__ else None,
        epilog="Exit status: 0 every run keeps SPEC §3, 1 a run breaks it, 2 usage error.",
    )
    parser.add_argument(
        "scenarios", nargs="+", type=Path, help="concrete SceML scenario files (.xmi)"
    )
    parser.add_argument(
        "--esmini", help="the esmini binary (default: $ESMINI, else esmini on the PATH)"
    )
    parser.add_argument(
        "--osc-version",
        action="append",
        dest="versions",
        choices=("1.0", "1.1", "1.2", "1.3"),
        help="OpenSCENARIO version to export; repeat for several (default: 1.0 and 1.3)",
    )
    parser.add_argument(
        "--timestep", type=float, default=0.05, help="esmini's fixed time step in s"
    )
    parser.add_argument(
        "--keep", type=Path, help="keep exports, logs and CSV traces in this folder"
    )
    parser.add_argument("--summary", action="store_true", help="print only one line per run")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    """Check every scenario at every version; 0 if all runs keep the rules, else 1."""
    arguments = parse_arguments(argv)
    esmini = find_esmini(arguments.esmini)
    if esmini is None:
        print("esmini not found: pass --esmini PATH or set $ESMINI", file=sys.stderr)
        return 2
    versions = arguments.versions or list(DEFAULT_VERSIONS)
    reports = []
    with tempfile.TemporaryDirectory(prefix="sceml-esmini-") as temporary:
        folder = arguments.keep or Path(temporary)
        folder.mkdir(parents=True, exist_ok=True)
        for path in arguments.scenarios:
            for version in versions:
                report = check_scenario(
                    path.resolve(), version, esmini, arguments.timestep, folder.resolve()
                )
                reports.append(report)
                if not arguments.summary:
                    print(format_report(report), end="\n\n")
    for report in reports:
        print(summary_line(report))
    return 0 if all(report.ok for report in reports) else 1


if __name__ == "__main__":
    sys.exit(main())

"""`sceml check-run`: whether a player's run of a scenario kept the scenario's meaning.

The scenario is exported again in memory (the export is deterministic, so this is the document
the player was given, at the version its log names) to know which events belong to which node;
the run is read by the reader of the player's formats (`READERS`).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import scemlmodel as scm

from ..errors import ArgumentError
from ..export import build_xosc
from ..maps import RoadMap, load_map
from ..maps.reference import map_reference
from ..model import graph
from ..model.loading import load_scenario
from ..modules import flatten
from ..xosc.profiles import DEFAULT_VERSION
from . import esmini
from .checker import RunReport, check_run
from .record import PlayerRun

#: Readers of each player's log and trace files: (log, trace or None) -> PlayerRun.
READERS: dict[str, Callable[[Path, Path | None], PlayerRun]] = {esmini.NAME: esmini.read}


def check_player_run(
    scenario_path: str | Path,
    log: str | Path,
    trace: str | Path | None = None,
    *,
    player: str = esmini.NAME,
    version: str | None = None,
    allow: tuple[Path, ...] = (),
) -> RunReport:
    """Check the run a player logged (`log`, and `trace` for goals and teleports) of the
    concrete scenario in `scenario_path`. The OpenSCENARIO version is `version`, else the one
    the log names, else 1.3."""
    reader = READERS.get(player)
    if reader is None:
        choices = ", ".join(sorted(READERS))
        raise ArgumentError(f"no reader for the player {player!r}; choose one of: {choices}")
    run = reader(Path(log), Path(trace) if trace is not None else None)
    return check_scenario_run(scenario_path, run, version=version, allow=allow)


def check_scenario_run(
    scenario_path: str | Path,
    run: PlayerRun,
    *,
    version: str | None = None,
    allow: tuple[Path, ...] = (),
) -> RunReport:
    """Check a run already read against the scenario in `scenario_path`."""
    path = Path(scenario_path)
    scenario = load_scenario(path, allow=allow).root
    chosen = version or run.osc_version or DEFAULT_VERSION
    document = build_xosc(scenario, version=chosen, source_path=path)
    flat = (
        flatten(scenario) if any(isinstance(n, scm.ModuleUse) for n in scenario.nodes) else scenario
    )
    run.osc_version = chosen
    return check_run(flat, document.tree, document.events_of, run, _road_map(flat, path), path.name)


def _road_map(flat: scm.Scenario, path: Path) -> RoadMap | None:
    root = graph.root_node(flat)
    reference = map_reference(root.map, path) if root is not None else None
    if reference is None or reference.path is None:
        return None
    return load_map(reference.path)


def _time(value: float | None) -> str:
    return "-" if value is None else f"{value:.2f}"


def format_report(report: RunReport) -> str:
    """A readable per-node timeline and the verdict of one run."""
    width = max([len(n.name) for n in report.nodes] + [4])
    lines = [
        f"{report.scenario}, OpenSCENARIO {report.osc_version}, played by {report.player}",
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
            lines.append("    (still running at the stop; the end node does not wait for it)")
    lines.append(f"  storyboard stopped by {report.ending}")
    lines.extend(f"    ! {problem}" for problem in report.problems)
    count = len(report.violations())
    verdict = "the run kept the scenario's meaning" if report.ok else f"{count} violation(s)"
    lines.append(f"  verdict: {verdict}")
    return "\n".join(lines)

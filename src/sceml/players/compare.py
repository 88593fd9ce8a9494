"""A preview run beside a player's run of the same scenario: node starts, positions, the end.

Both runs place an actor by its reference point, the centre of its box (`xosc.meaning`), so
positions compare directly. A node's start is its activation: in the preview the instant its
predecessors finished; in the player the start of its first event for maneuvers, joins and
ports, and for conditions (whose marker event starts only when the condition holds) the step
after the player found its predecessors finished.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..model import catalog
from ..simulate.run import Run
from ..xosc.meaning import FLOW_DELAY_STEPS
from .checker import RunReport, required
from .record import PlayerRun

#: What counts as agreeing (issue 25): node starts within this many seconds, positions within
#: this many metres.
START_AGREEMENT = 0.15
POSITION_AGREEMENT = 0.6


@dataclass(frozen=True)
class Comparison:
    """How far a preview run and a player's run of one scenario lie apart."""

    scenario: str
    worst_start: float
    worst_start_node: str
    worst_position: float
    worst_position_actor: str
    worst_position_time: float
    preview_end: str
    player_end: str
    #: How far apart the two runs stopped (s); infinite when one did not stop.
    end_apart: float

    @property
    def same_end(self) -> bool:
        """Both stopped the same way (end node or time limit) within the start agreement."""
        return self.preview_end == self.player_end and self.end_apart <= START_AGREEMENT + 1e-9

    @property
    def agrees(self) -> bool:
        return (
            self.worst_start <= START_AGREEMENT + 1e-9
            and self.worst_position <= POSITION_AGREEMENT
            and self.same_end
        )


def player_starts(report: RunReport, step: float) -> dict[str, float]:
    """Each node's activation in the player's run, by node name: a condition's is the step
    after its predecessors finished (`xosc.meaning.FLOW_DELAY_STEPS`), or the instant,
    after the root or a node written into the trigger (`xosc.flows`); an inlined node's is
    derived by the checker."""
    finishes = {node.name: node.finish for node in report.nodes}
    inline = {node.name for node in report.nodes if node.inlined}
    starts: dict[str, float] = {}
    for node in report.nodes:
        reached = []
        for name in node.after:
            # The root is no node of the report: it finished at 0, and a flow out of it
            # costs no step (`xosc.flows.flow_steps`), as none out of an inlined node does.
            root = name not in finishes
            done = 0.0 if root else finishes[name]
            steps = 0 if root or name in inline else FLOW_DELAY_STEPS
            reached.append(None if done is None else done + steps * step)
        ready = required(reached, node.one)
        if node.inlined and node.start is not None:
            starts[node.name] = node.start
        elif catalog.is_kind_of(node.kind, "Condition") and ready is not None:
            starts[node.name] = round(ready, 9)
        elif node.start is not None:
            starts[node.name] = node.start
    return starts


def compare(preview: Run, report: RunReport, run: PlayerRun) -> Comparison:
    """Compare the preview's run with the player's (its check report and trace)."""
    starts = player_starts(report, run.step)
    worst_start, worst_node = 0.0, "-"
    for record in preview.timeline:
        theirs = starts.get(record.name)
        if record.started is None or theirs is None:
            continue
        off = abs(record.started - theirs)
        if off > worst_start:
            worst_start, worst_node = off, record.name
    worst_position, worst_actor, worst_time = 0.0, "-", 0.0
    end = min(preview.end_time, run.stop_time if run.stop_time is not None else math.inf)
    for index, actor in enumerate(preview.actors):
        trace = run.traces.get(actor.name)
        if trace is None:
            continue
        keep = preview.times <= end + 1e-9
        times = preview.times[keep]
        xs = np.interp(times, trace.times, trace.x)
        ys = np.interp(times, trace.times, trace.y)
        off = np.hypot(preview.states[index, keep, 0] - xs, preview.states[index, keep, 1] - ys)
        if off.size and float(off.max()) > worst_position:
            k = int(np.argmax(off))
            worst_position, worst_actor, worst_time = float(off[k]), actor.name, float(times[k])
    return Comparison(
        report.scenario,
        worst_start,
        worst_node,
        worst_position,
        worst_actor,
        worst_time,
        preview.end_reason,
        "end node" if report.ending.startswith("end node") else "maximum duration",
        abs(preview.end_time - run.stop_time) if run.stop_time is not None else math.inf,
    )

"""`sceml check-run` on esmini runs recorded with esmini 3.6.0 (tests/players/data/README.md).

Expected times are worked out from the scenarios by hand: each flow costs esmini one step of
0.05 s, except a flow out of the root (the root's successors start at t = 0), a maneuver's own
time follows from its numbers. esmini stamps an action's completion with the start of the step
in which it completes: an action that acts from its first step and lasts T s ends at T - 0.05 s
after its start in the log (the trace reaches the goal at T).
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.players import esmini
from sceml.players.check import check_player_run

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "examples"
GOOD = [
    "overtaking-concrete-1.3",
    "uis2-concrete-1.0",
    "drive-after-moving-1.3",
    "turn-while-speeding-1.0",
    "follow-in-turn-1.3",
    "nested-1.3",
    "join-one-race-1.0",
    "parallel-1.3",
    "junction-1.3",
    "longitudinal-1.0",
    "stop-on-arrival-1.3",
    "stop-on-arrival-1.0",
    "interrupts-1.3",
    "follow-interrupted-1.3",
]


def model(stem: str) -> Path:
    """The scenario a recording played: `<name>[-before-issue-25]-<version>`."""
    name = stem.rsplit("-", 1)[0].removesuffix("-before-issue-25")
    if name.endswith("-concrete"):
        return EXAMPLES / f"{name}.xmi"
    return HERE / "scenarios" / f"{name}.xmi"


@pytest.mark.parametrize("stem", GOOD)
def test_runs_of_todays_exports_keep_the_meaning(stem: str, recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording(stem)
    report = check_player_run(model(stem), log, trace)
    assert report.ok, report.violations()
    assert report.ending.startswith("end node at")
    assert report.osc_version == stem.rsplit("-", 1)[1]


def test_drive_distance_after_moving_is_driven_from_the_nodes_start(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("drive-after-moving-1.3")
    report = check_player_run(model("drive-after-moving-1.3"), log, trace)
    nodes = {node.name: node for node in report.nodes}
    # KeepVelocity 3 s from 0 s; DriveDistance a step later, 20 m at 8 m/s: 2.5 s.
    assert nodes["KeepVelocity_1"].finish == pytest.approx(3.0)
    drive = nodes["DriveDistance_1"]
    assert (drive.start, drive.finish) == pytest.approx((3.05, 5.55))
    run = esmini.read(log, trace)
    ego = run.traces["ego"]
    i, j = ego.at(3.05), ego.at(5.55)
    assert ego.x[j] - ego.x[i] == pytest.approx(20.0, abs=0.5)  # a straight arm, along x


def test_a_condition_in_the_stop_trigger_ends_the_run_in_its_step(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("stop-on-arrival-1.3")
    report = check_player_run(model("stop-on-arrival-1.3"), log, trace)
    assert report.ok, report.violations()
    there = next(node for node in report.nodes if node.name == "InLocationRadius_1")
    # The ego drives from s = 5 at 10 m/s; within 2 m of s = 60 (strictly) from s > 58, after
    # 5.3 s: the first step after, 5.35 s. The condition stands in the StopTrigger (no event
    # of its own): it held when the run stopped, and the run stopped in that step, by the
    # end node (its group holds the root's `>= 0` too, which is no time-out).
    assert there.inlined
    assert (there.start, there.finish) == pytest.approx((0.0, 5.35))
    assert report.stop_time == pytest.approx(5.35)
    assert report.ending == "end node at 5.35 s"


def test_a_turn_no_longer_stops_the_speed_change_it_runs_beside(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("turn-while-speeding-1.0")
    report = check_player_run(model("turn-while-speeding-1.0"), log, trace)
    accelerate = next(node for node in report.nodes if node.name == "Accelerate_1")
    # 3 -> 9 m/s at 1 m/s2: 6 s from t = 0, acting from the first step; stamped a step early.
    assert accelerate.start == pytest.approx(0.0)
    assert accelerate.finish == pytest.approx(5.95)
    assert not esmini.read(log, trace).cut_short


def test_an_interrupted_maneuver_finishes_when_the_other_starts(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("interrupts-1.3")
    run = esmini.read(log, trace)
    # esmini ends the Accelerate at 2 s, when the Decelerate starts: a cut the check accepts,
    # since the Decelerate interrupts (release 1.5), and not its goal (15 m/s, never reached).
    assert [(cut.time, cut.event) for cut in run.cut_short] == [(2.0, "Accelerate_1")]
    report = check_player_run(model("interrupts-1.3"), log, trace)
    assert report.ok, report.violations()
    times = {node.name: (node.start, node.finish) for node in report.nodes}
    assert times["Accelerate_1"] == (pytest.approx(0.0), pytest.approx(2.0))
    assert times["Decelerate_1"][0] == pytest.approx(2.0)
    # The lane change after the Accelerate: a flow costs a step.
    assert times["LaneChange_1"][0] == pytest.approx(2.05)
    # 5 m/s + 2 s at 1 m/s2 = 7 m/s when it was ended, then down at 2 m/s2.
    ego = run.traces["ego"]
    assert float(ego.speed[ego.at(2.0)]) == pytest.approx(7.0, abs=0.11)
    assert float(ego.speed[ego.at(2.5)]) == pytest.approx(6.0, abs=0.11)


def test_an_interrupted_follow_counts_as_finished(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("follow-interrupted-1.3")
    report = check_player_run(model("follow-interrupted-1.3"), log, trace)
    assert report.ok, report.violations()
    times = {node.name: (node.start, node.finish) for node in report.nodes}
    # The Follow's gap (10 m) is never reached: 35 m apart, the ego brakes to 3 m/s at 2 s,
    # below the lead's 4 m/s. Its finish event sees the ended action's completion a step
    # later (2.05 s), and the lane change after it starts a step after that; the preview
    # starts it at 2.05 s (docs/openscenario-mapping.md).
    assert times["Follow_1"] == (pytest.approx(0.0), pytest.approx(2.05))
    assert times["LaneChange_1"][0] == pytest.approx(2.10)


def test_the_overtaking_example_overtakes_in_esmini(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("overtaking-concrete-1.3")
    run = esmini.read(log, trace)
    report = check_player_run(model("overtaking-concrete-1.3"), log, trace)
    back = next(n for n in report.nodes if n.name.endswith("ChangeLaneRight_1.LaneChange_1"))
    assert back.finish is not None
    ego, truck, oncoming = (run.traces[name] for name in ("ego", "truck", "oncoming"))
    k = ego.at(back.finish)
    # Back on its lane (centre y = -1.75) ahead of the truck, before the road's end at x = 109.
    assert ego.y[k] == pytest.approx(-1.75, abs=0.1)
    assert truck.x[truck.at(back.finish)] < ego.x[k] < 109.0
    # No contact: side by side the centres are a lane (3.5 m) apart; one behind the other more
    # than half of both lengths (4.5 / 2 + 9 / 2 = 6.75 m to the truck, 4.5 m to a car).
    assert np.min(np.hypot(ego.x - truck.x, ego.y - truck.y)) > 3.0
    assert np.min(np.hypot(ego.x - oncoming.x, ego.y - oncoming.y)) > 3.0


@pytest.mark.parametrize(
    ("stem", "violation"),
    [
        # TraveledDistanceCondition counted the 24 m driven before: it held at once.
        ("drive-after-moving-before-issue-25-1.3", "0.00 m were driven since its start, not 20 m"),
        # AcquirePositionAction took the longitudinal domain: the Accelerate ended at 3 m/s.
        ("turn-while-speeding-before-issue-25-1.3", "the speed was 3.00 m/s, not the target 9"),
        # The same for a Follow beside a turn, which esmini logged as stopped.
        ("follow-in-turn-before-issue-25-1.3", "cut short by the player at 0.05 s"),
    ],
)
def test_runs_of_the_old_exports_are_refused(stem: str, violation: str, recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording(stem)
    report = check_player_run(model(stem), log, trace)
    assert not report.ok
    assert any(violation in problem for problem in report.violations()), report.violations()


def test_a_jump_in_the_trace_is_a_teleport(recording) -> None:  # type: ignore[no-untyped-def]
    log, trace = recording("drive-after-moving-1.3")
    lines = trace.read_text().splitlines()
    # Move the ego 5 m ahead from t = 2.0 s on (row "40, 2.000000, ego, ...": x is column 14).
    edited = []
    for line in lines:
        cells = line.split(",")
        if len(cells) > 14 and cells[2].strip() == "ego" and float(cells[1]) >= 2.0:
            cells[13] = f" {float(cells[13]) + 5.0:.6f}"
        edited.append(",".join(cells))
    trace.write_text("\n".join(edited) + "\n")
    report = check_player_run(model("drive-after-moving-1.3"), log, trace)
    assert any("ego jumped 5.40 m at 2.00 s" in p for p in report.problems), report.problems


def test_the_command_says_whether_to_trust_a_run(recording) -> None:  # type: ignore[no-untyped-def]
    runner = CliRunner()
    log, trace = recording("nested-1.3")
    good = runner.invoke(
        cli, ["check-run", str(model("nested-1.3")), "--log", str(log), "--csv", str(trace)]
    )
    assert good.exit_code == 0, good.output
    assert "the run kept the scenario's meaning" in good.output
    log, trace = recording("drive-after-moving-before-issue-25-1.3")
    args = [
        "check-run",
        str(model("drive-after-moving-1.3")),
        "--log",
        str(log),
        "--csv",
        str(trace),
    ]
    bad = runner.invoke(cli, args)
    assert bad.exit_code == 1
    assert "DriveDistance_1" in bad.output and "1 violation(s)" in bad.output


def test_the_command_refuses_what_is_not_an_esmini_log(tmp_path: Path) -> None:
    log = tmp_path / "notes.txt"
    log.write_text("hello\n")
    result = CliRunner().invoke(cli, ["check-run", str(model("nested-1.3")), "--log", str(log)])
    assert result.exit_code == 2
    assert "not an esmini log" in result.output


def test_without_a_trace_only_the_timeline_is_checked(recording) -> None:  # type: ignore[no-untyped-def]
    log, _ = recording("drive-after-moving-before-issue-25-1.3")
    report = check_player_run(model("drive-after-moving-1.3"), log)
    assert report.ok  # the timeline alone looks right: only the trace shows 0 m driven
    # The old marker held at once (24.8 m driven since t = 0) at 3.10 s; Stop from 3.15 s,
    # 8 m/s at 4 m/s2 in 2 s acting from its first step: 5.10 s; the end a step later.
    assert math.isclose(report.stop_time or 0.0, 5.15)


def test_the_old_overtaking_stopped_dead_at_the_road_end_is_refused(
    recording, tmp_path: Path
) -> None:  # type: ignore[no-untyped-def]
    """Issue 25, 3: the Overtaking example of before (its files kept beside the recording) ran
    out of road in esmini with its lane change back half done; esmini stopped the ego dead."""
    examples = tmp_path / "examples"
    shutil.copytree(HERE / "data" / "overtaking-before-issue-25", examples)
    shutil.copytree(HERE.parent.parent / "maps", tmp_path / "maps")
    log, trace = recording("overtaking-concrete-before-issue-25-1.3")
    report = check_player_run(examples / "overtaking-concrete.xmi", log, trace)
    # The east arm ends at x = 109; the ego's centre was 0.85 m short of its lane's (y = -1.75).
    assert report.violations() == [
        "the player stopped ego dead at (109.0, -0.9) at 10.55 s from 11.0 m/s "
        "(the end of its road?): a maneuver cut short"
    ]

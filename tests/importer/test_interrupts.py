"""An event that overrides a running one (issue 24, "same run"; release 1.5's
`Maneuver.interrupts`): files/interrupts.xosc is written by hand, and files/interrupts.csv is
esmini 3.6's run of it (`--fixed_timestep 0.05 --csv_logger`), recorded by hand. esmini's log
of that run, read by hand: SpeedUp starts at 1.05 s; at 4.05 s Brake starts and esmini stops
SpeedUp ("on conflicting Longitudinal domain(s)"), whose event completes then, so Shift,
waiting for that, starts at 4.05 s too; Brake completes at 6.75 s, the run stops at 7.80 s.

Before release 1.5 the import made Brake wait for SpeedUp (SceML ran one speed maneuver of an
actor at a time), as in acc-test and alks-test, whose TargetBrake2Event started 7 s late."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.importer import import_file
from sceml.model import graph
from sceml.players.esmini import parse_csv
from sceml.simulate import simulate
from sceml.simulate.run import Run
from sceml.validation import validate
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "interrupts.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


def _node(scenario: scm.Scenario, name: str) -> scm.GraphElement:
    return next(n for n in scenario.nodes if n.name == name)


def _upstream(node: scm.GraphElement) -> set[str]:
    """The names of every node `node` waits for, directly or through others."""
    return {str(n.name) for n in graph.reachable(graph.predecessors(node), backwards=True)}


def test_the_brake_interrupts_the_speed_up_instead_of_waiting_for_it(
    imported: scm.Scenario,
) -> None:
    speed_up, brake = _node(imported, "SpeedUp"), _node(imported, "Brake")
    assert isinstance(speed_up, scm.Accelerate) and isinstance(brake, scm.Decelerate)
    # Either may start while the other runs, as far as the graph tells (two times): both
    # interrupt, as players run any two actions of one domain.
    assert brake.interrupts is True
    assert speed_up.interrupts is True
    assert "SpeedUp" not in _upstream(brake)
    assert "SpeedUp" in _upstream(_node(imported, "Shift"))
    assert _node(imported, "Shift").interrupts is False  # the only lateral maneuver


def test_the_interrupting_pair_passes_simultaneity(imported: scm.Scenario) -> None:
    codes = {d.code for d in validate(imported)}
    assert "SCEML-C001" not in codes
    # One interrupting is enough: it is meant to start while the other runs.
    _node(imported, "SpeedUp").interrupts = False
    try:
        assert "SCEML-C001" not in {d.code for d in validate(imported)}
        # Without the flag the two speed changes could run together: the rule says so.
        _node(imported, "Brake").interrupts = False
        assert "SCEML-C001" in {d.code for d in validate(imported)}
    finally:
        _node(imported, "SpeedUp").interrupts = True
        _node(imported, "Brake").interrupts = True


@pytest.mark.parametrize(("version", "priority"), [("1.1", "overwrite"), ("1.2", "override")])
def test_the_export_starts_the_brake_on_its_time_alone(
    imported: scm.Scenario, version: str, priority: str
) -> None:
    tree = build_xosc(imported, version=version, source_path=SOURCE).tree
    assert schema.validate_tree(tree, version) == []
    brake = tree.getroot().find(".//Event[@name='Brake']")
    assert brake is not None
    assert brake.get("priority") == priority
    assert not list(brake.iter("StoryboardElementStateCondition"))
    # The import read `SimulationTime > 4` as a wait of 4.05 s from the start (the step it
    # first holds); the export writes that wait as the delay of "the run has begun".
    (condition,) = brake.iterfind("StartTrigger/ConditionGroup/Condition")
    assert float(condition.get("delay")) == pytest.approx(4.05)
    assert condition.find(".//SimulationTimeCondition") is not None


def test_export_then_import_gives_the_same_scenario(
    imported: scm.Scenario, tmp_path: Path, same: object
) -> None:
    exported = tmp_path / "interrupts.xosc"
    exported.write_bytes(
        etree.tostring(build_xosc(imported, version="1.2", source_path=SOURCE).tree)
    )
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    again = import_file(exported).scenario
    assert _node(again, "Brake").interrupts is True
    # The file states no environment; the export writes the default one, which comes back.
    root = graph.root_node(again)
    assert root is not None and root.environment is not None
    root.environment = None
    same(imported, again)  # type: ignore[operator]


def test_the_preview_ends_the_speed_up_when_the_brake_starts(imported: scm.Scenario) -> None:
    run = simulate(imported, SOURCE)
    times = {record.name: record for record in run.timeline}
    # SimulationTime > 4 first holds at 4.05 s: Brake starts, SpeedUp ends then, not at
    # 11.05 s when it would have reached 30 m/s.
    assert times["SpeedUp"].finished == pytest.approx(4.05)
    assert times["SpeedUp"].note == "interrupted by Brake"
    assert times["Brake"].note == ""
    assert times["Brake"].started == pytest.approx(4.05)
    # Shift waits for SpeedUp to finish: one step after it ended.
    assert times["Shift"].started == pytest.approx(4.10)
    speed = _speeds(run, "Target")
    # 2 m/s2 from 1.05 s: 16 m/s at 4.05 s; then 4 m/s2 down: 15.8 m/s a step later, and
    # 5 m/s after (16 - 5) / 4 = 2.75 s, at 6.80 s.
    assert speed[4.05] == pytest.approx(16.0)
    assert speed[4.10] == pytest.approx(15.8)
    assert speed[6.80] == pytest.approx(5.0)
    assert max(v for t, v in speed.items() if t > 4.05) < 16.0


def test_the_preview_keeps_to_esmini_s_recorded_run(imported: scm.Scenario) -> None:
    traces, step = parse_csv((FILES / "interrupts.csv").read_text(), "interrupts.csv")
    assert step == pytest.approx(0.05)
    recorded = traces["Target"]
    run = simulate(imported, SOURCE)
    states = run.states[run.actor_index("Target")]
    for t, (x, _, _, speed) in zip(run.times, states, strict=True):
        k = recorded.at(float(t))
        # Within a step of either rate (0.1 and 0.2 m/s), and the 0.5 m issue 24 allows.
        assert speed == pytest.approx(float(recorded.speed[k]), abs=0.21)
        assert abs(x - float(recorded.x[k])) < 0.5


def _speeds(run: Run, actor: str) -> dict[float, float]:
    """The actor's speed at each sample, by its time rounded to the step."""
    states = run.states[run.actor_index(actor)]
    return {round(float(t), 2): float(s[3]) for t, s in zip(run.times, states, strict=True)}

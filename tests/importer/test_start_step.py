"""When the first events start (issue 24, "same run"): the root's successors start at t = 0, and
an original's `SimulationTime >= v` and `> v` keep the step between them through the round trip.

`files/start-step.xosc` is written by hand. esmini 3.6 (`--fixed_timestep 0.05`) starts its
events at AtZero 0.00 s, AfterZero 0.05 s, AtTwo 2.00 s, AfterTwo 2.05 s and InLater 8.05 s
(the act `Later` waits for `> 8`, its event for `> 0`), and its re-export at the same instants:
both read off esmini's logs by hand when this test was written. The tests need no esmini.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.importer import import_file
from sceml.model import graph
from sceml.simulate import simulate

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "start-step.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


def node(scenario: scm.Scenario, name: str) -> scm.GraphElement:
    return next(n for n in scenario.nodes if n.name == name)


def wait_before(scenario: scm.Scenario, name: str) -> float | None:
    """The TimeElapsed right after the root that the node waits for (None: the root itself)."""
    (before,) = graph.predecessors(node(scenario, name))
    if isinstance(before, scm.RootNode):
        return None
    assert isinstance(before, scm.TimeElapsed)
    assert graph.predecessors(before) == [graph.root_node(scenario)]
    return float(before.duration.value)


def test_greater_or_equal_holds_at_its_value_and_greater_a_step_later(
    imported: scm.Scenario,
) -> None:
    assert wait_before(imported, "AtZero") is None  # >= 0: with the root, at t = 0
    assert wait_before(imported, "AfterZero") == pytest.approx(0.05)
    assert wait_before(imported, "AtTwo") == pytest.approx(2.0)
    assert wait_before(imported, "AfterTwo") == pytest.approx(2.05)


def test_an_events_clock_that_holds_before_its_act_starts_waits_for_the_act(
    imported: scm.Scenario,
) -> None:
    # InLater's `> 0` holds long before its act starts at 8.05 s: it waits for the act's
    # start alone, no wait of 0.05 s. (It may start while AtZero, the Ego's speed change
    # before it, runs: it interrupts it, release 1.5; before, it also waited for it.)
    assert wait_before(imported, "InLater") == pytest.approx(8.05)
    assert node(imported, "InLater").interrupts is True


def start_conditions(document: etree._Element, event: str) -> list[tuple[str, str, str]]:
    """(value, rule, delay) of each SimulationTimeCondition in the event's StartTrigger."""
    found = document.find(f".//Event[@name='{event}']")
    assert found is not None, event
    return [
        (str(clock.get("value")), str(clock.get("rule")), str(condition.get("delay")))
        for condition in found.iterfind("StartTrigger/ConditionGroup/Condition")
        for clock in condition.iterfind("ByValueCondition/SimulationTimeCondition")
    ]


def test_the_export_writes_the_start_as_a_time_that_holds_at_zero(
    imported: scm.Scenario,
) -> None:
    document = build_xosc(imported, version="1.1", source_path=SOURCE).tree.getroot()
    assert start_conditions(document, "AtZero") == [("0.0", "greaterOrEqual", "0.0")]
    assert start_conditions(document, "AfterZero") == [("0.0", "greaterOrEqual", "0.05")]
    assert start_conditions(document, "AfterTwo") == [("0.0", "greaterOrEqual", "2.05")]
    # OpenSCENARIO 1.0 has no greaterOrEqual: a time above -1 holds from t = 0 as well.
    old = build_xosc(imported, version="1.0", source_path=SOURCE).tree.getroot()
    assert start_conditions(old, "AtZero") == [("-1.0", "greaterThan", "0.0")]


def test_the_preview_starts_them_when_esmini_does(imported: scm.Scenario) -> None:
    run = simulate(imported, SOURCE)
    starts = {n: run.node(n).started for n in ("AtZero", "AfterZero", "AtTwo", "AfterTwo")}
    assert starts == pytest.approx(
        {"AtZero": 0.0, "AfterZero": 0.05, "AtTwo": 2.0, "AfterTwo": 2.05}
    )
    assert run.node("InLater").started == pytest.approx(8.05)
    # 10 -> 20 m/s at 2 m/s²: 5 s from the start, acting from the step after it.
    assert run.node("AtZero").finished == pytest.approx(5.0)
    assert run.node("AfterTwo").finished == pytest.approx(7.05)


def test_an_edge_condition_at_the_start_keeps_its_edge_and_follows_the_root(tmp_path: Path) -> None:
    # An edge is a change between two evaluations, so it cannot hold at the first one (t = 0);
    # the node keeps the edge (release 1.3), which says so to the preview and the export, so no
    # wait of a step is put before it: Second's speed change waits for Second to become faster
    # than 5 m/s.
    text = SOURCE.read_text()
    old = (
        '<Condition name="AfterZeroWhen" delay="0" conditionEdge="none">\n'
        '                  <ByValueCondition><SimulationTimeCondition value="0" '
        'rule="greaterThan"/></ByValueCondition>'
    )
    assert old in text
    rising = (
        '<Condition name="AfterZeroWhen" delay="0" conditionEdge="rising">'
        '<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any">'
        '<EntityRef entityRef="Second"/></TriggeringEntities><EntityCondition>'
        '<SpeedCondition value="5" rule="greaterThan"/></EntityCondition></ByEntityCondition>'
    )
    path = tmp_path / "start-step.xosc"
    path.write_text(text.replace(old, rising))
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    scenario = import_file(path).scenario
    speed = next(n for n in scenario.nodes if isinstance(n, scm.SpeedCondition))
    assert graph.successors(speed) == [node(scenario, "AfterZero")]
    assert speed.edge == scm.ConditionEdge.rising
    assert graph.predecessors(speed) == [graph.root_node(scenario)]

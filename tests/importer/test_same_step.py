"""Triggers read from a file start their events in the same step after the round trip (issue 24,
"same run"): a condition the import makes a node is written back into the StartTrigger of the
event that waits for it (`xosc.flows.inlined`), not as a marker event a step before it.

`files/triggers-in-step.xosc` is written by hand; every expectation below is read off it."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc
from sceml.importer import import_file
from sceml.model import graph
from sceml.model.build import ScenarioBuilder, world

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "triggers-in-step.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


@pytest.fixture(scope="module")
def exported(imported: scm.Scenario) -> etree._Element:
    return build_xosc(imported, version="1.1", source_path=SOURCE).tree.getroot()


def event(document: etree._Element, name: str) -> etree._Element:
    found = document.find(f".//Event[@name='{name}']")
    assert found is not None, f"no event {name}"
    return found


def groups(element: etree._Element, trigger: str = "StartTrigger") -> list[list[str]]:
    """Each ConditionGroup as what its conditions test: `state:<event>`, `time>v+delay` (or
    `time>=v+delay`), the tag of an entity condition."""
    read = []
    for group in element.iterfind(f"{trigger}/ConditionGroup"):
        tests = []
        for condition in group.iterfind("Condition"):
            state = condition.find(".//StoryboardElementStateCondition")
            clock = condition.find(".//SimulationTimeCondition")
            if state is not None:
                tests.append(f"state:{state.get('storyboardElementRef')}")
            elif clock is not None:
                delay = float(condition.get("delay"))
                rule = ">=" if clock.get("rule") == "greaterOrEqual" else ">"
                tests.append(f"time{rule}{float(clock.get('value')):g}+{delay:g}")
            else:
                tests.append(condition.find(".//EntityCondition/*").tag)
        read.append(sorted(tests))
    return sorted(read)


def test_a_condition_with_a_state_is_in_the_events_own_trigger(exported: etree._Element) -> None:
    # Brake: SpeedUp completed AND the ego faster than 14 m/s, in one group, as in the file.
    assert groups(event(exported, "Brake")) == [["SpeedCondition", "state:SpeedUp"]]
    assert exported.find(".//Event[@name='Fast']") is None  # no marker event for it


def test_a_condition_alone_is_in_the_events_own_trigger(exported: etree._Element) -> None:
    # Cut: the lead within 30 m of the ego, from the act's start (`SimulationTime > 0`, which
    # first holds at 0.05 s, then a 1 s delay: written into the trigger of each event of the
    # act as a delay of 1.05 s from t = 0).
    assert groups(event(exported, "Cut")) == [["RelativeDistanceCondition", "time>=0+1.05"]]
    assert exported.find(".//Event[@name='Near']") is None


def test_a_second_lane_change_interrupts_the_first_and_keeps_its_condition(
    imported: scm.Scenario, exported: etree._Element
) -> None:
    # Back may start while Cut runs, and Cut while Back runs: both interrupt (release 1.5;
    # before, Back also waited for Cut), as players end a running lane change when another
    # starts. Back starts on its own condition, which stays in its trigger.
    close = next(n for n in imported.nodes if n.name == "Close")
    back = next(n for n in imported.nodes if n.name == "Back")
    cut = next(n for n in imported.nodes if n.name == "Cut")
    assert (back.interrupts, cut.interrupts) == (True, True)
    assert graph.predecessors(back) == [close]
    assert [str(p.name) for p in graph.predecessors(close)] == ["InStepAct_start_delay"]
    assert groups(event(exported, "Back")) == [["RelativeDistanceCondition", "time>=0+1.05"]]


def test_waits_in_a_row_add_up_in_one_trigger(exported: etree._Element) -> None:
    # The act waits a step and 1 s, SpeedUp 2 s after the act: 3.05 s after the start (as
    # esmini starts it), no event between.
    assert groups(event(exported, "SpeedUp")) == [["time>=0+3.05"]]
    assert exported.find(".//Event[@name='InStepAct_start_delay']") is None


def test_the_stop_trigger_names_its_conditions_groups_directly(exported: etree._Element) -> None:
    # Either distance (two groups, met in a join-one that is written into the StopTrigger), or
    # the time limit, as the file has it. The branches the StopTrigger does not name reach the
    # end joined with it; their groups test all a distance group tests and more, so they are
    # left out.
    stop = exported.find("Storyboard")
    assert groups(stop, "StopTrigger") == [["state:EgoFar"], ["state:LeadFar"], ["time>60+0"]]
    assert exported.find(".//Event[@name='stop_holds']") is None
    assert exported.find(".//Event[@name='stop_time']") is None


def test_an_init_speed_relative_to_another_actor_is_its_initial_speed(
    imported: scm.Scenario,
) -> None:
    lead = next(a for a in graph.actors(imported) if a.name == "Lead")
    assert float(lead.initialSpeed.value) == 10.0  # the ego's 12 m/s less 2


def test_an_action_named_within_its_event_is_that_events(tmp_path: Path) -> None:
    # Both lane changes' actions called `Action` (as `cut-in_cr` names them), the StopTrigger's
    # first group waiting for `Back::Action`: the end waits for Back, not for the first
    # action of that name (Cut's).
    document = etree.parse(str(SOURCE))
    for action in document.iter("Action"):
        if action.get("name") in ("CutAction", "BackAction"):
            action.set("name", "Action")
    far = document.find(".//StopTrigger/ConditionGroup/Condition[@name='EgoFar']")
    far.clear()
    far.attrib.update({"name": "BackDone", "delay": "0", "conditionEdge": "none"})
    value = etree.SubElement(far, "ByValueCondition")
    etree.SubElement(
        value,
        "StoryboardElementStateCondition",
        storyboardElementType="action",
        storyboardElementRef="Back::Action",
        state="endTransition",
    )
    path = tmp_path / "qualified.xosc"
    document.write(str(path))
    (tmp_path / "highway.xodr").write_bytes((FILES / "highway.xodr").read_bytes())
    scenario = import_file(path).scenario
    end = graph.end_node(scenario)
    stops = [p for p in graph.predecessors(end) if p.name == "stop_holds"]
    assert len(stops) == 1
    assert sorted(str(p.name) for p in graph.predecessors(stops[0])) == ["Back", "LeadFar"]


def test_a_wait_before_a_keep_velocity_comes_back_as_a_wait(tmp_path: Path) -> None:
    # root -> TimeElapsed 1 s -> KeepVelocity 2 s -> end: the wait is a delay in the
    # KeepVelocity's StartTrigger, and must not be read as a second KeepVelocity.
    b = ScenarioBuilder("kv", map="map.xodr", level="concrete", max_duration=20.0)
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0, h=0.0), speed=5.0)
    wait = b.add("TimeElapsed", ego, duration=1.0)
    keep = b.add("KeepVelocity", ego, duration=2.0)
    b.chain(b.root, wait, keep, b.end)
    path = tmp_path / "kv.xosc"
    path.write_bytes(build_xosc(b.scenario, version="1.3").data)
    kinds = sorted(n.eClass.name for n in import_file(path).scenario.nodes)
    assert kinds == ["EndNode", "KeepVelocity", "RootNode", "TimeElapsed"]

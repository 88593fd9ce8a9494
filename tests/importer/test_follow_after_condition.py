"""A condition in front of a Follow costs no step (issue 24, `long_dist_action_with_jerk`):
files/follow-when-close.xosc starts the ego's Follow once the ego is within 40 m of the lead.
The import makes the condition a node before the Follow; the export writes it into the
Follow's own StartTrigger (the Follow's finish marker waits for the Follow's event to have
started, not for the condition again), so no marker event sits between them.

Worked by hand from the file: the ego (20 m/s, s = 30) closes on the lead (12 m/s, s = 94) at
8 m/s, so the gap of 64 m is 40 m at 3.0 s. esmini 3.6 starts EgoFollows at 3.00 s in the
original and in this re-export; with the condition as a marker event, at 3.05 s, and the
preview said 3.05 s too."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.simulate import simulate
from sceml.xosc import schema
from sceml.xosc.flows import flow_steps, inlined

FILE = Path(__file__).parent / "files" / "follow-when-close.xosc"


def test_the_condition_costs_the_follow_no_step() -> None:
    scenario = import_file(FILE).scenario
    nodes = {str(n.name): n for n in scenario.nodes}
    (flow,) = nodes["EgoFollows"].incoming
    assert flow.source is nodes["Close"]
    inline = inlined(scenario.nodes)
    assert nodes["Close"] in inline
    assert flow_steps(nodes["Close"], inline) == 0


@pytest.mark.parametrize("version", ("1.1", "1.2", "1.3"))
def test_the_condition_is_in_the_follows_trigger(
    version: str, tmp_path: Path, same: Callable[[scm.Scenario, scm.Scenario], None]
) -> None:
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version=version, source_path=FILE)
    assert schema.validate_file(exported, version) == []
    document = etree.parse(str(exported)).getroot()
    names = sorted(str(e.get("name")) for e in document.iter("Event"))
    assert names == ["EgoFollows", "EgoFollows__gap_reached"]
    tests = document.findall(
        ".//Event[@name='EgoFollows']/StartTrigger/ConditionGroup/Condition"
        "/ByEntityCondition/EntityCondition/RelativeDistanceCondition"
    )
    assert [(t.get("value"), t.get("rule")) for t in tests] == [("40.0", "lessOrEqual")]
    marker = document.find(".//Event[@name='EgoFollows__gap_reached']/StartTrigger")
    assert marker is not None
    assert marker.find(".//RelativeDistanceCondition") is None  # not the condition again
    states = {
        (c.get("storyboardElementRef"), c.get("state"))
        for c in marker.iter("StoryboardElementStateCondition")
    }
    assert states == {("EgoFollows", "runningState"), ("EgoFollows", "completeState")}
    first.nodes[0].environment = scm.Environment()  # the export's default environment
    same(first, import_file(exported, allow=[FILE.parent]).scenario)


def test_the_preview_starts_the_follow_when_close() -> None:
    run = simulate(import_file(FILE).scenario, FILE)
    assert run.node("EgoFollows").started == pytest.approx(3.0)

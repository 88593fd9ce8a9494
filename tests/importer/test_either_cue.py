"""A trigger of two ConditionGroups goes back as two groups (issue 24, the light events of
esmini's LightStateManeuvers catalog, `auto_light`): files/either-cue.xosc brakes once the ego
has driven 300 m or is within 5 m of s = 100. The import makes them a join-one of two
conditions; the export writes each into the brake's own trigger as a group of its own, so the
brake starts in the step one holds, not a step later after a marker event.

Worked by hand from the file: the ego drives at 10 m/s from s = 50, so it is closer than 5 m
to s = 100 from 4.5 s on, first at 4.55 s (long before 300 m). esmini 3.6 starts Brake at
4.55 s in the original and in this re-export (at 4.60 s with the conditions as markers)."""

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

FILE = Path(__file__).parent / "files" / "either-cue.xosc"


def test_the_groups_meet_in_a_join_one() -> None:
    nodes = {str(n.name): n for n in import_file(FILE).scenario.nodes}
    (flow,) = nodes["Brake"].incoming
    assert isinstance(flow.source, scm.JoinOneFinished)
    kinds = sorted(str(f.source.eClass.name) for f in flow.source.incoming)
    assert kinds == ["InLocationRadius", "TraveledDistance"]


@pytest.mark.parametrize("version", ("1.1", "1.3"))
def test_each_group_is_in_the_brakes_trigger(
    version: str, tmp_path: Path, same: Callable[[scm.Scenario, scm.Scenario], None]
) -> None:
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version=version, source_path=FILE)
    assert schema.validate_file(exported, version) == []
    document = etree.parse(str(exported)).getroot()
    assert sorted(str(e.get("name")) for e in document.iter("Event")) == ["Brake"]
    groups = document.findall(".//Event[@name='Brake']/StartTrigger/ConditionGroup")
    tests = sorted(
        tag
        for group in groups
        for tag in (c.tag for c in group.iterfind("Condition/ByEntityCondition/EntityCondition/*"))
    )
    assert len(groups) == 2
    assert tests[-1] == "TraveledDistanceCondition"  # and the mark: Reach... or Distance...
    first.nodes[0].environment = scm.Environment()  # the export's default environment
    same(first, import_file(exported, allow=[FILE.parent]).scenario)


def test_the_preview_brakes_at_the_mark() -> None:
    # In the step the radius holds, no step later: the preview counts exactly 5 m (at 4.5 s)
    # as within the radius, where esmini's `lessThan` waits for the next step.
    run = simulate(import_file(FILE).scenario, FILE)
    assert run.node("Brake").started == pytest.approx(4.5)

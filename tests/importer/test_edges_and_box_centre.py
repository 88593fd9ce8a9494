"""Release 1.3's box centre and condition edges: a BoundingBox Center x other than 0 imports as
`Actor.boxCenterX` and a conditionEdge as `Condition.edge`; both export back at every version
(XSD-valid) and import again to the same scenario, and the preview honours them.

The times below were read by hand from esmini 3.6's log of `files/edges-and-box-centre.xosc`
(--fixed_timestep 0.05), which plays the original and its re-export alike: Lead's speed falls
past 10 m/s at 3.55 s, Ego's free space to Lead falls below 15 m at 7.65 s (7.75 s with the box
centred on the reference point, as the export wrote it before release 1.3).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.render.labels import Scope, parameter_items
from sceml.simulate import simulate
from sceml.simulate.conditions import on_edge
from sceml.xosc import schema

SOURCE = Path(__file__).parent / "files" / "edges-and-box-centre.xosc"
#: The step the preview runs at.
STEP = 0.05


def _node(scenario: scm.Scenario, name: str) -> scm.ActionNode:
    return next(n for n in scenario.nodes if n.name == name)


def _edges(path: Path) -> dict[str, str]:
    """Each Condition's conditionEdge, by condition name, where it is not none."""
    return {
        str(c.get("name")): str(c.get("conditionEdge"))
        for c in etree.parse(str(path)).iter("Condition")
        if c.get("conditionEdge") != "none"
    }


def _centres(path: Path) -> dict[str, str]:
    return {
        str(o.get("name")): str(o.find(".//BoundingBox/Center").get("x"))
        for o in etree.parse(str(path)).iter("ScenarioObject")
    }


def test_the_box_centre_and_the_edges_import_onto_the_model() -> None:
    imported = import_file(SOURCE)
    assert imported.report.counts()["opaque"] == 0
    actors = {a.name: a for a in graph.root_node(imported.scenario).actors}
    assert actors["Ego"].boxCenterX.value == 1.25
    assert actors["Lead"].boxCenterX is None  # Center x = 0: the default, left unset
    scenario = imported.scenario
    assert _node(scenario, "LeadNoLongerFast").edge == scm.ConditionEdge.falling
    assert _node(scenario, "TurnsGreen").edge == scm.ConditionEdge.rising
    assert _node(scenario, "CloseToLead").edge == scm.ConditionEdge.none


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_they_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    model = tmp_path / "edges.xmi"
    import_to_file(SOURCE, model)
    exported = tmp_path / "edges.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    assert _edges(SOURCE) == {"LeadNoLongerFast": "falling", "TurnsGreen": "rising"}
    assert _edges(exported) == _edges(SOURCE)
    assert {k: float(v) for k, v in _centres(exported).items()} == {
        "Ego": 1.25,
        "Lead": 0.0,
        "Follower": 0.0,
    }
    first, again = import_file(SOURCE).scenario, import_file(exported).scenario
    for scenario in (first, again):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first, again)


def test_the_preview_waits_for_the_edge() -> None:
    scenario = import_file(SOURCE).scenario
    run = simulate(scenario, SOURCE)
    # esmini: 3.55 s; the preview sees the speed reach 10 m/s within a step of it.
    falling = run.node("LeadNoLongerFast").finished
    assert falling is not None and 3.55 <= falling <= 3.55 + STEP + 1e-9
    rising = run.node("TurnsGreen").finished
    assert rising is not None and falling < rising <= falling + 2 * STEP + 1e-9
    # Without its edge the same condition holds at once: Lead starts at 15 m/s.
    _node(scenario, "LeadNoLongerFast").edge = scm.ConditionEdge.none
    assert simulate(scenario, SOURCE).node("LeadNoLongerFast").finished == pytest.approx(STEP)


def test_the_preview_measures_free_space_from_the_box_where_it_is() -> None:
    scenario = import_file(SOURCE).scenario
    assert simulate(scenario, SOURCE).node("CloseToLead").finished == pytest.approx(7.65)
    for actor in graph.root_node(scenario).actors:
        actor.boxCenterX = None
    assert simulate(scenario, SOURCE).node("CloseToLead").finished == pytest.approx(7.75)


@pytest.mark.parametrize(
    ("edge", "values", "holds"),
    [
        ("rising", [True, True, False, True], [False, False, False, True]),
        ("rising", [False, True, True], [False, True, False]),
        ("falling", [True, False, False, True, False], [False, True, False, False, True]),
        ("risingOrFalling", [False, True, False], [False, True, True]),
    ],
)
def test_an_edge_holds_on_a_change_never_at_the_first_evaluation(
    edge: str, values: list[bool], holds: list[bool]
) -> None:
    answers = iter(values)
    test = on_edge(lambda _world: next(answers), edge)
    assert [test(None) for _ in values] == holds  # type: ignore[arg-type]


def test_a_label_shows_an_edge_other_than_none() -> None:
    scenario = import_file(SOURCE).scenario
    rising = dict(parameter_items(_node(scenario, "TurnsGreen"), Scope()))
    assert rising["edge"] == "rising"
    assert "edge" not in dict(parameter_items(_node(scenario, "CloseToLead"), Scope()))

"""A destination beyond the next junction (two-tees.xodr: straight on at junction 7, left at
junction 8). esmini 3.6 routes an AcquirePositionAction there through both junctions (checked
by hand: the car is within 2 m of the destination at 23.6 s); SceML's TurnLeft to it validates
(SCEML-R006 no longer wants it beyond the next junction only: `routing-test`), the preview
drives the same way and arrives at the same step, and the export plays it back the same.

A turn that starts where an Init route has brought the car (route-then-turn.xosc, as
`routing-test`) is written as a route from there, not from the car's start: `routing-test`'s
re-export (its 15 m/s2 stop at esmini's 10) played 480 m off with the route from its start, the
same as the original with the route from where it turns (both checked by hand with esmini 3.6;
on this map both routes happen to lead the same way)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.simulate import simulate
from sceml.validation import validate

FILES = Path(__file__).parent / "files"
TWO_JUNCTIONS = FILES / "route-two-junctions.xosc"
ROUTE_THEN_TURN = FILES / "route-then-turn.xosc"


def _turn(scenario: scm.Scenario) -> scm.RoutedManeuver:
    (turn,) = [n for n in scenario.nodes if isinstance(n, scm.RoutedManeuver)]
    return turn


def _beside_its_map(folder: Path) -> Path:
    """The scenario and its map copied into `folder`, where validation may read the map."""
    shutil.copy(FILES / "two-tees.xodr", folder)
    shutil.copy(TWO_JUNCTIONS, folder)
    shutil.copytree(FILES / "catalogs", folder / "catalogs")
    return folder / TWO_JUNCTIONS.name


def _errors(path: Path) -> list[str]:
    document = load(path)
    found = validate(document.root, document=document)
    return [f"{d.code} {d.message}" for d in found if d.severity is Severity.ERROR]


def test_a_left_turn_two_junctions_away_validates(tmp_path: Path) -> None:
    out = tmp_path / "two.xmi"
    imported = import_to_file(_beside_its_map(tmp_path), out)
    turn = _turn(imported.scenario)
    assert turn.eClass.name == "TurnLeft"
    assert (turn.destination.roadId, turn.destination.laneId) == ("34", -1)
    assert _errors(out) == []


def test_a_right_turn_there_is_refused_naming_the_way(tmp_path: Path) -> None:
    source = _beside_its_map(tmp_path)
    imported = import_file(source)
    left = _turn(imported.scenario)
    right = scm.TurnRight(name=left.name, referenceActor=left.referenceActor)
    right.destination = left.destination
    for flow in [*left.incoming, *left.outgoing]:
        if flow.target is left:
            flow.target = right
        else:
            flow.source = right
    imported.scenario.nodes.remove(left)
    imported.scenario.nodes.append(right)
    out = tmp_path / "right.xmi"
    save(imported.scenario, out, origin=source)
    (error,) = _errors(out)
    assert error == (
        "SCEML-R006 GoNorth: the way to the destination from road 30, lane -1 is straight on "
        "at junction 7, then a left turn at junction 8, with no right turn"
    )


def test_the_preview_turns_at_the_second_junction_and_arrives_when_esmini_does() -> None:
    run = simulate(import_file(TWO_JUNCTIONS).scenario, TWO_JUNCTIONS)
    (turn,) = [n for n in run.timeline if n.kind == "TurnLeft"]
    # 10 m/s from x = -80 on the west arm: 23.6 s in esmini 3.6, within 2 m of (116.75, 45).
    assert turn.finished == pytest.approx(23.6)
    x, y, heading, _ = run.states[run.actor_index("Ego"), -1]
    assert (x, heading) == pytest.approx((116.75, 1.5707963))
    assert 43.0 <= y <= 45.0


def test_the_export_routes_to_the_same_destination(tmp_path: Path, same) -> None:
    first = import_file(TWO_JUNCTIONS)
    exported = tmp_path / "two.xosc"
    export_to_file(first.scenario, exported, version="1.1", source_path=TWO_JUNCTIONS)
    again = import_file(exported, allow=[FILES]).scenario
    for scenario in (first.scenario, again):
        graph.root_node(scenario).environment = None
    same(first.scenario, again)


def test_a_turn_after_the_init_route_is_routed_from_where_the_car_is(tmp_path: Path) -> None:
    exported = tmp_path / "then.xosc"
    first = import_file(ROUTE_THEN_TURN).scenario
    export_to_file(first, exported, version="1.1", source_path=ROUTE_THEN_TURN)
    tree = etree.parse(str(exported))
    (event,) = [e for e in tree.iter("Event") if e.get("name") == "GoNorth"]
    places = [w.find("Position/LanePosition") for w in event.iter("Waypoint")]
    # The reach position it waited for (road 32, past junction 7), then the destination.
    assert [(p.get("roadId"), p.get("laneId"), p.get("s")) for p in places] == [
        ("32", "-1", "50.0"),
        ("34", "-1", "30.0"),
    ]


@pytest.mark.xfail(
    strict=True,
    reason="the Init route is kept as an opaque node and written back as a story event at "
    "t = 0 (esmini plays it as the Init action); read again, that story AssignRouteAction "
    "becomes a Cross to its last waypoint, a straight trajectory on export (docs/import.md)",
)
def test_an_init_route_survives_a_second_round_trip(tmp_path: Path, same) -> None:
    exported = tmp_path / "then.xosc"
    first = import_file(ROUTE_THEN_TURN).scenario
    export_to_file(first, exported, version="1.1", source_path=ROUTE_THEN_TURN)
    again = import_file(exported, allow=[FILES]).scenario
    for scenario in (first, again):
        graph.root_node(scenario).environment = None
    same(first, again)


def test_the_preview_turns_where_the_init_route_has_brought_the_car() -> None:
    run = simulate(import_file(ROUTE_THEN_TURN).scenario, ROUTE_THEN_TURN)
    (turn,) = [n for n in run.timeline if n.kind == "TurnLeft"]
    # esmini 3.6: the reach position holds at 12.85 s (the preview: 12.8 s, at exactly 2 m),
    # the destination is reached at 23.6 s. The turn starts in the step its condition holds:
    # the condition is written into the turn's own trigger (an arrival's marker waits for the
    # turn's start, `xosc.flows`); before, it kept a marker event, a step later, and the
    # preview's 12.8 + 0.05 s happened to match esmini's 12.85 s.
    assert (turn.started, turn.finished) == pytest.approx((12.8, 23.6))

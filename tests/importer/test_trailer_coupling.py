"""Trailers coupled in the story (release 1.5): OpenSCENARIO 1.3's ConnectTrailerAction and
DisconnectTrailerAction import as ConnectTrailer (the trailer its target actor) and
DisconnectTrailer, export back at 1.3 as written (earlier versions refuse them) and import again
to the same scenario; the preview tows the trailer while it is coupled.

The places below were worked out by hand for `files/trailer-connect.xosc` (road 1 of
highway.xodr runs along x at y = 0; lane -1's centre is y = -1.75): Trailer's reference point
is Car's less the hitch's 1.2 m and the coupler's 3.25 m, 4.45 m behind. The preview starts a
node's delay in the step after the node finishes (Couple at 1 s: DriveOff's 1 s from 1.10 s
to 2.10 s), so Car speeds up at 2 m/s² from 2.10 s and reaches 10 m/s at 7.10 s: at 8 s it is
at 50 + 25 + 10 × 0.9 = 84. Uncouple acts at 4.15 s, when the last drag gave Trailer Car's
speed at 4.10 s, 2 × 2 = 4 m/s, and Car stood at 50 + 4 = 54, Trailer at 49.55; Trailer then
rolls on at 4 m/s: 49.55 + 4 × 3.9 = 65.15 at 8 s. esmini 3.6 (--fixed_timestep 0.05) runs the
file with its speed change a step earlier: Car at 84.75 and Trailer at 65.45 at 8 s, the
trailer rolling on at 4 m/s.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import ExportError, export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.simulate import simulate
from sceml.validation import validate
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "trailer-connect.xosc"


def _trailer_actions(path: Path) -> list[tuple[str, dict[str, str]]]:
    """Each TrailerAction's child: its tag and attributes, in document order."""
    return [
        (str(child.tag), dict(child.attrib))
        for action in etree.parse(str(path)).iter("TrailerAction")
        for child in action
    ]


def test_trailer_actions_import_as_coupling_nodes() -> None:
    imported = import_file(SOURCE)
    assert imported.report.counts()["opaque"] == 0
    nodes = {str(n.name): n for n in imported.scenario.nodes}
    couple, uncouple = nodes["Couple"], nodes["Uncouple"]
    assert isinstance(couple, scm.ConnectTrailer) and isinstance(uncouple, scm.DisconnectTrailer)
    assert (couple.referenceActor.name, couple.targetActor.name) == ("Car", "Trailer")
    assert (uncouple.referenceActor.name, uncouple.targetActor) == ("Car", None)
    assert [d.code for d in validate(imported.scenario) if d.severity.name == "ERROR"] == []


def test_they_export_at_1_3_as_they_were_read(tmp_path: Path, same) -> None:
    first = import_file(SOURCE)
    exported = tmp_path / "coupling.xosc"
    export_to_file(first.scenario, exported, version="1.3", source_path=SOURCE)
    assert schema.validate_file(exported, "1.3") == []
    assert (
        _trailer_actions(exported)
        == _trailer_actions(SOURCE)
        == [
            ("ConnectTrailerAction", {"trailerRef": "Trailer"}),
            ("DisconnectTrailerAction", {}),
        ]
    )
    again = import_file(exported, allow=[FILES])
    for scenario in (first.scenario, again.scenario):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first.scenario, again.scenario)


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2"))
def test_earlier_versions_refuse_them(version: str, tmp_path: Path) -> None:
    with pytest.raises(ExportError) as refused:
        export_to_file(import_file(SOURCE).scenario, tmp_path / "c.xosc", version=version)
    said = str(refused.value.diagnostics)
    assert "ConnectTrailer needs OpenSCENARIO 1.3" in said
    assert "DisconnectTrailer needs OpenSCENARIO 1.3" in said
    assert not (tmp_path / "c.xosc").exists()


def _x(run, name: str, t: float) -> float:
    return float(run.states[run.actor_index(name), int(np.argmin(np.abs(run.times - t))), 0])


def test_the_preview_tows_the_trailer_while_coupled() -> None:
    run = simulate(import_file(SOURCE).scenario, SOURCE)
    for t in (0.0, 1.0, 2.0, 3.0, 4.1):
        assert _x(run, "Car", t) - _x(run, "Trailer", t) == pytest.approx(4.45, abs=1e-6), t
    assert _x(run, "Car", 4.1) == pytest.approx(54.0, abs=1e-6)
    assert _x(run, "Car", 8.0) == pytest.approx(84.0, abs=1e-6)
    assert _x(run, "Trailer", 8.0) == pytest.approx(65.15, abs=1e-6)
    trailer = run.states[run.actor_index("Trailer")]
    rolling = run.times >= 4.2
    assert np.allclose(trailer[rolling, 3], 4.0) and np.allclose(trailer[:, 1], -1.75)
    # Coupled, the trailer's box lies against the car's: no metrics for the pair.
    with pytest.raises(KeyError):
        run.pair("Car", "Trailer")


def test_a_trailer_away_from_the_hitch_is_drawn_to_it_when_coupled(tmp_path: Path) -> None:
    moved = tmp_path / "away.xosc"
    moved.write_text(
        SOURCE.read_text(encoding="utf-8").replace('s="45.55"', 's="40"'), encoding="utf-8"
    )
    shutil.copy(FILES / "highway.xodr", tmp_path)
    run = simulate(import_file(moved).scenario, moved)
    assert _x(run, "Trailer", 1.0) == pytest.approx(40.0)
    # Coupled at 1 s: from the next drag on, the coupler is at the hitch (esmini: the same).
    assert _x(run, "Trailer", 1.1) == pytest.approx(45.55, abs=1e-6)


def test_an_uncoupled_trailer_without_roads_stops_where_it_stands(tmp_path: Path) -> None:
    # No map: esmini cannot move a trailer along a road there and stops it (trailer_connect).
    scenario = import_file(SOURCE).scenario
    graph.root_node(scenario).map = None
    for actor in graph.root_node(scenario).actors:
        pose = actor.startPosition
        actor.startPosition = scm.WorldPosition(
            x=scm.Value(value=float(pose.s.value)), y=scm.Value(value=-1.75), h=scm.Value(value=0.0)
        )
    run = simulate(scenario)
    trailer = run.states[run.actor_index("Trailer")]
    assert np.allclose(trailer[run.times >= 4.2, 3], 0.0)
    assert _x(run, "Trailer", 8.0) == pytest.approx(49.55, abs=1e-6)


def test_an_init_coupling_acts_right_after_the_root(tmp_path: Path) -> None:
    # esmini couples in Init at the start: a ConnectTrailer right after the root, as an Init
    # light is a LightState there.
    tree = etree.parse(str(SOURCE))
    init_car = next(p for p in tree.iter("Private") if p.get("entityRef") == "Car")
    coupling = etree.SubElement(etree.SubElement(init_car, "PrivateAction"), "TrailerAction")
    etree.SubElement(coupling, "ConnectTrailerAction", trailerRef="Trailer")
    moved = tmp_path / "init.xosc"
    tree.write(str(moved))
    shutil.copy(FILES / "highway.xodr", tmp_path)
    imported = import_file(moved)
    assert imported.report.counts()["opaque"] == 0
    root = graph.root_node(imported.scenario)
    first = [
        n
        for n in imported.scenario.nodes
        if isinstance(n, scm.ConnectTrailer) and n.name != "Couple"
    ]
    assert len(first) == 1 and [f.source for f in first[0].incoming] == [root]
    assert first[0].targetActor.name == "Trailer"

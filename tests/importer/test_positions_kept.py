"""Positions keep their OpenSCENARIO kind: Road and the four relative positions import as the
same kind and export back as the same element at every version, in Init, as a destination and
in a condition."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model.loading import load
from sceml.xosc import schema

FILES = Path(__file__).resolve().parent / "files"
VERSIONS = ("1.0", "1.1", "1.2", "1.3")
KEPT = (
    "RoadPosition",
    "RelativeLanePosition",
    "RelativeRoadPosition",
    "RelativeObjectPosition",
    "RelativeWorldPosition",
)


def positions(path: Path) -> list[tuple[str, str, tuple[tuple[str, str], ...]]]:
    """Each position of a file's storyboard that is not a world or lane position: whose it is
    (the Private's or ManeuverGroup's entity), its kind and its attributes (numbers as floats,
    orientation included), sorted."""
    found = []
    for element in etree.parse(str(path)).iter(*KEPT):
        if _own_start(element):
            continue
        owner = next(
            (a for a in element.iterancestors() if a.tag in ("Private", "ManeuverGroup")), None
        )
        entity = _entity(owner)
        attributes = {key: _number(key, value) for key, value in element.attrib.items()}
        for orientation in element.iter("Orientation"):
            attributes |= {f"orientation.{k}": _number(k, v) for k, v in orientation.attrib.items()}
        found.append((entity, element.tag, tuple(sorted(attributes.items()))))
    return sorted(found)


def _own_start(element: etree._Element) -> bool:
    """The first vertex of a Cross's polyline: the actor where it is (SceML's export writes it)."""
    parent = element.getparent()
    return (
        parent is not None
        and parent.getparent() is not None
        and parent.getparent().tag == "Vertex"
        and element.get("dx") == element.get("dy") == "0.0"
        and element.get("dz") is None
    )


def _entity(owner: etree._Element | None) -> str:
    if owner is None:
        return ""
    named = owner if owner.tag == "Private" else owner.find("Actors/EntityRef")
    return "" if named is None else str(named.get("entityRef"))


def _number(key: str, text: str) -> str:
    """Numbers compared as numbers (`50` is `50.0`); ids and types as written."""
    return text if key in ("roadId", "type", "entityRef") else repr(float(text))


def test_road_positions_import_as_road_positions() -> None:
    imported = import_file(FILES / "road-positions.xosc")
    starts = {a.name: a.startPosition for a in imported.scenario.nodes[0].actors}
    ego, lead = starts["Ego"], starts["Lead"]
    assert isinstance(ego, scm.RoadPosition) and isinstance(lead, scm.RoadPosition)
    assert (ego.roadId, ego.s.value, ego.t.value, ego.h) == ("1", 50.0, -5.5, None)
    assert (lead.s.value, lead.t.value, lead.h.value) == (90.0, -1.75, 0.05)
    drive = next(n for n in imported.scenario.nodes if getattr(n, "destination", None) is not None)
    assert isinstance(drive.destination, scm.RoadPosition)
    assert (drive.destination.s.value, drive.destination.t.value) == (400.0, -5.25)
    assert imported.report.counts()["opaque"] == 0


@pytest.mark.parametrize("version", VERSIONS)
def test_road_positions_export_back_as_they_were(version: str, tmp_path: Path) -> None:
    model = tmp_path / "road-positions.xmi"
    import_to_file(FILES / "road-positions.xosc", model)
    exported = tmp_path / "road-positions.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    original = positions(FILES / "road-positions.xosc")
    again = positions(exported)
    # The export also writes the destination into the condition that waits for the arrival.
    assert sorted(set(again)) == original
    assert ("Ego", "RoadPosition", (("roadId", "1"), ("s", "400.0"), ("t", "-5.25"))) in again
    assert (
        "Lead",
        "RoadPosition",
        (
            ("orientation.h", "0.05"),
            ("orientation.type", "relative"),
            ("roadId", "1"),
            ("s", "90.0"),
            ("t", "-1.75"),
        ),
    ) in again


def test_relative_positions_import_naming_their_entity() -> None:
    imported = import_file(FILES / "relative-positions.xosc")
    actors = {a.name: a for a in imported.scenario.nodes[0].actors}
    lead, side, behind = (actors[n].startPosition for n in ("Lead", "Side", "Behind"))
    assert isinstance(lead, scm.RelativeLanePosition) and lead.entity is actors["Ego"]
    assert (lead.dLane, lead.ds.value, lead.offset.value) == (1, 30.0, 0.25)
    assert isinstance(side, scm.RelativeRoadPosition)
    assert (side.ds.value, side.dt.value) == (-10.0, -3.5)
    assert isinstance(behind, scm.RelativeObjectPosition) and behind.h.value == 0.0
    drive = next(n for n in imported.scenario.nodes if n.name == "DriveThere")
    assert isinstance(drive.destination, scm.RelativeWorldPosition)
    assert drive.destination.entity is actors["Lead"]
    near = next(n for n in imported.scenario.nodes if n.name == "NearLead")
    assert isinstance(near.position, scm.RelativeObjectPosition)
    assert (near.position.dx.value, near.position.dy.value) == (-40.0, -3.5)
    assert imported.report.counts()["opaque"] == 0


@pytest.mark.parametrize("version", VERSIONS)
def test_relative_positions_export_back_as_they_were(version: str, tmp_path: Path) -> None:
    model = tmp_path / "relative-positions.xmi"
    import_to_file(FILES / "relative-positions.xosc", model)
    exported = tmp_path / "relative-positions.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    original, again = positions(FILES / "relative-positions.xosc"), positions(exported)
    # The export writes dz="0" where the original left it to its default, and each destination
    # twice (the action and the condition that waits for the arrival).
    written = {
        (who, tag, tuple(a for a in attributes if a != ("dz", "0.0")))
        for who, tag, attributes in again
    }
    assert sorted(written) == original

"""Trailers (release 1.4): a vehicle's TrailerHitch, TrailerCoupler and Trailer import as
`Actor.hitchX`, `couplerX` and `trailer`; a trailer written in place becomes an actor named as
esmini names it (`Car+`); they export back at 1.3 (earlier versions have no trailer: SCEML-E008)
and import again to the same scenario; the preview drags each trailer behind its hitch.

The places below were worked out by hand for `files/trailers.xosc` and agree with esmini 3.6's
run of it (--fixed_timestep 0.05): Car+'s reference point is Car's, less the hitch's 1.2 m and
the coupler's 3.25 m, 4.45 m behind (45.55 at 0 s); Semi's is Tractor's + 1 - 7, 6 m behind (94
at 0 s, whatever its own start says: 30). Car speeds up from 10 to 15 m/s at 2 m/s² from 1 s:
at 6 s it is at 50 + 10 + 31.25 + 37.5 = 128.75 (esmini: 128.875, its speed a step ahead) and
Car+ at 124.3 (124.425); Tractor at 8 m/s is at 148 and Semi at 142 (esmini: the same).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.render.labels import root_lines
from sceml.render.mapscene import build_scene
from sceml.simulate import simulate
from sceml.validation import validate
from sceml.xosc import schema

SOURCE = Path(__file__).parent / "files" / "trailers.xosc"


def _actors(scenario: scm.Scenario) -> dict[str, scm.Actor]:
    return {str(a.name): a for a in graph.root_node(scenario).actors}


def _couplings(path: Path) -> dict[str, tuple[str | None, str | None, str | None]]:
    """Each Vehicle's (hitch dx, coupler dx, what it tows: `ref:Name` or `inline`), by the name
    of the ScenarioObject or Trailer that holds it."""
    found = {}
    for holder in etree.parse(str(path)).iter("ScenarioObject", "Trailer"):
        vehicle = holder.find("Vehicle")
        if vehicle is None:
            continue
        hitch, coupler = vehicle.find("TrailerHitch"), vehicle.find("TrailerCoupler")
        trailer = vehicle.find("Trailer")
        towed = None
        if trailer is not None:
            ref = trailer.find("TrailerRef")
            towed = f"ref:{ref.get('entityRef')}" if ref is not None else "inline"
        found[str(holder.get("name"))] = (
            None if hitch is None else str(float(str(hitch.get("dx")))),
            None if coupler is None else str(float(str(coupler.get("dx")))),
            towed,
        )
    return found


def test_trailers_import_onto_the_actors() -> None:
    imported = import_file(SOURCE)
    actors = _actors(imported.scenario)
    assert list(actors) == ["Car", "Car+", "Semi", "Tractor"]
    assert actors["Car"].trailer is actors["Car+"] and actors["Tractor"].trailer is actors["Semi"]
    assert actors["Car"].hitchX.value == -1.2 and actors["Car+"].couplerX.value == 3.25
    assert actors["Tractor"].hitchX.value == 1.0 and actors["Semi"].couplerX.value == 7.0
    assert actors["Car+"].startPosition is None  # it starts at the hitch
    assert actors["Semi"].startPosition is not None
    assert [d.code for d in validate(imported.scenario) if d.severity.name == "ERROR"] == []


def test_they_export_at_1_3_as_they_were_read(tmp_path: Path, same) -> None:
    model = tmp_path / "trailers.xmi"
    import_to_file(SOURCE, model)
    exported = tmp_path / "trailers.xosc"
    export_to_file(load(model).root, exported, version="1.3", source_path=model)
    assert schema.validate_file(exported, "1.3") == []
    assert _couplings(SOURCE) == {
        "Car": ("-1.2", None, "inline"),
        "car_trailer": (None, "3.25", None),
        "Semi": (None, "7.0", None),
        "Tractor": ("1.0", None, "ref:Semi"),
    }
    written = _couplings(exported)
    assert written.pop("Car_2") == (None, "3.25", None)  # in place: players name it Car+
    assert written == {k: v for k, v in _couplings(SOURCE).items() if k != "car_trailer"}
    # A trailer written in place has no Init of its own and no ManeuverGroup.
    refs = {str(e.get("entityRef")) for e in etree.parse(str(exported)).iter("Private")}
    assert refs == {"Car", "Semi", "Tractor"}
    first, again = import_file(SOURCE).scenario, import_file(exported).scenario
    for scenario in (first, again):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first, again)
    assert (
        _towing(again)
        == _towing(first)
        == {
            "Car": ("Car+", -1.2, None),
            "Car+": (None, None, 3.25),
            "Semi": (None, None, 7.0),
            "Tractor": ("Semi", 1.0, None),
        }
    )


def _towing(scenario: scm.Scenario) -> dict[str, tuple[str | None, float | None, float | None]]:
    """Each actor's (trailer, hitch, coupler): `same` compares the nodes, not the actors."""
    return {
        name: (
            None if actor.trailer is None else str(actor.trailer.name),
            None if actor.hitchX is None else actor.hitchX.value,
            None if actor.couplerX is None else actor.couplerX.value,
        )
        for name, actor in _actors(scenario).items()
    }


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2"))
def test_earlier_versions_refuse_a_trailer(version: str) -> None:
    scenario = import_file(SOURCE).scenario
    found = {
        (d.code, d.message.split("'")[1])
        for d in validate(scenario, osc_version=version)
        if d.code == "SCEML-E008"
    }
    assert found == {("SCEML-E008", "Car"), ("SCEML-E008", "Tractor")}


def test_an_earlier_file_with_trailers_says_its_export_needs_1_3(tmp_path: Path) -> None:
    """esmini's catalogs give trailers to 1.1 files (its `trailers.xosc`): the entry is read."""
    tree = etree.parse(str(SOURCE))
    car = tree.find("Entities/ScenarioObject[@name='Car']")
    vehicle = car.find("Vehicle")
    catalog = etree.fromstring(
        '<OpenSCENARIO><FileHeader revMajor="1" revMinor="3" date="2026-11-26T12:00:00" '
        'description="vehicles" author="SceML tests"/><Catalog name="VehicleCatalog"/>'
        "</OpenSCENARIO>"
    )
    catalog.find("Catalog").append(vehicle)
    (tmp_path / "Vehicles").mkdir()
    etree.ElementTree(catalog).write(str(tmp_path / "Vehicles" / "VehicleCatalog.xosc"))
    etree.SubElement(car, "CatalogReference", catalogName="VehicleCatalog", entryName="car")
    for name in ("Semi", "Tractor"):  # 1.1 has no trailer elements in place
        tree.find(f"Entities/ScenarioObject[@name='{name}']").getparent().remove(
            tree.find(f"Entities/ScenarioObject[@name='{name}']")
        )
    for private in tree.iter("Private"):
        if private.get("entityRef") != "Car":
            private.getparent().remove(private)
    tree.find("FileHeader").set("revMinor", "1")
    locations = tree.find("CatalogLocations")
    etree.SubElement(etree.SubElement(locations, "VehicleCatalog"), "Directory", path="Vehicles")
    older = tmp_path / "trailers-1.1.xosc"
    tree.write(str(older))
    (tmp_path / "highway.xodr").write_bytes((SOURCE.parent / "highway.xodr").read_bytes())
    imported = import_file(older)
    assert (imported.report.version, imported.report.needs_version) == ("1.1", "1.3")
    assert _actors(imported.scenario)["Car"].trailer.name == "Car+"


def test_the_preview_drags_each_trailer_behind_its_hitch() -> None:
    run = simulate(import_file(SOURCE).scenario, SOURCE)

    def x(name: str, t: float) -> float:
        row = run.states[run.actor_index(name), int(np.argmin(np.abs(run.times - t)))]
        return float(row[0])

    assert x("Car+", 0.0) == pytest.approx(45.55)
    assert x("Semi", 0.0) == pytest.approx(94.0)  # at the hitch, not at its own start (30)
    assert x("Car", 6.0) == pytest.approx(128.75, abs=1e-6)
    assert x("Car+", 6.0) == pytest.approx(124.3, abs=1e-6)
    assert x("Semi", 6.0) == pytest.approx(142.0, abs=1e-6)
    semi = run.states[run.actor_index("Semi")]
    assert np.allclose(semi[:, 1], -5.25) and np.allclose(semi[:, 3], 8.0)
    # A semi-trailer's box lies under its tractor's by design: no metrics, no collision.
    with pytest.raises(KeyError):
        run.pair("Semi", "Tractor")
    assert not run.collided and run.pair("Car", "Semi").min_distance > 5.0


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda a: setattr(a["Car"], "trailer", a["Car"]), "tows itself"),
        (lambda a: setattr(a["Semi"], "trailer", a["Tractor"]), "in a loop"),
        (lambda a: setattr(a["Car+"], "trailer", a["Semi"]), "towed by 2 actors"),
    ],
)
def test_towing_forms_chains(change, message: str) -> None:
    scenario = import_file(SOURCE).scenario
    assert not [d for d in validate(scenario) if d.code == "SCEML-A009"]
    change(_actors(scenario))
    found = [d.message for d in validate(scenario) if d.code == "SCEML-A009"]
    assert found and all(message in text for text in found), found


def test_a_towed_actor_needs_no_start_but_others_do() -> None:
    scenario = import_file(SOURCE).scenario
    actors = _actors(scenario)
    actors["Car"].trailer = None  # Car+ is towed by nobody now, and has no start
    found = [d.message for d in validate(scenario) if d.code == "SCEML-E002"]
    assert found == ["actor 'Car+' has no start position (concrete scenario)"]


def test_a_towed_entity_is_declared_before_its_tower(tmp_path: Path) -> None:
    """esmini reads a TrailerRef as it reads the entities: `Failed to find object Semi` (exit
    255, esmini 3.6) when Semi comes after Tractor. The export puts it first."""
    scenario = import_file(SOURCE).scenario
    root = graph.root_node(scenario)
    semi = _actors(scenario)["Semi"]
    root.actors.remove(semi)
    root.actors.append(semi)  # now after its tower
    exported = tmp_path / "trailers.xosc"
    export_to_file(scenario, exported, version="1.3", source_path=SOURCE)
    names = [str(o.get("name")) for o in etree.parse(str(exported)).iter("ScenarioObject")]
    assert names == ["Car", "Semi", "Tractor"]


def test_a_trailer_is_never_guessed_to_be_the_ego(tmp_path: Path) -> None:
    tree = etree.parse(str(SOURCE))
    entities = tree.find("Entities")
    semi = entities.find("ScenarioObject[@name='Semi']")
    entities.remove(semi)
    entities.insert(0, semi)  # the first vehicle is now a trailer
    first = tmp_path / "trailer-first.xosc"
    tree.write(str(first))
    (tmp_path / "highway.xodr").write_bytes((SOURCE.parent / "highway.xodr").read_bytes())
    egos = [a.name for a in graph.root_node(import_file(first).scenario).actors if a.isEgo]
    assert egos == ["Car"]


def test_the_map_view_draws_each_trailer_at_its_hitch() -> None:
    scene = build_scene(import_file(SOURCE).scenario, SOURCE)
    places = {mark.name: mark.place for mark in scene.actors}
    assert all(place is not None for place in places.values()), scene.notes
    assert (places["Car+"].centre.x, places["Car+"].centre.y) == pytest.approx((45.55, -1.75))
    assert (places["Semi"].centre.x, places["Semi"].centre.y) == pytest.approx((94.0, -5.25))


def test_the_root_box_says_who_tows_whom() -> None:
    scenario = import_file(SOURCE).scenario
    lines = root_lines(graph.root_node(scenario), scenario)
    assert "  Car: Car, ego, tows Car+" in lines and "  Tractor: Truck, tows Semi" in lines
    assert "  Semi: Truck" in lines  # towed, tows nothing


@pytest.mark.parametrize(("version", "hitches"), [("1.1", 0), ("1.3", 2)])
def test_a_hitch_with_nothing_towed_is_written_only_where_the_version_has_one(
    version: str, hitches: int, tmp_path: Path
) -> None:
    """esmini's catalog cars all have a TrailerHitch and an empty TrailerRef (cut-in.xosc's
    car_white): such a 1.1 file exports back as 1.1, without the hitch it cannot say."""
    scenario = import_file(SOURCE).scenario
    actors = _actors(scenario)
    graph.root_node(scenario).actors.remove(actors["Car+"])
    actors["Car"].trailer = actors["Tractor"].trailer = None
    assert actors["Car"].hitchX is not None
    exported = tmp_path / "hitches.xosc"
    export_to_file(scenario, exported, version=version, source_path=SOURCE)
    assert schema.validate_file(exported, version) == []
    assert sum(1 for _ in etree.parse(str(exported)).iter("TrailerHitch")) == hitches

"""Vehicles read from catalog entries (release 1.5): `files/catalog-references.xosc` imports
with `RootNode.vehicleCatalog` = "catalogs" and each entity's entry as `Actor.catalogEntry`,
and exports back with CatalogLocations (relative to the output) and the same references.

Worked out by hand from `files/catalogs/VehicleCatalog.xosc`: car_white says Center x 1.4,
5.04 x 2.0 x 1.5 m, maxSpeed $MaxSpeed (69), 10 and 10 m/s2; truck_yellow says Center x 2.5,
12 x 2.5 x 3.5 m, 30 m/s, 3 and 8 m/s2, none of them parameters. So Ego is car_white as it is,
Lead is car_white with MaxSpeed 40 (the file's assignment), Truck is truck_yellow; a Truck
2 m longer cannot be said by truck_yellow (length is no parameter of it), and is written in
place with a warning (SCEML-A011).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.validation import validate
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "catalog-references.xosc"


def _actors(scenario: scm.Scenario) -> dict[str, scm.Actor]:
    return {str(a.name): a for a in graph.root_node(scenario).actors}


def _entities(path: Path) -> dict[str, tuple[str, ...]]:
    """Each ScenarioObject as written: its reference (catalog, entry, assignments), or `inline`."""
    found: dict[str, tuple[str, ...]] = {}
    for item in etree.parse(str(path)).iter("ScenarioObject"):
        reference = item.find("CatalogReference")
        if reference is None:
            found[str(item.get("name"))] = ("inline",)
            continue
        found[str(item.get("name"))] = (
            str(reference.get("catalogName")),
            str(reference.get("entryName")),
            *(
                f"{a.get('parameterRef')}={float(str(a.get('value')))}"
                for a in reference.iter("ParameterAssignment")
            ),
        )
    return found


def _directory(path: Path) -> str | None:
    directory = etree.parse(str(path)).find("CatalogLocations/VehicleCatalog/Directory")
    return None if directory is None else str(directory.get("path"))


def test_the_import_keeps_the_folder_and_each_actors_entry() -> None:
    scenario = import_file(SOURCE).scenario
    assert graph.root_node(scenario).vehicleCatalog == "catalogs"
    entries = {name: actor.catalogEntry for name, actor in _actors(scenario).items()}
    assert entries == {
        "Ego": "car_white",
        "Lead": "car_white",
        "Truck": "truck_yellow",
        "Bike": None,
    }
    # Lead's assignment is its own top speed (its entry's 69 m/s otherwise).
    assert _actors(scenario)["Lead"].maxSpeed.value == 40.0


@pytest.mark.parametrize("version", ("1.0", "1.2", "1.3"))
def test_it_exports_back_as_the_same_references(version: str, tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / "out" / "again.xosc"
    exported.parent.mkdir()
    export_to_file(first, exported, version=version, source_path=SOURCE)
    assert schema.validate_file(exported, version) == []
    # The original's entities, as the original writes them (Bike in place).
    assert (
        _entities(exported)
        == _entities(SOURCE)
        == {
            "Ego": ("VehicleCatalog", "car_white"),
            "Lead": ("VehicleCatalog", "car_white", "MaxSpeed=40.0"),
            "Truck": ("VehicleCatalog", "truck_yellow"),
            "Bike": ("inline",),
        }
    )
    # Relative to the output, so that a player finds it from there.
    expected = os.path.relpath(FILES / "catalogs", exported.parent)
    assert _directory(exported) == Path(expected).as_posix()
    assert (exported.parent / str(_directory(exported))).resolve() == (FILES / "catalogs").resolve()
    again = import_file(exported, allow=[FILES]).scenario
    graph.root_node(first).environment = None  # the export writes the default one
    graph.root_node(again).environment = None
    same(first, again)
    assert {n: a.catalogEntry for n, a in _actors(again).items()} == {
        n: a.catalogEntry for n, a in _actors(first).items()
    }


def test_the_saved_model_names_the_folder_from_where_it_is(tmp_path: Path) -> None:
    model = tmp_path / "deeper" / "model.xmi"
    model.parent.mkdir()
    import_to_file(SOURCE, model)
    root = graph.root_node(load(model, allow=[FILES]).root)
    assert root.vehicleCatalog == Path(os.path.relpath(FILES / "catalogs", model.parent)).as_posix()
    assert (model.parent / root.vehicleCatalog).resolve() == (FILES / "catalogs").resolve()


def _saved(tmp_path: Path, change) -> tuple[Path, scm.Scenario]:  # type: ignore[no-untyped-def]
    scenario = import_file(SOURCE).scenario
    change(scenario)
    model = tmp_path / "model.xmi"
    save(scenario, model, origin=SOURCE)
    return model, load(model, allow=[FILES]).root


def _a011(model: Path, scenario: scm.Scenario) -> list[str]:
    document = load(model, allow=[FILES])
    return [d.message for d in validate(document.root, document=document) if d.code == "SCEML-A011"]


def test_values_the_entry_cannot_say_are_written_in_place_with_a_warning(tmp_path: Path) -> None:
    def longer(scenario: scm.Scenario) -> None:
        _actors(scenario)["Truck"].length = scm.Value(value=14.0)

    model, scenario = _saved(tmp_path, longer)
    [message] = _a011(model, scenario)
    assert message.startswith("actor 'Truck': catalog entry 'truck_yellow' in ")
    assert "cannot say length 14.0 (the entry says 12.0)" in message
    exported = tmp_path / "longer.xosc"
    export_to_file(load(model, allow=[FILES]).root, exported, source_path=model)
    assert _entities(exported)["Truck"] == ("inline",)
    assert _entities(exported)["Ego"] == ("VehicleCatalog", "car_white")
    truck = etree.parse(str(exported)).find("Entities/ScenarioObject[@name='Truck']/Vehicle")
    assert truck is not None and truck.find("BoundingBox/Dimensions").get("length") == "14.0"


def test_a_missing_entry_or_folder_is_a_warning_naming_them(tmp_path: Path) -> None:
    def unknown(scenario: scm.Scenario) -> None:
        _actors(scenario)["Ego"].catalogEntry = "car_blue"

    model, scenario = _saved(tmp_path, unknown)
    assert _a011(model, scenario) == [
        f"actor 'Ego': catalog entry 'car_blue': no catalog file in "
        f"{tmp_path / graph.root_node(scenario).vehicleCatalog} has a Vehicle of that name; "
        "exported in place"
    ]

    def nowhere(scenario: scm.Scenario) -> None:
        graph.root_node(scenario).vehicleCatalog = None

    model, scenario = _saved(tmp_path, nowhere)
    assert sorted(_a011(model, scenario)) == [
        f"actor '{name}': catalog entry '{entry}', but the root node names no vehicleCatalog; "
        "exported in place"
        for name, entry in (("Ego", "car_white"), ("Lead", "car_white"), ("Truck", "truck_yellow"))
    ]


def test_a_folder_outside_the_allowed_ones_is_not_read(tmp_path: Path) -> None:
    scenario = import_file(SOURCE).scenario
    model = tmp_path / "model.xmi"
    save(scenario, model, origin=SOURCE)
    document = load(model)  # no --allow: only tmp_path (and its project root) may be read
    messages = [
        d.message for d in validate(document.root, document=document) if d.code == "SCEML-A011"
    ]
    assert len(messages) == 3
    assert all("is outside the folders files may be read from" in m for m in messages), messages
    exported = tmp_path / "outside.xosc"
    export_to_file(document.root, exported, source_path=model)
    assert set(_entities(exported).values()) == {("inline",)}
    assert _directory(exported) is None

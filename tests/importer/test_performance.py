"""A vehicle's own Performance (release 1.4): `files/performance.xosc`'s Vehicles import as
`Actor.maxSpeed`, `maxAcceleration`, `maxDeceleration` where they differ from the kind's usual
(SceML's export table), export back as they were read, and hold the preview as esmini holds them.

Worked out by hand: Ego states 25 m/s ($EgoTop), 4 m/s2 and 10 m/s2 (a car's usual, so unset);
Lead is catalog car_white with MaxSpeed assigned 50 (10 and 10 usual); Truck is truck_yellow,
30 m/s (3 and 8 a truck's usual). Ego starts at s = 50 at 10 m/s and is asked for 30 m/s at
8 m/s2 at once: held to 4 m/s2 it is at 14 m/s at 1 s, reaches its top 25 m/s at 3.75 s and
s = 50 + 10 * 3.75 + 2 * 3.75^2 = 115.625, then keeps 25 m/s: s = 171.875 at 6 s. esmini 3.6
(--fixed_timestep 0.05) plays the same speeds: 14 at 1 s, 25 from 3.75 s (its places a step
ahead: 116.0 at 3.75 s, 172.25 at 6 s).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model import graph
from sceml.render.labels import root_lines
from sceml.simulate import simulate
from sceml.validation import validate
from sceml.xosc import schema

SOURCE = Path(__file__).parent / "files" / "performance.xosc"
FEATURES = ("maxSpeed", "maxAcceleration", "maxDeceleration")


def _own(scenario: scm.Scenario) -> dict[str, tuple[float | None, ...]]:
    return {
        str(actor.name): tuple(
            None if actor.eGet(f) is None else actor.eGet(f).value for f in FEATURES
        )
        for actor in graph.root_node(scenario).actors
    }


def _written(path: Path) -> dict[str, tuple[str, ...]]:
    """Each ScenarioObject's Performance as written in place, or its CatalogReference: the
    entry and its parameter assignments (release 1.5)."""
    found: dict[str, tuple[str, ...]] = {}
    for item in etree.parse(str(path)).iter("ScenarioObject"):
        reference = item.find("CatalogReference")
        if reference is not None:
            found[str(item.get("name"))] = (
                str(reference.get("entryName")),
                *(
                    f"{a.get('parameterRef')}={float(str(a.get('value')))}"
                    for a in reference.iter("ParameterAssignment")
                ),
            )
            continue
        performance = item.find("Vehicle/Performance")
        assert performance is not None, item.get("name")
        found[str(item.get("name"))] = tuple(str(float(str(performance.get(f)))) for f in FEATURES)
    return found


def test_each_vehicles_own_performance_is_imported_where_it_is_not_the_usual() -> None:
    imported = import_file(SOURCE)
    assert _own(imported.scenario) == {
        "Ego": (25.0, 4.0, None),
        "Lead": (50.0, None, None),
        "Truck": (30.0, None, None),
    }
    unkept = [e.message for e in imported.report.section("not represented")]
    assert any("'Ego': Performance maxAccelerationRate" in m for m in unkept), unkept
    # Ego is asked for more than it is good for, though not more than a car. Its rate of 8 m/s²
    # is taken down to its maxAcceleration of 4 as it is read (the rate players drive, reported
    # as a guess); its target speed is kept, with a warning that the players hold it to its own
    # top speed (the export goes ahead, as esmini plays it).
    guesses = [e.message for e in imported.report.section("guessed")]
    assert any(
        "the rate 8 m/s² taken down to the Vehicle's maxAcceleration 4" in m for m in guesses
    )
    assert sorted((d.code, d.message) for d in validate(imported.scenario)) == [
        (
            "SCEML-L005",
            "Ego.SpeedUp.targetSpeed is 30 m/s, above Ego's own limit of 25 m/s (90 km/h): the "
            "players hold it to that",
        ),
    ]


@pytest.mark.parametrize("version", ("1.0", "1.2"))
def test_it_exports_back_as_it_was_read(version: str, tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / "performance.xosc"
    export_to_file(first, exported, version=version, source_path=SOURCE)
    assert schema.validate_file(exported, version) == []
    # Lead and Truck were read from catalog entries (release 1.5): written as references again,
    # Lead with its top speed assigned to the entry's $MaxSpeed (69 in the catalog), Truck's
    # 30 m/s, 3 and 8 m/s2 the entry's own.
    assert _written(exported) == {
        "Ego": ("25.0", "4.0", "10.0"),
        "Lead": ("car_white", "MaxSpeed=50.0"),
        "Truck": ("truck_yellow",),
    }
    # The re-export refers to the catalogs beside SOURCE: read again where they may be read.
    again = import_file(exported, allow=[SOURCE.parent]).scenario
    graph.root_node(first).environment = None  # the export writes the default one
    graph.root_node(again).environment = None
    same(first, again)
    assert _own(again) == _own(first)


def test_an_actor_without_its_own_limits_is_written_its_kinds(tmp_path: Path) -> None:
    scenario = import_file(SOURCE).scenario
    for actor in graph.root_node(scenario).actors:
        for feature in FEATURES:
            actor.eSet(feature, None)
    exported = tmp_path / "usual.xosc"
    export_to_file(scenario, exported, version="1.2", source_path=SOURCE)
    # SceML's table: a car 69.444 m/s, 10 and 10 m/s2; a truck 33.333 m/s, 3 and 8 m/s2.
    # Truck's entry says 30 m/s, not as a parameter: Truck is written in place (SCEML-A011);
    # Lead's entry has $MaxSpeed (69), assigned the car's 69.444.
    assert _written(exported)["Ego"] == ("69.444", "10.0", "10.0")
    assert _written(exported)["Truck"] == ("33.333", "3.0", "8.0")
    assert _written(exported)["Lead"] == ("car_white", "MaxSpeed=69.444")


def test_the_preview_holds_ego_to_its_own_rate_and_top_speed() -> None:
    run = simulate(import_file(SOURCE).scenario, SOURCE)
    ego = run.states[run.actor_index("Ego")]

    def at(t: float, column: int) -> float:
        return float(ego[int(np.argmin(np.abs(run.times - t))), column])

    assert at(1.0, 3) == pytest.approx(14.0)
    assert at(3.75, 3) == pytest.approx(25.0)
    assert at(3.75, 0) == pytest.approx(115.625)
    assert at(6.0, 3) == pytest.approx(25.0)
    assert at(6.0, 0) == pytest.approx(171.875)


def test_an_own_limit_beyond_what_the_preview_simulates_caps_nothing() -> None:
    # esmini's and CARLA's hero cars say maxAcceleration 200 m/s²: a cap above the preview's
    # ceiling (100 m/s²) is no motion to refuse. With Ego's rate cap raised so far, its 8 m/s²
    # speed-up (taken down to 4 at import) runs at 4 m/s² up to its 25 m/s top speed.
    scenario = import_file(SOURCE).scenario
    ego = next(a for a in scenario.nodes[0].actors if a.name == "Ego")
    ego.maxAcceleration.value = 200.0
    run = simulate(scenario, SOURCE)
    speeds = run.states[run.actor_index("Ego")][:, 3]
    assert float(speeds[int(np.argmin(np.abs(run.times - 1.0)))]) == pytest.approx(14.0)
    assert float(speeds.max()) == pytest.approx(25.0)


def test_the_root_box_names_the_own_limits() -> None:
    scenario = import_file(SOURCE).scenario
    lines = root_lines(graph.root_node(scenario), scenario)
    assert "  Ego: Car, ego, top speed 25 m/s, max acceleration 4 m/s2" in lines
    assert "  Truck: Truck, top speed 30 m/s, catalog entry truck_yellow" in lines

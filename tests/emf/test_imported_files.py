"""Eclipse EMF reads a scenario that `sceml import` wrote, opaque nodes included, and writes it
back so that SceML reads the same model."""

from __future__ import annotations

from pathlib import Path

from sceml.importer import import_to_file
from sceml.model.compare import differences
from sceml.model.loading import load

from .conftest import ECORE, REPO, Harness

FILES = REPO / "tests" / "importer" / "files"


def test_emf_reads_and_writes_an_imported_scenario_with_opaque_nodes(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    # Its controller activation is kept opaque (the lane offset of alks-lane-keeping, used
    # here before, maps now).
    import_to_file(FILES / "cut-in.xosc", source / "alks.xmi")
    assert "OpaqueAction" in (source / "alks.xmi").read_text()
    result = emf.run("roundtrip", ECORE, source, out, Path("alks.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "alks.xmi"), load(out / "alks.xmi")
    assert differences(original.root, from_emf.root) == []


def test_emf_reads_and_writes_an_imported_scenario_with_road_positions(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "road-positions.xosc", source / "road.xmi")
    assert (source / "road.xmi").read_text().count('xsi:type="scemlmodel:RoadPosition"') == 3
    result = emf.run("roundtrip", ECORE, source, out, Path("road.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "road.xmi"), load(out / "road.xmi")
    assert differences(original.root, from_emf.root) == []
    lead = next(a for a in from_emf.root.nodes[0].actors if a.name == "Lead")
    assert lead.startPosition.h.value == 0.05


def test_emf_reads_and_writes_relative_positions_naming_their_actors(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "relative-positions.xosc", source / "relative.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("relative.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "relative.xmi"), load(out / "relative.xmi")
    assert differences(original.root, from_emf.root) == []
    actors = {a.name: a for a in from_emf.root.nodes[0].actors}
    lead = actors["Lead"].startPosition
    assert lead.eClass.name == "RelativeLanePosition" and lead.entity is actors["Ego"]
    assert (lead.dLane, lead.ds.value) == (1, 30.0)


def test_emf_keeps_how_an_imported_time_to_collision_measures(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "ttc-measured.xosc", source / "ttc.xmi")
    written = (source / "ttc.xmi").read_text()
    assert 'freespace="false"' in written and 'relativeDistanceType="longitudinal"' in written
    result = emf.run("roundtrip", ECORE, source, out, Path("ttc.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    from_emf = load(out / "ttc.xmi").root
    assert differences(load(source / "ttc.xmi").root, from_emf) == []
    (ttc,) = [n for n in from_emf.nodes if n.eClass.name == "TimeToCollision"]
    assert (ttc.freespace, ttc.relativeDistanceType.name) == (False, "longitudinal")


def test_emf_reads_and_writes_an_imported_traveled_distance(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "traveled-distance.xosc", source / "traveled.xmi")
    assert "scemlmodel:TraveledDistance" in (source / "traveled.xmi").read_text()
    result = emf.run("roundtrip", ECORE, source, out, Path("traveled.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    assert differences(load(source / "traveled.xmi").root, load(out / "traveled.xmi").root) == []


def test_emf_keeps_how_an_imported_time_headway_measures(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "headway-measured.xosc", source / "headway.xmi")
    assert 'coordinateSystem="lane"' in (source / "headway.xmi").read_text()
    result = emf.run("roundtrip", ECORE, source, out, Path("headway.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    assert differences(load(source / "headway.xmi").root, load(out / "headway.xmi").root) == []


def test_emf_keeps_an_imported_lane_change_target(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "lane-changes.xosc", source / "lanes.xmi")
    written = (source / "lanes.xmi").read_text()
    assert 'targetLane="-3"' in written and 'shape="cubic"' in written
    result = emf.run("roundtrip", ECORE, source, out, Path("lanes.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    assert differences(load(source / "lanes.xmi").root, load(out / "lanes.xmi").root) == []


def test_emf_reads_and_writes_global_nodes_declarations_signals_and_lane_headings(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    for name in ("variables", "lane-headings", "traffic-signals", "lane-offsets"):
        import_to_file(FILES / f"{name}.xosc", source / f"{name}.xmi")
        result = emf.run("roundtrip", ECORE, source, out, Path(f"{name}.xmi"))
        assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
        original, from_emf = load(source / f"{name}.xmi"), load(out / f"{name}.xmi")
        assert differences(original.root, from_emf.root) == []
    globals_back = load(out / "variables.xmi").root
    kinds = {n.eClass.name for n in globals_back.nodes}
    assert {"SetVariable", "VariableCondition"} <= kinds
    assert [(d.name, d.variable) for d in globals_back.nodes[0].declarations] == [
        ("Counter", True),
        ("Mood", True),
    ]
    lead = next(a for a in load(out / "lane-headings.xmi").root.nodes[0].actors if a.name == "Lead")
    assert lead.startPosition.h.value == 3.141593


def test_emf_reads_and_writes_imported_controllers(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    names = ("controller_object", "controller_assign", "controller_override")
    for name in names:
        import_to_file(FILES / f"{name}.xosc", source / f"{name}.xmi")
        result = emf.run("roundtrip", ECORE, source, out, Path(f"{name}.xmi"))
        assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
        original = load(source / f"{name}.xmi").root
        assert differences(original, load(out / f"{name}.xmi").root) == [], name
    from_emf = load(out / "controller_override.xmi").root
    (override,) = [n for n in from_emf.nodes if n.name == "Override"]
    assert [(o.kind.name, o.active, o.value) for o in override.overrides] == [
        ("throttle", True, 0.3),
        ("steeringWheel", True, 0.05),
        ("gear", True, 3.0),
    ]
    # An unset domain (EBooleanObject) stays unset through EMF, not false.
    (assign,) = [n for n in from_emf.nodes if n.name == "Assign"]
    assert (assign.activation.longitudinal, assign.activation.lateral) == (True, None)
    ego = next(a for a in load(out / "controller_object.xmi").root.nodes[0].actors)
    assert [(p.name, p.value) for p in ego.controller.properties][1] == ("timeGap", "2.0")


def test_emf_keeps_how_many_times_an_imported_node_runs(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "repeats.xosc", source / "repeats.xmi")
    assert 'maxRuns="3"' in (source / "repeats.xmi").read_text()
    result = emf.run("roundtrip", ECORE, source, out, Path("repeats.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    assert 'maxRuns="3"' in (out / "repeats.xmi").read_text()
    assert differences(load(source / "repeats.xmi").root, load(out / "repeats.xmi").root) == []


def test_emf_keeps_how_an_imported_relative_distance_measures(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "relative-distance-measured.xosc", source / "distance.xmi")
    written = (source / "distance.xmi").read_text()
    assert 'freespace="true"' in written and 'relativeDistanceType="longitudinal"' in written
    result = emf.run("roundtrip", ECORE, source, out, Path("distance.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    from_emf = load(out / "distance.xmi").root
    assert differences(load(source / "distance.xmi").root, from_emf) == []
    (close,) = [n for n in from_emf.nodes if n.eClass.name == "InVehicleRadius"]
    assert (close.freespace, close.relativeDistanceType.name) == (True, "longitudinal")
    assert close.rule.name == "lessThan"


def test_emf_reads_and_writes_imported_route_positions(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "route-positions.xosc", source / "routes.xmi")
    assert (source / "routes.xmi").read_text().count('xsi:type="scemlmodel:RoutePosition"') == 3
    result = emf.run("roundtrip", ECORE, source, out, Path("routes.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    from_emf = load(out / "routes.xmi").root
    assert differences(load(source / "routes.xmi").root, from_emf) == []
    ego = next(a for a in from_emf.nodes[0].actors if a.name == "Ego").startPosition
    assert [w.routeStrategy.name for w in ego.waypoints] == ["shortest", "fastest"]
    assert (ego.laneId, ego.pathS.value) == (-2, 30.0)


def test_emf_reads_and_writes_trailers_and_reverse_speeds(emf: Harness, tmp_path: Path) -> None:
    """Release 1.4: Actor.trailer (a reference to another actor, `Car+` included), hitchX and
    couplerX; a negative target speed."""
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "trailers.xosc", source / "trailers.xmi")
    import_to_file(FILES / "reversing.xosc", source / "reversing.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("trailers.xmi"), Path("reversing.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    for name in ("trailers.xmi", "reversing.xmi"):
        original, from_emf = load(source / name), load(out / name)
        assert differences(original.root, from_emf.root) == []
    actors = {a.name: a for a in load(out / "trailers.xmi").root.nodes[0].actors}
    assert actors["Car"].trailer is actors["Car+"] and actors["Tractor"].trailer is actors["Semi"]
    assert (actors["Car"].hitchX.value, actors["Car+"].couplerX.value) == (-1.2, 3.25)
    reverse = next(n for n in load(out / "reversing.xmi").root.nodes if n.name == "Reverse")
    assert reverse.targetSpeed.value == -3.0


def test_emf_reads_and_writes_trailer_couplings(emf: Harness, tmp_path: Path) -> None:
    """Release 1.5: ConnectTrailer (its trailer the target actor) and DisconnectTrailer."""
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "trailer-connect.xosc", source / "coupling.xmi")
    written = (source / "coupling.xmi").read_text()
    for kind in ("ConnectTrailer", "DisconnectTrailer"):
        assert f'xsi:type="scemlmodel:{kind}"' in written
    result = emf.run("roundtrip", ECORE, source, out, Path("coupling.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "coupling.xmi"), load(out / "coupling.xmi")
    assert differences(original.root, from_emf.root) == []
    couple = next(n for n in from_emf.root.nodes if n.name == "Couple")
    assert (couple.referenceActor.name, couple.targetActor.name) == ("Car", "Trailer")


def test_emf_reads_and_writes_imported_lights_and_motion_conditions(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "lights-and-stops.xosc", source / "lights.xmi")
    import_to_file(FILES / "relative-speeds.xosc", source / "speeds.xmi")
    written = (source / "lights.xmi").read_text() + (source / "speeds.xmi").read_text()
    for kind in ("LightState", "StandStill", "AccelerationCondition", "MatchSpeed"):
        assert f'xsi:type="scemlmodel:{kind}"' in written
    assert 'mode="flashing"' in written and 'direction="longitudinal"' in written
    assert 'relation="factor"' in written
    for name in ("lights.xmi", "speeds.xmi"):
        result = emf.run("roundtrip", ECORE, source, out, Path(name))
        assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
        assert differences(load(source / name).root, load(out / name).root) == []


def test_emf_reads_and_writes_an_actors_own_performance(emf: Harness, tmp_path: Path) -> None:
    """Release 1.4: Actor.maxSpeed, maxAcceleration, maxDeceleration (a Vehicle's Performance),
    set on some actors and unset on others."""
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "performance.xosc", source / "performance.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("performance.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "performance.xmi"), load(out / "performance.xmi")
    assert differences(original.root, from_emf.root) == []
    actors = {a.name: a for a in from_emf.root.nodes[0].actors}
    assert (actors["Ego"].maxSpeed.value, actors["Ego"].maxAcceleration.value) == (25.0, 4.0)
    assert actors["Ego"].maxDeceleration is None and actors["Lead"].maxSpeed.value == 50.0


def test_emf_reads_and_writes_speed_shapes_and_inclusive_rules(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "speed-shapes.xosc", source / "shapes.xmi")
    written = (source / "shapes.xmi").read_text()
    # The defaults (linear, greaterThan) are not written: these are the release 1.4 literals.
    assert written.count('shape="cubic"') == 1 and written.count('rule="lessOrEqual"') == 1
    result = emf.run("roundtrip", ECORE, source, out, Path("shapes.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "shapes.xmi"), load(out / "shapes.xmi")
    assert differences(original.root, from_emf.root) == []
    shapes = sorted(n.shape.name for n in from_emf.root.nodes if hasattr(n, "shape"))
    assert shapes == ["cubic", "linear", "sinusoidal", "step", "step"]


def test_emf_reads_and_writes_a_trajectory_in_follow_mode(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "trajectory-follow-mode.xosc", source / "follow.xmi")
    assert (source / "follow.xmi").read_text().count('followingMode="follow"') == 1
    result = emf.run("roundtrip", ECORE, source, out, Path("follow.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "follow.xmi"), load(out / "follow.xmi")
    assert differences(original.root, from_emf.root) == []
    walk = next(n for n in from_emf.root.nodes if n.eClass.name == "FollowTrajectory")
    assert walk.followingMode.name == "follow"


def test_emf_reads_and_writes_interrupting_maneuvers(emf: Harness, tmp_path: Path) -> None:
    # Release 1.5's Maneuver.interrupts: an attribute EMF reads from the .ecore and writes back.
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "interrupts.xosc", source / "interrupts.xmi")
    assert (source / "interrupts.xmi").read_text().count('interrupts="true"') == 2
    result = emf.run("roundtrip", ECORE, source, out, Path("interrupts.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "interrupts.xmi"), load(out / "interrupts.xmi")
    assert differences(original.root, from_emf.root) == []
    interrupting = {n.name for n in from_emf.root.nodes if getattr(n, "interrupts", False)}
    assert interrupting == {"SpeedUp", "Brake"}


def test_emf_reads_and_writes_a_distance_keeping_with_its_measure_and_limits(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "distance-keeping.xosc", source / "keeping.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("keeping.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "keeping.xmi"), load(out / "keeping.xmi")
    assert differences(original.root, from_emf.root) == []
    nodes = {n.eClass.name: n for n in from_emf.root.nodes}
    follow, approach = nodes["Follow"], nodes["Approach"]
    assert (follow.freespace, follow.maxAccelerationRate.value) == (True, 2.0)
    assert (approach.displacement.name, approach.timeGap.value) == ("leading", 1.5)


def test_emf_reads_and_writes_a_trajectory_that_begins_at_its_first_waypoint(
    emf: Harness, tmp_path: Path
) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "trajectory-follow-mode.xosc", source / "walk.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("walk.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "walk.xmi"), load(out / "walk.xmi")
    assert differences(original.root, from_emf.root) == []
    (walk,) = [n for n in from_emf.root.nodes if n.eClass.name == "FollowTrajectory"]
    assert walk.fromFirstWaypoint is True


def test_emf_keeps_the_vehicle_catalog_and_each_actors_entry(emf: Harness, tmp_path: Path) -> None:
    # Release 1.5: RootNode.vehicleCatalog and Actor.catalogEntry, as the import sets them.
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "catalog-references.xosc", source / "catalogs.xmi")
    result = emf.run("roundtrip", ECORE, source, out, Path("catalogs.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "catalogs.xmi"), load(out / "catalogs.xmi")
    assert differences(original.root, from_emf.root) == []
    root = from_emf.root.nodes[0]
    assert root.vehicleCatalog == original.root.nodes[0].vehicleCatalog
    assert root.vehicleCatalog.endswith("tests/importer/files/catalogs")
    entries = {a.name: a.catalogEntry for a in root.actors}
    assert entries == {
        "Ego": "car_white",
        "Lead": "car_white",
        "Truck": "truck_yellow",
        "Bike": None,
    }

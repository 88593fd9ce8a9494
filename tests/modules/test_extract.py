"""Extraction: a single-entry, single-exit part of a scenario becomes a library module and a use,
and flattening gives the original behaviour back; bad selections change nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.errors import SaveError
from sceml.model.build import ScenarioBuilder
from sceml.model.compare import differences
from sceml.model.graph import actors as scenario_actors
from sceml.model.graph import predecessors, successors
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.modules import (
    ExtractError,
    RoleSpec,
    extract,
    extract_file,
    flatten,
    list_definitions,
    parse_role,
    store,
)
from sceml.modules.extract import plan_extraction

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
BIKE_BRANCH = ["InVehicleRadius_1", "Accelerate_2", "Cross_1", "InLocationRadius_2"]


def uis1(level: str = "concrete") -> scm.Scenario:
    return load(EXAMPLES / f"uis1-{level}.xmi").root


@pytest.mark.parametrize("level", ["functional", "logical", "concrete"])
@pytest.mark.parametrize("parametrize", [False, True])
def test_extracting_the_bike_branch_and_flattening_gives_uis1_back(
    level: str, parametrize: bool, canonical
) -> None:
    scenario = uis1(level)
    library = scm.Library(name="lib")
    use = extract(scenario, BIKE_BRANCH, "BikeCrossing", library, parametrize=parametrize)
    assert use.definition is library.modules[0]
    assert canonical(flatten(scenario)) == canonical(uis1(level))


@pytest.mark.parametrize(
    "nodes",
    [["Accelerate_2", "Cross_1"], ["Accelerate_1", "TurnRight_1", "InLocationRadius_1"]],
)
def test_other_parts_of_uis1_extract_and_flatten_back(nodes: list[str], canonical) -> None:
    scenario = uis1()
    extract(scenario, nodes, "Part", scm.Library(name="lib"), parametrize=True)
    assert canonical(flatten(scenario)) == canonical(uis1())


def test_the_module_gets_roles_ports_and_the_nodes_and_the_scenario_a_use() -> None:
    scenario = uis1()
    library = scm.Library(name="lib")
    use = extract(scenario, BIKE_BRANCH, "BikeCrossing", library)
    definition = library.modules[0]
    assert [(r.name, [k.kind.name for k in r.allowedKinds]) for r in definition.roles] == [
        ("bike", ["Bicycle"]),
        ("ego", ["Car"]),
    ]
    names = [str(n.name) for n in definition.nodes]
    assert names == ["In", "Out", *BIKE_BRANCH]
    by_name = {n.name: n for n in definition.nodes}
    assert successors(by_name["In"]) == [by_name["InVehicleRadius_1"]]
    assert predecessors(by_name["Out"]) == [by_name["InLocationRadius_2"]]
    wait = by_name["InVehicleRadius_1"]
    assert (wait.referenceActor, wait.targetActor) == tuple(definition.roles)
    assert wait.radius.value == 12.0  # values stay as they were
    assert {b.role: b.actor.name for b in use.bindings} == {"bike": "bike", "ego": "ego"}
    outer = {n.name: n for n in scenario.nodes}
    assert predecessors(use) == [outer["Root"]]
    assert successors(use) == [outer["End"]]
    assert set(outer) == {"Root", "End", "Accelerate_1", "TurnRight_1", "InLocationRadius_1", "BikeCrossing_1"}  # fmt: skip


def test_roles_can_be_named_and_widened() -> None:
    library = scm.Library(name="lib")
    roles = dict(
        [parse_role("bike=crosser:TwoWheeler|Pedestrian"), parse_role("ego=trigger:FourWheeler")]
    )
    use = extract(uis1(), BIKE_BRANCH, "Crossing", library, roles=roles)
    definition = library.modules[0]
    assert [(r.name, [k.kind.name for k in r.allowedKinds]) for r in definition.roles] == [
        ("crosser", ["TwoWheeler", "Pedestrian"]),
        ("trigger", ["FourWheeler"]),
    ]
    assert {b.role: b.actor.name for b in use.bindings} == {"crosser": "bike", "trigger": "ego"}


def test_parse_role_forms() -> None:
    assert parse_role("bike=crosser") == ("bike", RoleSpec("crosser", ()))
    assert parse_role(" bike = :Bicycle|Pedestrian") == ("bike", RoleSpec("", ("Bicycle", "Pedestrian")))  # fmt: skip
    for bad in ("bike", "bike=", "=crosser", "bike=crosser:Horse"):
        with pytest.raises(ExtractError):
            parse_role(bad)


def test_parametrize_turns_values_into_parameters_the_use_overrides() -> None:
    library = scm.Library(name="lib")
    use = extract(uis1(), BIKE_BRANCH, "BikeCrossing", library, parametrize=True)
    parameters = {p.name: p for p in library.modules[0].parameters}
    radius = parameters["InVehicleRadius_1_radius"]
    assert (radius.unit, radius.default.value) == ("m", 12.0)
    assert parameters["Cross_1_destination_x"].default.value == 10.0
    assert parameters["Cross_1_destination_h"].unit == "rad"
    overrides = {o.parameter: o.value.value for o in use.overrides}
    assert overrides["InVehicleRadius_1_radius"] == 12.0
    assert set(overrides) == set(parameters)
    wait = next(n for n in library.modules[0].nodes if n.name == "InVehicleRadius_1")
    assert wait.radius.parameter is radius


REFUSALS = [
    (["Accelerate_2", "InLocationRadius_2"], "Bike", "entered from exactly one node"),
    (
        ["Accelerate_1", "Accelerate_2"],
        "Bike",
        "entered from exactly one node, but is entered from Root, InVehicleRadius_1",
    ),  # fmt: skip
    (["InVehicleRadius_1", "Cross_1"], "Bike", "entered from exactly one node"),
    (
        ["Accelerate_1", "TurnRight_1", "InVehicleRadius_1"],
        "Bike",
        "but is left from TurnRight_1, InVehicleRadius_1",
    ),  # fmt: skip
    (["Root", "Accelerate_1"], "Bike", "not Root"),
    (["Cross_9"], "Bike", "no node 'Cross_9'"),
    ([], "Bike", "select at least one node"),
    (BIKE_BRANCH, "", "needs a name"),
]


@pytest.mark.parametrize(("nodes", "name", "message"), REFUSALS)
def test_bad_selections_are_refused_and_change_nothing(nodes, name, message) -> None:
    scenario, library = uis1(), scm.Library(name="lib")
    with pytest.raises(ExtractError, match=message) as caught:
        extract(scenario, nodes, name, library)
    assert caught.value.exit_code == 2
    assert differences(scenario, uis1()) == []
    assert list(library.modules) == []


def test_two_exits_are_refused() -> None:
    b = ScenarioBuilder("Fork")
    car = b.actor("Car", "ego", ego=True)
    first, second, third = b.add("Stop", car), b.add("Stop", car), b.add("Stop", car)
    b.chain(b.root, first, second, b.end)
    b.chain(first, third, b.end)
    with pytest.raises(ExtractError, match="left from exactly one of its nodes, but is left from"):
        extract(b.scenario, ["Stop_1", "Stop_2", "Stop_3"], "M", scm.Library())


def test_a_node_off_the_path_from_entry_to_exit_is_refused() -> None:
    b = ScenarioBuilder("Dead end")
    car = b.actor("Car", "ego", ego=True)
    start, on_path, exit_, dead = (b.add("Stop", car) for _ in range(4))
    b.chain(b.root, start, on_path, exit_, b.end)
    b.flow(start, dead)
    with pytest.raises(ExtractError, match="Stop_4 do not lie on a path"):
        extract(b.scenario, ["Stop_2", "Stop_3", "Stop_4"], "M", scm.Library())


def test_a_fork_from_one_source_may_be_extracted(canonical) -> None:
    b = ScenarioBuilder("Parallel")
    car, bike = b.actor("Car", "ego", ego=True), b.actor("Bicycle", "bike")
    stop, go = b.add("Stop", car), b.add("Accelerate", bike, targetSpeed=3)
    join = b.join_all(stop, go)
    b.flow(b.root, stop)
    b.flow(b.root, go)
    b.flow(join, b.end)
    before = canonical(b.scenario)
    extract(b.scenario, ["Stop_1", "Accelerate_1", "JoinAllFinished_1"], "Both", scm.Library())
    assert canonical(flatten(b.scenario)) == before


@pytest.mark.parametrize(
    ("roles", "message"),
    [
        ({"truck": RoleSpec("t", ())}, "a role is given for truck, which the selected nodes"),
        ({"bike": RoleSpec("x", ("Pedestrian",))}, "would not accept its own actor 'bike'"),
        ({"bike": RoleSpec("ego", ())}, "the same role name 'ego'"),
    ],
)
def test_bad_roles_are_refused(roles, message) -> None:
    scenario = uis1()
    with pytest.raises(ExtractError, match=message):
        extract(scenario, BIKE_BRANCH, "M", scm.Library(), roles=roles)
    assert differences(scenario, uis1()) == []


def test_extract_file_creates_the_library_and_rewrites_the_scenario(
    examples_copy: Path, canonical
) -> None:
    path, library_path = examples_copy / "uis1-logical.xmi", examples_copy / "lib" / "new.xmi"
    report = extract_file(path, BIKE_BRANCH, "BikeCrossing", library_path)
    assert report.created_library and report.use == "BikeCrossing_1"
    assert 'href="lib/new.xmi#BikeCrossing"' in path.read_text()
    reloaded = load(path).root
    assert canonical(flatten(reloaded)) == canonical(uis1("logical"))
    assert [s.name for s in list_definitions(load(library_path).root)] == ["BikeCrossing"]


def test_extract_file_adds_to_an_existing_library_and_can_write_elsewhere(
    examples_copy: Path, canonical
) -> None:
    library_path = examples_copy / "library" / "sceml-library.xmi"
    out = examples_copy / "out" / "uis2-extracted.xmi"
    original = (examples_copy / "uis2-concrete.xmi").read_bytes()
    extract_file(
        examples_copy / "uis2-concrete.xmi",
        ["InLocationRadius_2", "DriveDistance_1"],
        "CarGoesStraight",
        library_path,
        output=out,
    )
    assert (examples_copy / "uis2-concrete.xmi").read_bytes() == original
    text = out.read_text()
    assert 'href="../library/sceml-library.xmi#CrossingManeuver"' in text
    assert 'href="../library/sceml-library.xmi#CarGoesStraight"' in text
    names = [s.name for s in list_definitions(load(library_path).root)]
    assert names[0] == "CrossingManeuver" and names[-1] == "CarGoesStraight"
    expected = canonical(flatten(load(examples_copy / "uis2-concrete.xmi").root))
    assert canonical(flatten(load(out, allowed_roots=[examples_copy]).root)) == expected


def test_a_duplicate_name_is_refused_and_no_file_changes(examples_copy: Path) -> None:
    path, library_path = (
        examples_copy / "uis1-concrete.xmi",
        examples_copy / "library" / "sceml-library.xmi",
    )
    before = (path.read_bytes(), library_path.read_bytes())
    with pytest.raises(ExtractError, match="already has a module 'CrossingManeuver'"):
        extract_file(path, BIKE_BRANCH, "CrossingManeuver", library_path)
    assert (path.read_bytes(), library_path.read_bytes()) == before


def test_a_failed_save_leaves_both_files_as_they_were(examples_copy: Path, monkeypatch) -> None:
    path, library_path = (
        examples_copy / "uis1-concrete.xmi",
        examples_copy / "library" / "sceml-library.xmi",
    )
    before = (path.read_bytes(), library_path.read_bytes())
    real_save = save
    calls = []

    def failing_second_save(root, target):
        calls.append(target)
        if len(calls) == 2:
            raise SaveError("disk full", file=target)
        return real_save(root, target)

    monkeypatch.setattr(store, "save", failing_second_save)
    with pytest.raises(SaveError, match="disk full"):
        extract_file(path, BIKE_BRANCH, "BikeCrossing", library_path)
    assert (path.read_bytes(), library_path.read_bytes()) == before
    assert sorted(p.name for p in examples_copy.rglob(".*.tmp")) == []


def test_planning_an_extraction_leaves_the_scenario_and_says_what_extract_would_do(
    canonical,
) -> None:
    scenario = uis1()
    library = scm.Library(name="lib")
    plan = plan_extraction(scenario, BIKE_BRANCH, "BikeCrossing", library)
    assert canonical(scenario) == canonical(uis1())  # unchanged
    assert [str(d.name) for d in library.modules] == ["BikeCrossing"]
    assert plan.use.definition is library.modules[0] and plan.use.eContainer() is None
    assert list(plan.use.incoming) == [] and list(plan.use.outgoing) == []
    own = {str(n.name): n for n in scenario.nodes}
    actors = {str(a.name): a for a in scenario_actors(scenario)}
    assert {b.role: b.actor for b in plan.use.bindings} == {
        "bike": actors["bike"],
        "ego": actors["ego"],
    }
    assert plan.region.nodes == [own[name] for name in BIKE_BRANCH]
    # The bike branch starts the scenario's node list after Root, End and the ego's three nodes.
    assert [str(n.name) for n in scenario.nodes][plan.position] == "InVehicleRadius_1"
    assert plan.connections() == [(own["Root"], plan.use), (plan.use, own["End"])]
    # extract itself, on another copy, puts its use at that place with those flows.
    other = uis1()
    use = extract(other, BIKE_BRANCH, "BikeCrossing", scm.Library(name="lib"))
    assert list(other.nodes).index(use) == plan.position
    assert [str(n.name) for n in predecessors(use)] == ["Root"]
    assert [str(n.name) for n in successors(use)] == ["End"]
    assert plan.use.name == use.name == "BikeCrossing_1"

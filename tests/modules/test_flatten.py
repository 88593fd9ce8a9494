"""Flattening: expanded uses behave like hand-inlined nodes, with readable unique names, and every
way a use can fail to expand is a located FlattenError."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from pyecore.resources import URI

import scemlmodel as scm
from sceml.model.build import (
    GraphBuilder,
    LibraryBuilder,
    ScenarioBuilder,
    actor_named,
    relative_lane,
    relative_object,
    world,
)
from sceml.model.compare import differences
from sceml.model.documents import new_resource_set
from sceml.model.graph import end_node, predecessors, root_node
from sceml.model.loading import load
from sceml.model.params import span, uniform
from sceml.model.saving import save
from sceml.modules import FlattenError, depth, expand, flatten, list_definitions

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# UIS2's CrossingManeuver use, written out by hand from the module and the use's overrides.
CROSSING_VALUES = {
    "concrete": {"radius": 15.0, "speed": 1.5},
    "logical": {"radius": span(10.0, 20.0, 5.0), "speed": uniform(1.0, 2.0)},
}


def hand_inlined_uis2(level: str) -> scm.Scenario:
    scenario = load(EXAMPLES / f"uis2-{level}.xmi").root
    use = next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse))
    for flow in [*use.incoming, *use.outgoing]:
        flow.source = flow.target = None
        scenario.flows.remove(flow)
    scenario.nodes.remove(use)
    pedestrian, car = actor_named(scenario, "pedestrian"), actor_named(scenario, "car")
    values = CROSSING_VALUES[level]
    b = GraphBuilder(scenario)
    wait = b.add("InVehicleRadius", pedestrian, target=car, radius=values["radius"])
    go = b.add("Accelerate", pedestrian, targetSpeed=values["speed"])
    cross = b.add("Cross", pedestrian, destination=world(-10.0, 4.5, h=1.570796))
    arrived = b.add("InLocationRadius", pedestrian, position=world(-10.0, 4.5), radius=2.0)
    b.chain(root_node(scenario), wait, go, cross, arrived, end_node(scenario))
    return scenario


@pytest.mark.parametrize("level", ["concrete", "logical"])
def test_flattened_uis2_behaves_like_hand_inlined_uis2(level: str, canonical) -> None:
    flat = flatten(load(EXAMPLES / f"uis2-{level}.xmi").root)
    assert canonical(flat) == canonical(hand_inlined_uis2(level))
    assert not any(isinstance(n, scm.ModuleUse) for n in flat.nodes)


def test_expanded_nodes_are_named_after_their_use() -> None:
    flat = flatten(load(EXAMPLES / "uis2-concrete.xmi").root)
    names = {str(n.name) for n in flat.nodes}
    assert {
        "CrossingManeuver_1.InVehicleRadius_1",
        "CrossingManeuver_1.Accelerate_1",
        "CrossingManeuver_1.Cross_1",
        "CrossingManeuver_1.InLocationRadius_1",
    } < names
    by_name = {n.name: n for n in flat.nodes}
    wait = by_name["CrossingManeuver_1.InVehicleRadius_1"]
    assert (wait.referenceActor.name, wait.targetActor.name) == ("pedestrian", "car")
    assert predecessors(wait) == [by_name["Root"]]


def test_flatten_leaves_the_input_untouched_and_saves_a_self_contained_file(
    examples_copy: Path, tmp_path: Path
) -> None:
    document = load(examples_copy / "uis2-logical.xmi")
    flat = flatten(document.root)
    assert differences(document.root, load(examples_copy / "uis2-logical.xmi").root) == []
    target = tmp_path / "out" / "flat.xmi"
    save(flat, target)
    assert "href=" not in target.read_text()
    reloaded = load(target, allowed_roots=[target.parent])
    assert differences(flat, reloaded.root) == []


def test_a_scenario_without_uses_flattens_to_an_equal_copy() -> None:
    scenario = load(EXAMPLES / "uis1-concrete.xmi").root
    assert differences(scenario, flatten(scenario)) == []


OVERTAKING_NAMES = {
    "Root",
    "End",
    "KeepVelocity_1",
    "Overtaking_1.PassVehicle_1.ChangeLaneLeft_1.TimeToCollision_1",
    "Overtaking_1.PassVehicle_1.ChangeLaneLeft_1.LaneChange_1",
    "Overtaking_1.PassVehicle_1.Accelerate_1",
    "Overtaking_1.PassVehicle_1.ChangeLaneRight_1.TimeElapsed_1",
    "Overtaking_1.PassVehicle_1.ChangeLaneRight_1.LaneChange_1",
    "Overtaking_1.InVehicleRadius_1",
    "Overtaking_1.DriveDistance_1",
    "Overtaking_1.JoinAllFinished_1",
}


def test_nesting_three_deep_flattens_with_scoped_names_roles_and_parameters() -> None:
    result = expand(load(EXAMPLES / "overtaking-concrete.xmi").root)
    assert result.expanded == [
        "Overtaking_1",
        "Overtaking_1.PassVehicle_1",
        "Overtaking_1.PassVehicle_1.ChangeLaneLeft_1",
        "Overtaking_1.PassVehicle_1.ChangeLaneRight_1",
    ]
    by_name = {n.name: n for n in result.scenario.nodes}
    assert set(by_name) == OVERTAKING_NAMES
    prefix = "Overtaking_1.PassVehicle_1."
    closing = by_name[prefix + "ChangeLaneLeft_1.TimeToCollision_1"]
    assert (closing.referenceActor.name, closing.targetActor.name) == ("ego", "truck")
    assert closing.time.value == 3.0  # ChangeLaneLeft's default
    # passingSpeed: overridden in the scenario, passed on by Overtaking to PassVehicle.
    assert by_name[prefix + "Accelerate_1"].targetSpeed.value == 13.0
    # passingTime: Overtaking's default, passed on twice, down to ChangeLaneRight's holdTime.
    assert by_name[prefix + "ChangeLaneRight_1.TimeElapsed_1"].duration.value == 1.5
    cut_in = by_name[prefix + "ChangeLaneRight_1.LaneChange_1"]
    assert (cut_in.direction.name, cut_in.distance.value) == ("right", 15.0)
    join = by_name["Overtaking_1.JoinAllFinished_1"]
    assert {p.name for p in predecessors(join)} == {
        "Overtaking_1.DriveDistance_1",
        prefix + "ChangeLaneRight_1.LaneChange_1",
    }
    assert predecessors(by_name["End"]) == [by_name["KeepVelocity_1"], join]
    assert {p.name for p in predecessors(closing)} == {"Root"}


def test_provenance_names_the_use_chain_and_the_definition_element_three_deep() -> None:
    document = load(EXAMPLES / "overtaking-concrete.xmi")
    result = expand(document.root)
    by_name = {n.name: n for n in result.scenario.nodes}
    outer = next(n for n in document.root.nodes if n.name == "Overtaking_1")

    origin = result.origin(by_name["Overtaking_1.PassVehicle_1.ChangeLaneLeft_1.LaneChange_1"])
    assert origin is not None and origin.from_module
    assert [use.name for use in origin.uses] == [
        "Overtaking_1",
        "PassVehicle_1",
        "ChangeLaneLeft_1",
    ]
    assert origin.uses[0] is outer and origin.in_scenario is outer
    # The inner uses are those of the definitions, the element that of the innermost definition.
    assert [use.eContainer().name for use in origin.uses[1:]] == ["Overtaking", "PassVehicle"]
    assert origin.element.name == "LaneChange_1"
    assert origin.element.eContainer().name == "ChangeLaneLeft"
    assert origin.element.eResource.uri.normalize().endswith("sceml-library.xmi")

    plain = document.root.nodes[2]
    mine = result.origin(by_name["KeepVelocity_1"])
    assert mine is not None and not mine.from_module
    assert mine.element is plain and mine.in_scenario is plain
    assert result.origin(result.scenario).element is document.root


def test_provenance_traces_substituted_values_to_the_override_or_default() -> None:
    document = load(EXAMPLES / "overtaking-concrete.xmi")
    result = expand(document.root)
    by_name = {n.name: n for n in result.scenario.nodes}
    prefix = "Overtaking_1.PassVehicle_1."
    # passingSpeed: the scenario's override, passed on through Overtaking to PassVehicle.
    speed = result.origin(by_name[prefix + "Accelerate_1"].targetSpeed)
    override = next(o for o in document.root.nodes[3].overrides if o.parameter == "passingSpeed")
    assert speed is not None and speed.element is override.value
    assert [use.name for use in speed.uses] == ["Overtaking_1", "PassVehicle_1"]
    # The time to collision of ChangeLaneLeft is its own default.
    time = result.origin(by_name[prefix + "ChangeLaneLeft_1.TimeToCollision_1"].time)
    assert time is not None and time.element.eContainer().name == "timeToCollision"
    assert time.element.eContainer().eContainer().name == "ChangeLaneLeft"


def test_every_element_of_the_flat_scenario_has_an_origin_except_rewired_flows() -> None:
    result = expand(load(EXAMPLES / "overtaking-logical.xmi").root)
    missing = [o for o in result.scenario.eAllContents() if result.origin(o) is None]
    assert missing and all(isinstance(o, scm.Flow) for o in missing)
    assert all(result.origin(n) is not None for n in result.scenario.nodes)


def test_an_override_reaches_the_innermost_node_at_the_logical_level() -> None:
    flat = flatten(load(EXAMPLES / "overtaking-logical.xmi").root)
    speed_up = next(n for n in flat.nodes if n.name == "Overtaking_1.PassVehicle_1.Accelerate_1")
    assert isinstance(speed_up.targetSpeed, scm.UniformDistribution)
    assert (speed_up.targetSpeed.min, speed_up.targetSpeed.max) == (12.0, 14.0)


def test_a_library_change_is_seen_when_flattening(examples_copy: Path) -> None:
    path = examples_copy / "library" / "sceml-library.xmi"
    library = load(path)
    crossing = next(m for m in library.root.modules if m.name == "CrossingManeuver")
    arrival = next(p for p in crossing.parameters if p.name == "arrivalRadius")
    arrival.default.value = 3.5
    save(library.root, path)
    flat = flatten(load(examples_copy / "uis2-concrete.xmi").root)
    arrived = next(n for n in flat.nodes if n.name == "CrossingManeuver_1.InLocationRadius_1")
    assert arrived.radius.value == 3.5


def test_moving_scenario_and_library_together_keeps_flattening(
    examples_copy: Path, tmp_path: Path
) -> None:
    moved = tmp_path / "elsewhere" / "deeper"
    shutil.copytree(examples_copy, moved)
    shutil.rmtree(examples_copy)
    names = {n.name for n in flatten(load(moved / "overtaking-logical.xmi").root).nodes}
    assert names == OVERTAKING_NAMES


def _save_libraries(libraries: dict[Path, scm.Library]) -> None:
    # Every library needs its file before any is saved, so cross-file references come out right.
    resource_set = new_resource_set()
    for path, library in libraries.items():
        resource_set.create_resource(URI(str(path))).append(library)
    for path, library in libraries.items():
        save(library, path)


def _scenario_using(definition: scm.ModuleDefinition, path: Path) -> Path:
    b = ScenarioBuilder("Uses", level="functional")
    car = b.actor("Car", "ego", ego=True)
    b.chain(b.root, b.use(definition, {"driver": car}), b.end)
    save(b.scenario, path)
    return path


def _module(library: LibraryBuilder, name: str):
    module = library.module(name)
    module.role("driver", "FourWheeler")
    return module


def test_direct_recursion_is_an_error(tmp_path: Path) -> None:
    library = LibraryBuilder("lib")
    looping = _module(library, "Loop")
    inner = looping.use(looping.definition, {"driver": looping.definition.roles[0]})
    looping.chain(looping.in_port, inner, looping.out_port)
    _save_libraries({tmp_path / "lib.xmi": library.library})
    scenario = _scenario_using(looping.definition, tmp_path / "scenario.xmi")
    with pytest.raises(FlattenError, match="module uses itself: Loop -> Loop") as caught:
        flatten(load(scenario).root)
    assert caught.value.exit_code == 1
    assert caught.value.file == str(tmp_path / "lib.xmi")  # where the looping use is written
    assert caught.value.line is not None


def test_transitive_recursion_across_files_is_an_error(tmp_path: Path) -> None:
    first, second = LibraryBuilder("first"), LibraryBuilder("second")
    a, b = _module(first, "A"), _module(second, "B")
    a.chain(a.in_port, a.use(b.definition, {"driver": a.definition.roles[0]}), a.out_port)
    b.chain(b.in_port, b.use(a.definition, {"driver": b.definition.roles[0]}), b.out_port)
    _save_libraries(
        {tmp_path / "first.xmi": first.library, tmp_path / "sub" / "second.xmi": second.library}
    )
    assert 'href="sub/second.xmi#B"' in (tmp_path / "first.xmi").read_text()
    scenario = _scenario_using(a.definition, tmp_path / "scenario.xmi")
    with pytest.raises(FlattenError, match="module uses itself: A -> B -> A"):
        flatten(load(scenario).root)
    reloaded = load(tmp_path / "first.xmi").root
    with pytest.raises(FlattenError, match="A -> B -> A"):
        depth(reloaded.modules[0])
    (summary,) = list_definitions(reloaded)
    assert summary.size.depth is None
    assert "A -> B -> A" in str(summary.size.problem)


def _edit(path: Path, old: str, new: str) -> Path:
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new))
    return path


def test_unresolved_library_file_names_the_path_tried(examples_copy: Path) -> None:
    path = _edit(examples_copy / "uis2-concrete.xmi", "library/sceml-library.xmi", "lib/x.xmi")
    with pytest.raises(FlattenError) as caught:
        flatten(load(path).root)
    message = str(caught.value)
    assert "'lib/x.xmi#CrossingManeuver' cannot be loaded" in message
    assert f"{examples_copy / 'lib' / 'x.xmi'}: no such file" in message
    assert caught.value.file == str(path)
    assert caught.value.line is not None
    assert caught.value.element == "CrossingManeuver_1"


def test_unresolved_module_name_lists_the_modules_there_are(examples_copy: Path) -> None:
    path = _edit(examples_copy / "uis2-concrete.xmi", "#CrossingManeuver", "#Crossing")
    with pytest.raises(FlattenError, match=r"has no module 'Crossing' \(it has: CrossingManeuver,"):
        flatten(load(path).root)


def test_library_outside_the_allowed_folders_is_reported(examples_copy: Path) -> None:
    document = load(examples_copy / "uis2-concrete.xmi", allowed_roots=[examples_copy / "none"])
    with pytest.raises(FlattenError, match="reference leaves the allowed folders"):
        flatten(document.root)


def test_unbound_role_is_an_error(examples_copy: Path) -> None:
    path = _edit(
        examples_copy / "uis2-concrete.xmi",
        '<bindings xsi:type="scemlmodel:RoleBinding" role="trigger" actor="//@nodes.0/@actors.1"/>',
        "",
    )
    with pytest.raises(
        FlattenError, match="role 'trigger' of module 'CrossingManeuver' is not bound"
    ):
        flatten(load(path).root)


def test_unknown_override_is_an_error(examples_copy: Path) -> None:
    path = _edit(
        examples_copy / "uis2-concrete.xmi", 'parameter="crossingSpeed"', 'parameter="pace"'
    )
    with pytest.raises(FlattenError, match="module 'CrossingManeuver' has no parameter 'pace'"):
        flatten(load(path).root)


def test_unwired_port_is_an_error(tmp_path: Path) -> None:
    library = LibraryBuilder("lib")
    broken = _module(library, "Broken")
    broken.add("Stop", broken.definition.roles[0])
    _save_libraries({tmp_path / "lib.xmi": library.library})
    scenario = _scenario_using(broken.definition, tmp_path / "scenario.xmi")
    with pytest.raises(FlattenError, match="module 'Broken': port 'In' is not wired"):
        flatten(load(scenario).root)


def test_a_module_passing_activation_straight_through_keeps_the_flow(tmp_path: Path) -> None:
    library = LibraryBuilder("lib")
    empty = _module(library, "Empty")
    empty.chain(empty.in_port, empty.out_port)
    b = ScenarioBuilder("Uses", level="functional")
    car = b.actor("Car", "ego", ego=True)
    stop = b.add("Stop", car)
    b.chain(b.root, b.use(empty.definition, {"driver": car}), stop, b.end)
    flat = flatten(b.scenario)
    by_name = {n.name: n for n in flat.nodes}
    assert set(by_name) == {"Root", "End", "Stop_1"}
    assert predecessors(by_name["Stop_1"]) == [by_name["Root"]]


def test_a_relative_position_naming_a_role_names_the_bound_actor_once_flattened(
    tmp_path: Path,
) -> None:
    lib = LibraryBuilder("Relative")
    module = lib.module("PullAhead")
    mover, leader = module.role("mover", "Car"), module.role("leader", "Car")
    ahead = relative_lane(leader, 0, 30.0)
    drive = module.add("Cross", mover, destination=ahead)
    near = module.add(
        "InLocationRadius", mover, position=relative_object(leader, 10.0, 0.0, h=0.1), radius=2.0
    )
    module.chain(module.in_port, drive, near, module.out_port)
    library_file = save(lib.library, tmp_path / "lib.xmi")
    definition = load(library_file).root.modules[0]
    b = ScenarioBuilder("Uses", map="../maps/intersection.xodr", level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=world(0.0, 0.0))
    car = b.actor("Car", "car", start=world(10.0, 0.0))
    use = b.use(definition, {"mover": ego, "leader": car})
    b.chain(b.root, use, b.end)
    flat = {n.name: n for n in flatten(b.scenario).nodes}
    destination = flat[f"{use.name}.{drive.name}"].destination
    position = flat[f"{use.name}.{near.name}"].position
    assert destination.entity.name == "car" and isinstance(destination.entity, scm.Actor)
    assert (destination.dLane, destination.ds.value) == (0, 30.0)
    assert position.entity.name == "car" and position.h.value == 0.1


def test_two_unnamed_uses_of_one_module_are_numbered_apart(tmp_path: Path) -> None:
    # The editor may leave a use unnamed; each then gets its own number, and its nodes theirs.
    library = LibraryBuilder("lib")
    module = _module(library, "Brake")
    stop = module.add("Stop", module.definition.roles[0])
    module.chain(module.in_port, stop, module.out_port)
    _save_libraries({tmp_path / "lib.xmi": library.library})
    b = ScenarioBuilder("Uses", level="functional")
    car = b.actor("Car", "ego", ego=True)
    first, second = (
        b.use(module.definition, {"driver": car}),
        b.use(module.definition, {"driver": car}),
    )
    b.chain(b.root, first, second, b.end)
    first.name = second.name = None
    save(b.scenario, tmp_path / "scenario.xmi")
    names = {str(n.name) for n in flatten(load(tmp_path / "scenario.xmi").root).nodes}
    assert {"Brake_1.Stop_1", "Brake_2.Stop_1"} <= names
    assert not any("~" in name for name in names)

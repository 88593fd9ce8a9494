"""sceml.diff.compare_files: changes by name and path, renames as renames, layout apart.

Every expected change below was worked out by hand from examples/uis2-logical.xmi.
"""

from __future__ import annotations

from pathlib import Path

from diff.conftest import actor, node

import scemlmodel as scm
from sceml.diff import compare_files
from sceml.diff.words import describe
from sceml.model import params
from sceml.model.loading import load_scenario
from sceml.model.saving import save


def lines(old: Path, new: Path) -> list[str]:
    return [describe(change) for change in compare_files(old, new).changes]


def test_the_same_file_has_no_changes(uis2: Path) -> None:
    assert compare_files(uis2, uis2).changes == []


def test_a_coordinate_change_is_one_change_by_name_path_and_unit(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        node(scenario, "TurnLeft_1").destination.x = params.value(-30.0)

    found = compare_files(uis2, edited(edit)).changes
    assert len(found) == 1
    change = found[0]
    assert (change.part, change.action, change.path) == (
        "nodes",
        "changed",
        "TurnLeft_1.destination.x",
    )
    assert (change.old, change.new, change.unit) == (("value", -34.0), ("value", -30.0), "m")
    assert describe(change) == "~ TurnLeft_1.destination.x: -34 -> -30 m"


def test_reordering_nodes_in_the_file_is_no_change(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        moved = node(scenario, "TurnLeft_1")
        scenario.nodes.remove(moved)
        scenario.nodes.insert(1, moved)

    new = edited(edit)
    assert new.read_bytes() != uis2.read_bytes()  # every reference after it is renumbered
    assert compare_files(uis2, new).changes == []


def test_a_renamed_node_is_a_rename_not_a_removal_and_an_addition(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        node(scenario, "TurnLeft_1").name = "EgoTurnsLeft"

    assert lines(uis2, edited(edit)) == ["~ TurnLeft_1 renamed to EgoTurnsLeft (TurnLeft)"]


def test_a_renamed_and_edited_node_keeps_its_identity(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        turn = node(scenario, "TurnLeft_1")
        turn.name = "EgoTurnsLeft"
        turn.tolerance = params.value(5.0)

    assert lines(uis2, edited(edit)) == [
        "~ TurnLeft_1 renamed to EgoTurnsLeft (TurnLeft)",
        "~ EgoTurnsLeft.tolerance: 3 -> 5 m",
    ]


def test_a_renamed_actor_does_not_change_the_nodes_that_refer_to_it(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        actor(scenario, "car").name = "oncoming"

    found = compare_files(uis2, edited(edit)).changes
    assert [(c.part, c.action, c.was, c.element) for c in found] == [
        ("actors", "renamed", "car", "oncoming")
    ]


def test_a_value_becoming_a_range_reads_as_both(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        node(scenario, "DriveDistance_1").distance = params.span(50.0, 70.0, 5.0)

    assert lines(uis2, edited(edit)) == ["~ DriveDistance_1.distance: 60 -> [50, 70] step 5 m"]


def test_a_removed_and_an_added_node_of_different_kinds(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        drive = node(scenario, "DriveDistance_1")
        for flow in [f for f in scenario.flows if drive in (f.source, f.target)]:
            scenario.flows.remove(flow)
        scenario.nodes.remove(drive)
        stop = scm.Stop(name="Stop_1", referenceActor=actor(scenario, "car"))
        scenario.nodes.append(stop)
        scenario.flows.append(scm.Flow(source=node(scenario, "InLocationRadius_2"), target=stop))

    assert lines(uis2, edited(edit)) == [
        "- DriveDistance_1 (DriveDistance) removed",
        "+ Stop_1 (Stop) added",
        "- InLocationRadius_2 -> DriveDistance_1 (flow) removed",
        "- DriveDistance_1 -> End (flow) removed",
        "+ InLocationRadius_2 -> Stop_1 (flow) added",
    ]


def test_module_use_bindings_and_overrides_by_role_and_parameter(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        use = node(scenario, "CrossingManeuver_1")
        next(b for b in use.bindings if b.role == "trigger").actor = actor(scenario, "ego")
        next(o for o in use.overrides if o.parameter == "destinationX").value = params.value(-12.0)

    found = compare_files(uis2, edited(edit)).changes
    assert [(c.part, c.path, describe(c)) for c in found] == [
        (
            "modules",
            "CrossingManeuver_1.bindings[trigger]",
            "~ CrossingManeuver_1.bindings[trigger]: car -> ego",
        ),
        (
            "modules",
            "CrossingManeuver_1.overrides[destinationX]",
            "~ CrossingManeuver_1.overrides[destinationX]: -10 -> -12",
        ),
    ]


def test_root_settings_and_layout_are_parts_of_their_own(uis2: Path, edited) -> None:
    def edit(scenario: scm.Scenario) -> None:
        root = node(scenario, "Root")
        root.maxDuration = params.value(90.0)
        node(scenario, "End").diagramPosition = scm.DiagramPosition(x=10.0, y=400.0)

    found = compare_files(uis2, edited(edit)).changes
    assert [(c.part, describe(c)) for c in found] == [
        ("root", "~ Root.maxDuration: 60 -> 90 s"),
        ("layout", "~ End moved auto -> (10, 400)"),
    ]


def test_a_missing_side_lists_everything_as_added_or_removed(uis2: Path) -> None:
    added = compare_files(None, uis2).changes
    removed = compare_files(uis2, None).changes
    # UIS2: 3 actors, 8 nodes (root, end, 5 action nodes, one module use), 9 flows.
    assert sum(c.action == "added" for c in added) == len(added) == 3 + 8 + 9
    assert {c.action for c in removed} == {"removed"} and len(removed) == 20


def test_a_file_of_an_older_metamodel_release_is_compared_after_migration(
    examples_copy: Path,
) -> None:
    kept = Path(__file__).resolve().parents[2] / "metamodel/history/1.0/examples"
    old = examples_copy / "uis2-release-1.0.xmi"
    old.write_bytes((kept / "uis2-logical.xmi").read_bytes())
    assert "metamodel/1.0" in old.read_text()
    current = load_scenario(old).root  # migrated in memory
    node(current, "TurnLeft_1").tolerance = params.value(5.0)
    new = save(current, examples_copy / "uis2-current.xmi")
    assert "metamodel/1.0" not in new.read_text()
    assert lines(old, new) == ["~ TurnLeft_1.tolerance: 3 -> 5 m"]

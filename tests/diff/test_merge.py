"""sceml merge: independent edits join, the same edit twice is one, conflicts are refused whole."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from diff.conftest import actor, node

import scemlmodel as scm
from sceml.cli import cli
from sceml.diff import compare_files
from sceml.diff.words import describe
from sceml.model import params
from sceml.model.loading import load_scenario


def merge(base: Path, ours: Path, theirs: Path, out: Path) -> tuple[int, str]:
    result = CliRunner().invoke(cli, ["merge", str(base), str(ours), str(theirs), "-o", str(out)])
    return result.exit_code, result.output


def _longer_drive(scenario: scm.Scenario) -> None:
    node(scenario, "DriveDistance_1").distance = params.value(70.0)


def _wider_turn(scenario: scm.Scenario) -> None:
    node(scenario, "TurnLeft_1").tolerance = params.value(5.0)


def test_changes_to_different_things_merge(uis2: Path, edited) -> None:
    def theirs_edit(scenario: scm.Scenario) -> None:
        _wider_turn(scenario)
        node(scenario, "InLocationRadius_1").name = "EgoArrived"
        actor(scenario, "pedestrian").name = "walker"

    ours = edited(_longer_drive, "ours.xmi")
    theirs = edited(theirs_edit, "theirs.xmi")
    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, ours, theirs, out)
    assert code == 0, shown
    assert sorted(describe(c) for c in compare_files(uis2, out).changes) == [
        "~ DriveDistance_1.distance: 60 -> 70 m",
        "~ InLocationRadius_1 renamed to EgoArrived (InLocationRadius)",
        "~ TurnLeft_1.tolerance: 3 -> 5 m",
        "~ pedestrian renamed to walker (Pedestrian)",
    ]
    # The module use still binds the renamed actor: one object, renamed, not a copy.
    merged = load_scenario(out).root
    use = node(merged, "CrossingManeuver_1")
    assert next(b for b in use.bindings if b.role == "crosser").actor is actor(merged, "walker")


def test_the_same_change_on_both_sides_is_one_change(uis2: Path, edited) -> None:
    ours = edited(_longer_drive, "ours.xmi")
    theirs = edited(_longer_drive, "theirs.xmi")
    out = uis2.with_name("merged.xmi")
    assert merge(uis2, ours, theirs, out)[0] == 0
    assert [describe(c) for c in compare_files(uis2, out).changes] == [
        "~ DriveDistance_1.distance: 60 -> 70 m"
    ]


def test_an_added_node_and_its_flows_come_across(uis2: Path, edited) -> None:
    def theirs_edit(scenario: scm.Scenario) -> None:
        drive, end = node(scenario, "DriveDistance_1"), node(scenario, "End")
        flow = next(f for f in scenario.flows if (f.source, f.target) == (drive, end))
        stop = scm.Stop(name="Stop_1", referenceActor=actor(scenario, "car"))
        scenario.nodes.append(stop)
        flow.target = stop
        scenario.flows.append(scm.Flow(source=stop, target=end))

    out = uis2.with_name("merged.xmi")
    code, shown = merge(
        uis2, edited(_longer_drive, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out
    )
    assert code == 0, shown
    assert sorted(describe(c) for c in compare_files(uis2, out).changes) == [
        "+ DriveDistance_1 -> Stop_1 (flow) added",
        "+ Stop_1 (Stop) added",
        "+ Stop_1 -> End (flow) added",
        "- DriveDistance_1 -> End (flow) removed",
        "~ DriveDistance_1.distance: 60 -> 70 m",
    ]
    merged = load_scenario(out).root
    assert node(merged, "Stop_1").referenceActor is actor(merged, "car")


def test_two_values_for_one_parameter_conflict_and_nothing_is_written(uis2: Path, edited) -> None:
    def other_value(scenario: scm.Scenario) -> None:
        node(scenario, "DriveDistance_1").distance = params.value(80.0)

    ours = edited(_longer_drive, "ours.xmi")
    before = ours.read_bytes()
    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, ours, edited(other_value, "theirs.xmi"), ours)
    assert code == 1
    assert (
        "conflict: DriveDistance_1.distance: changed differently (ours: 70 m; theirs: 80 m)"
        in shown
    )
    assert ours.read_bytes() == before and not out.exists()


def test_a_node_deleted_on_one_side_and_edited_on_the_other_conflicts(uis2: Path, edited) -> None:
    def delete(scenario: scm.Scenario) -> None:
        drive = node(scenario, "DriveDistance_1")
        for flow in [f for f in scenario.flows if drive in (f.source, f.target)]:
            flow.target = node(scenario, "End") if flow.source is not drive else flow.target
            if flow.source is drive:
                scenario.flows.remove(flow)
        scenario.nodes.remove(drive)

    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, edited(_longer_drive, "ours.xmi"), edited(delete, "theirs.xmi"), out)
    assert code == 1
    assert "DriveDistance_1: edited by ours, deleted by theirs" in shown
    assert not out.exists()


def test_flows_that_together_make_a_cycle_conflict(uis2: Path, edited) -> None:
    # Each side alone has no cycle: ours adds TurnLeft_1 -> InLocationRadius_2 (two branches
    # meet), theirs InLocationRadius_2 -> Accelerate_1, which leads to TurnLeft_1.
    def forward(scenario: scm.Scenario) -> None:
        scenario.flows.append(
            scm.Flow(
                source=node(scenario, "TurnLeft_1"), target=node(scenario, "InLocationRadius_2")
            )
        )

    def back(scenario: scm.Scenario) -> None:
        scenario.flows.append(
            scm.Flow(
                source=node(scenario, "InLocationRadius_2"), target=node(scenario, "Accelerate_1")
            )
        )

    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, edited(forward, "ours.xmi"), edited(back, "theirs.xmi"), out)
    assert code == 1
    assert "together make a cycle" in shown
    assert "flows among Accelerate_1, InLocationRadius_2, TurnLeft_1:" in shown
    assert not out.exists()


def test_changes_that_together_break_a_rule_conflict(uis2: Path, edited) -> None:
    # Each side hands the ego role to a different actor: one ego on each side, two together.
    def ours_edit(scenario: scm.Scenario) -> None:
        actor(scenario, "ego").isEgo = False
        actor(scenario, "car").isEgo = True

    def theirs_edit(scenario: scm.Scenario) -> None:
        actor(scenario, "ego").isEgo = False
        actor(scenario, "pedestrian").isEgo = True

    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, edited(ours_edit, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out)
    assert code == 1
    assert "together the changes break a rule: SCEML-A" in shown and "ego" in shown
    assert not out.exists()


def test_a_new_name_taken_on_the_other_side_conflicts(uis2: Path, edited) -> None:
    def ours_edit(scenario: scm.Scenario) -> None:
        actor(scenario, "car").name = "other"

    def theirs_edit(scenario: scm.Scenario) -> None:
        actor(scenario, "pedestrian").name = "other"

    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, edited(ours_edit, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out)
    assert code == 1
    assert "theirs' new name is taken by ours (ours: pedestrian; theirs: other)" in shown


def test_renamed_differently_on_both_sides_conflicts(uis2: Path, edited) -> None:
    def name(new: str):
        def edit(scenario: scm.Scenario) -> None:
            node(scenario, "TurnLeft_1").name = new

        return edit

    out = uis2.with_name("merged.xmi")
    code, shown = merge(
        uis2, edited(name("Left"), "ours.xmi"), edited(name("Turn"), "theirs.xmi"), out
    )
    assert code == 1
    assert "renamed differently (ours: Left; theirs: Turn)" in shown


def test_a_binding_and_an_override_of_one_module_use_merge(uis2: Path, edited) -> None:
    def ours_edit(scenario: scm.Scenario) -> None:
        use = node(scenario, "CrossingManeuver_1")
        next(b for b in use.bindings if b.role == "trigger").actor = actor(scenario, "ego")

    def theirs_edit(scenario: scm.Scenario) -> None:
        use = node(scenario, "CrossingManeuver_1")
        next(o for o in use.overrides if o.parameter == "destinationX").value = params.value(-12.0)
        node(scenario, "TurnLeft_1").destination = scm.LanePosition(
            roadId="2", laneId=-1, s=params.value(5.0)
        )

    out = uis2.with_name("merged.xmi")
    code, shown = merge(uis2, edited(ours_edit, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out)
    assert code == 0, shown
    merged = load_scenario(out).root
    use = node(merged, "CrossingManeuver_1")
    assert next(b for b in use.bindings if b.role == "trigger").actor is actor(merged, "ego")
    override = next(o for o in use.overrides if o.parameter == "destinationX")
    assert override.value.value == -12.0
    assert len(use.overrides) == 5  # replaced in place of the old one, not added beside it
    destination = node(merged, "TurnLeft_1").destination
    assert isinstance(destination, scm.LanePosition)
    assert (destination.roadId, destination.laneId, destination.s.value) == ("2", -1, 5.0)


def test_an_added_actor_and_a_node_of_it_come_across_together(uis2: Path, edited) -> None:
    def theirs_edit(scenario: scm.Scenario) -> None:
        truck = scm.Truck(name="truck", initialSpeed=params.value(8.0))
        node(scenario, "Root").actors.append(truck)
        scenario.nodes.append(scm.KeepVelocity(name="KeepVelocity_1", referenceActor=truck))
        scenario.flows.append(scm.Flow(source=node(scenario, "Root"), target=scenario.nodes[-1]))
        scenario.flows.append(scm.Flow(source=scenario.nodes[-1], target=node(scenario, "End")))

    out = uis2.with_name("merged.xmi")
    code, shown = merge(
        uis2, edited(_longer_drive, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out
    )
    assert code == 0, shown
    merged = load_scenario(out).root
    assert node(merged, "KeepVelocity_1").referenceActor is actor(merged, "truck")
    assert actor(merged, "truck").initialSpeed.value == 8.0


def test_an_actor_removed_by_theirs_goes_with_its_references(uis2: Path, edited) -> None:
    def theirs_edit(scenario: scm.Scenario) -> None:
        car = actor(scenario, "car")
        node(scenario, "DriveDistance_1").referenceActor = actor(scenario, "ego")
        use = node(scenario, "CrossingManeuver_1")
        next(b for b in use.bindings if b.role == "trigger").actor = actor(scenario, "ego")
        node(scenario, "Root").actors.remove(car)

    out = uis2.with_name("merged.xmi")
    code, shown = merge(
        uis2, edited(_wider_turn, "ours.xmi"), edited(theirs_edit, "theirs.xmi"), out
    )
    assert code == 0, shown
    merged = load_scenario(out).root
    assert [a.name for a in node(merged, "Root").actors] == ["ego", "pedestrian"]
    assert node(merged, "DriveDistance_1").referenceActor is actor(merged, "ego")
    assert node(merged, "TurnLeft_1").tolerance.value == 5.0

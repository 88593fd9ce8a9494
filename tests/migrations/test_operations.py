"""Each migration operation on a file saved with release 1.0 (UIS2), checked element by element.

The expected texts come from reading examples/uis2-concrete.xmi of release 1.0 by hand: line 2 is
the Scenario, the ego's Accelerate_1 is node 2 (line 26), TurnLeft_1 node 3 (line 33), the End
node 1 (line 27), the ModuleUse node 7 (line 64).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree
from metamodel_releases import HISTORY_10

from sceml.errors import LoadError
from sceml.migrations import ecore
from sceml.migrations.operations import COMPUTED
from sceml.migrations.report import Change
from sceml.migrations.steps import Step, read_step
from sceml.migrations.tree import XSI_TYPE, TreeModel

UIS2 = HISTORY_10 / "examples" / "uis2-concrete.xmi"
RELEASE_10 = ecore.read(HISTORY_10 / "scemlmodel.ecore")


def run(
    tmp_path: Path, operations: str, source: Path = UIS2
) -> tuple[etree._Element, list[Change]]:
    """Apply a step of `operations` (YAML) to a 1.0 file; the model root and the changes."""
    migration = tmp_path / "1.0-to-1.2.yaml"
    migration.write_text(f'from: "1.0"\nto: "1.2"\noperations:\n{operations}', encoding="utf-8")
    step = read_step(migration)
    root = etree.parse(str(source)).getroot()
    changes = step.apply(TreeModel.of(root, RELEASE_10))
    return root, changes


def node(root: etree._Element, name: str) -> etree._Element:
    [found] = root.xpath(f"nodes[@name='{name}']")
    return found


def kind(element: etree._Element) -> str:
    return element.get(XSI_TYPE, "")


def test_rename_class(tmp_path: Path) -> None:
    root, changes = run(tmp_path, "  - rename_class: {from: DriveDistance, to: DriveFor}\n")
    assert kind(node(root, "DriveDistance_1")) == "scemlmodel:DriveFor"
    assert [(c.element, c.line, c.detail) for c in changes] == [
        ("DriveDistance_1", 60, "DriveDistance -> DriveFor")
    ]


def test_rename_class_of_the_root_renames_its_tag(tmp_path: Path) -> None:
    root, changes = run(tmp_path, "  - rename_class: {from: Scenario, to: Story}\n")
    assert etree.QName(root).localname == "Story" and changes[0].line == 2


def test_rename_containment_keeps_every_reference_into_it(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path, "  - rename_feature: {class: RootNode, from: actors, to: participants}\n"
    )
    assert [c.tag for c in node(root, "Root")].count("participants") == 3
    assert node(root, "DriveDistance_1").get("referenceActor") == "//@nodes.0/@participants.1"
    crossing = node(root, "CrossingManeuver_1")
    assert [b.get("actor") for b in crossing.iterchildren("bindings")] == [
        "//@nodes.0/@participants.2",
        "//@nodes.0/@participants.1",
    ]
    assert [(c.element, c.detail) for c in changes] == [("Root", "actors -> participants")]


def test_rename_attribute_on_subclasses(tmp_path: Path) -> None:
    root, _ = run(
        tmp_path, "  - rename_feature: {class: ActionNode, from: referenceActor, to: by}\n"
    )
    assert node(root, "TurnLeft_1").get("by") == "//@nodes.0/@actors.0"
    assert node(root, "TurnLeft_1").get("referenceActor") is None


def test_move_feature_into_a_new_element(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        "  - move_feature: {class: Actor, feature: initialSpeed, into: motion, into_type: Motion}\n",
    )
    ego = node(root, "Root").find("actors")
    assert ego.find("initialSpeed") is None
    [motion] = ego.iterchildren("motion")
    assert kind(motion) == "scemlmodel:Motion"
    assert motion.find("initialSpeed").get("value") == "5.0"
    assert [c.element for c in changes] == ["Root/ego", "Root/car", "Root/pedestrian"]


def test_add_feature_with_a_default_a_contained_value_and_a_computed_value(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(COMPUTED, "actor_count", lambda e, m: str(len(e.findall("actors"))))
    root, changes = run(
        tmp_path,
        "  - add_feature: {class: EndNode, feature: label, default: finish}\n"
        '  - add_feature: {class: Accelerate, feature: jerk, default: {type: Value, value: "1.5"}}\n'
        "  - add_feature: {class: RootNode, feature: actorCount, compute: actor_count}\n",
    )
    assert node(root, "End").get("label") == "finish"
    jerk = node(root, "Accelerate_1").find("jerk")
    assert (kind(jerk), jerk.get("value")) == ("scemlmodel:Value", "1.5")
    assert node(root, "Root").get("actorCount") == "3"
    assert [c.detail for c in changes] == [
        "label = 'finish'",
        "jerk = Value value=1.5",
        "actorCount = '3' (computed)",
    ]


def test_make_required_fills_only_what_is_unset(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        '  - make_required: {class: Actor, feature: length, default: {type: Value, value: "4.5"}}\n'
        '  - make_required: {class: Accelerate, feature: rate, default: {type: Value, value: "9"}}\n',
    )
    assert [a.find("length").get("value") for a in node(root, "Root").iterchildren("actors")] == [
        "4.5"
    ] * 3
    assert node(root, "Accelerate_1").find("rate").get("value") == "2.0"  # was set: kept
    assert len(changes) == 3


def test_split_class_by_a_feature(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        "  - split_class: {class: EndNode, by: policy, into: {joinOne: EndOnFirst}, "
        "otherwise: EndOnAll}\n",
    )
    end = node(root, "End")
    assert kind(end) == "scemlmodel:EndOnAll" and end.get("policy") is None
    assert [c.detail for c in changes] == ["EndNode (policy=joinAll) -> EndOnAll"]


def test_merge_classes_recording_which(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        "  - merge_classes: {classes: [TurnLeft, TurnRight], into: Turn, record: side, "
        "values: {TurnLeft: left, TurnRight: right}}\n",
    )
    turn = node(root, "TurnLeft_1")
    assert (kind(turn), turn.get("side")) == ("scemlmodel:Turn", "left")
    assert [(c.line, c.detail) for c in changes] == [(33, "TurnLeft -> Turn (side=left)")]


def test_change_type_by_scale_by_map_and_keeping_the_first(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        "  - change_type: {class: DiagramPosition, feature: x, to: EInt, convert: {scale: 2}}\n"
        "  - change_type: {class: Environment, feature: cloudState, to: Sky, "
        "convert: {map: {free: clear}}}\n"
        "  - change_type: {class: ModuleUse, feature: bindings, to: RoleBinding, "
        "convert: {first: true}}\n",
    )
    environment = node(root, "Root").find("environment")
    assert environment.get("cloudState") == "clear"
    crossing = node(root, "CrossingManeuver_1")
    assert [b.get("role") for b in crossing.iterchildren("bindings")] == ["crosser"]
    assert [c.detail for c in changes] == [
        "cloudState: 'free' -> 'clear' (Sky)",
        "bindings: dropped a second value (RoleBinding)",
    ]


def test_rename_literal(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path, "  - rename_literal: {enum: JoinPolicy, from: joinAll, to: all}\n"
    )
    assert node(root, "End").get("policy") == "all"
    assert [(c.element, c.detail) for c in changes] == [("End", "policy: joinAll -> all")]


def test_delete_feature_says_what_was_lost(tmp_path: Path) -> None:
    root, changes = run(
        tmp_path,
        "  - delete_feature: {class: Actor, feature: model, note: models are per profile}\n",
    )
    assert all(a.get("model") is None for a in node(root, "Root").iterchildren("actors"))
    assert changes[0].detail == "model ('vehicle.tesla.model3') removed"
    assert changes[0].note == "models are per profile"


def test_delete_class_drops_references_to_it_and_renumbers_the_rest(tmp_path: Path) -> None:
    root, changes = run(tmp_path, "  - delete_class: {class: EndNode, note: ends are implicit}\n")
    assert not root.xpath("nodes[@name='End']")
    flows = [(f.get("source"), f.get("target")) for f in root.iterchildren("flows")]
    # Before: 0->2, 2->3, 3->4, 4->1 (End), ...; node 1 is gone, so 2 is now 1, and so on.
    assert flows[:4] == [
        ("//@nodes.0", "//@nodes.1"),
        ("//@nodes.1", "//@nodes.2"),
        ("//@nodes.2", "//@nodes.3"),
        ("//@nodes.3", None),
    ]
    assert node(root, "DriveDistance_1").get("referenceActor") == "//@nodes.0/@actors.1"
    assert changes[0].detail == "EndNode removed" and changes[0].note == "ends are implicit"
    dropped = [c for c in changes if "dropped" in c.detail]
    assert len(dropped) == 3 and all(c.element.startswith("flows[") for c in dropped)


def test_a_wrong_migration_file_is_named_with_its_operation(tmp_path: Path) -> None:
    with pytest.raises(
        LoadError, match=r"operation 2 \(rename_clas\): unknown operation"
    ) as caught:
        run(
            tmp_path,
            "  - rename_class: {from: A, to: B}\n  - rename_clas: {from: A, to: B}\n",
        )
    assert caught.value.file is not None and caught.value.file.endswith("1.0-to-1.2.yaml")
    with pytest.raises(LoadError, match=r"operation 1 \(delete_class\): 'note'"):
        run(tmp_path, "  - delete_class: {class: EndNode}\n")


def test_the_shipped_steps_read_and_name_only_what_exists() -> None:
    from sceml.migrations import installed

    history = installed()
    for version, step in history.steps().items():
        assert isinstance(step, Step)
        assert (
            step.problems(history.metamodel_of(version), history.metamodel_of(step.to_release))
            == []
        )

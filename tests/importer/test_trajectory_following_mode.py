"""A trajectory's following mode (issue 24, release 1.4's FollowTrajectory.followingMode):
files/trajectory-follow-mode.xosc follows its polyline in `follow` mode, pedestrian-crossing.xosc
(the same file otherwise) in `position` mode; each imports with its mode, exports it back at
1.1 to 1.3 (XSD-valid) and imports again to the same scenario."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model.loading import load
from sceml.xosc import schema

FILES = Path(__file__).parent / "files"


def modes(path: Path) -> list[str]:
    return [
        str(m.get("followingMode")) for m in etree.parse(str(path)).iter("TrajectoryFollowingMode")
    ]


@pytest.mark.parametrize(
    ("name", "mode"), (("trajectory-follow-mode", "follow"), ("pedestrian-crossing", "position"))
)
def test_the_following_mode_is_kept(name: str, mode: str) -> None:
    imported = import_file(FILES / f"{name}.xosc")
    walks = [n for n in imported.scenario.nodes if n.eClass.name == "FollowTrajectory"]
    assert [n.followingMode.name for n in walks] == [mode]


@pytest.mark.parametrize("version", ("1.1", "1.2", "1.3"))
def test_follow_mode_exports_as_it_was_read(version: str, tmp_path: Path) -> None:
    source = FILES / "trajectory-follow-mode.xosc"
    assert modes(source) == ["follow"]
    model = tmp_path / "follow.xmi"
    import_to_file(source, model)
    exported = tmp_path / "follow.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    assert modes(exported) == ["follow"]
    # Read again: the same kinds of node, joins aside (the opaque VisibilityActions come back under the
    # export's action names, so the whole scenarios are not compared), the walk in follow mode.
    first, again = import_file(source).scenario, import_file(exported).scenario
    assert kinds(again) == kinds(first)
    walks = [n for n in again.nodes if n.eClass.name == "FollowTrajectory"]
    assert [n.followingMode.name for n in walks] == ["follow"]


def kinds(scenario: object) -> list[str]:
    """The kinds of its nodes but the joins: the walk's own join (its speed change and path)
    comes back folded into the join of the act's end."""
    nodes = scenario.nodes  # type: ignore[attr-defined]
    return sorted(str(n.eClass.name) for n in nodes if n.eClass.name != "JoinAllFinished")

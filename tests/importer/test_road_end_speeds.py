"""A speed change after its actor stood is read from 0 m/s (issue 24, `lane_change_simple`):
files/road-end-speeds.xosc drives a car off the end of its road at 25 m/s; the end of the road
(held 1 s) puts it back twice and speeds it up to 20 m/s in 4 s once; a second act, once the
first is over, speeds it up to 15 m/s in 3 s.

Worked by hand: esmini stops a car at the end of its road, so SpeedUp is 0 to 20 m/s in 4 s, a
rate of 5 m/s²; the second run of the teleport has no speed change beside it, so the car
stands when the second act begins: Again is 0 to 15 m/s in 3 s, 5 m/s² too. esmini 3.6 plays
them so (20 m/s at 9.0 s, 1 s at the end of the road from 4.0 s, then 4 s; 14.75 m/s at 57.0 s)
and plays this re-export the same. Read from the last speed set (25, then 20 m/s), both were
Decelerates, at 1.25 and 1.67 m/s²."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.xosc import schema

FILE = Path(__file__).parent / "files" / "road-end-speeds.xosc"


def test_the_changes_start_from_standing() -> None:
    imported = import_file(FILE)
    nodes = {str(n.name): n for n in imported.scenario.nodes}
    for name, target in (("SpeedUp", 20.0), ("Again", 15.0)):
        assert isinstance(nodes[name], scm.Accelerate)
        assert nodes[name].targetSpeed.value == target
        assert nodes[name].rate.value == pytest.approx(5.0)
    guessed = [e.message for e in imported.report.entries if e.section == "guessed"]
    assert any(m.startswith("SpeedUp: Ego's speed before taken as 0 m/s") for m in guessed)
    assert any(m.startswith("Ego stands at the end of its road after") for m in guessed)


def test_a_car_put_back_as_often_as_it_speeds_up_drives_on(tmp_path: Path) -> None:
    # The teleport runs once, as often as the speed change beside it: the trigger's last run
    # leaves the car driving, and the second act's change reads from the last speed set.
    text = FILE.read_text().replace(
        '<AbsoluteTargetSpeed value="20"/>', '<AbsoluteTargetSpeed value="22"/>'
    )
    changed = tmp_path / FILE.name
    changed.write_text(text.replace('maximumExecutionCount="2"', 'maximumExecutionCount="1"'))
    (tmp_path / "highway.xodr").symlink_to(FILE.parent / "highway.xodr")
    (tmp_path / "catalogs").symlink_to(FILE.parent / "catalogs")
    scenario = import_file(changed, allow=[FILE.parent]).scenario
    nodes = {str(n.name): n for n in scenario.nodes}
    assert nodes["SpeedUp"].rate.value == pytest.approx(22.0 / 4)
    assert isinstance(nodes["Again"], scm.Decelerate)
    assert nodes["Again"].rate.value == pytest.approx((22.0 - 15.0) / 3)


@pytest.mark.parametrize("version", ("1.0", "1.2"))
def test_the_rates_go_back_as_rates(version: str, tmp_path: Path) -> None:
    # The end of the road and the teleport stay opaque (their source lines and action names
    # change on the way), so the round trip is compared on what is mapped.
    first = import_file(FILE).scenario
    exported = tmp_path / FILE.name
    export_to_file(first, exported, version=version, source_path=FILE)
    assert schema.validate_file(exported, version) == []
    again = {str(n.name): n for n in import_file(exported, allow=[FILE.parent]).scenario.nodes}
    for name, target in (("SpeedUp", 20.0), ("Again", 15.0)):
        assert isinstance(again[name], scm.Accelerate)
        assert (again[name].targetSpeed.value, again[name].rate.value) == (target, 5.0)
    assert again["BackToStart"].maxRuns == 2

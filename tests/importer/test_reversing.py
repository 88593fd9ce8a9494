"""Reversing (release 1.4): a negative target or compared speed is driving backwards, as in
OpenSCENARIO. It imports as it stands, validates (SCEML-P007 no longer refuses it; the plausibility
limits judge its size), exports back at every version, and the preview drives backwards.

The figures below were worked out by hand for `files/reversing.xosc` and agree with esmini 3.6's
run of it (--fixed_timestep 0.05): Ego, at 5 m/s from s = 50, slows at 2 m/s² from 1 s, stands at
3.5 s (s = 55 + 5 * 2.5 / 2 = 61.25) and reaches -3 m/s at 5 s (s = 61.25 - 3 * 1.5 / 2 = 59),
then reverses at 3 m/s: s = 53 at 7 s (esmini: 52.8, its speed a step ahead). Its speed first
falls below -2 m/s in the step after 4.5 s, at 4.55 s, when Lead sets off (esmini: 4.55 s).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.render.labels import Scope, parameter_items
from sceml.simulate import simulate
from sceml.validation import validate
from sceml.xosc import schema

SOURCE = Path(__file__).parent / "files" / "reversing.xosc"
STEP = 0.05


def _node(scenario: scm.Scenario, name: str) -> scm.ActionNode:
    return next(n for n in scenario.nodes if n.name == name)


def _speeds(path: Path) -> dict[str, float]:
    """Each speed action's target and each speed condition's value, by the event or condition."""
    found = {}
    for event in etree.parse(str(path)).iter("Event"):
        for target in event.iter("AbsoluteTargetSpeed"):
            found[str(event.get("name"))] = float(str(target.get("value")))
    for condition in etree.parse(str(path)).iter("SpeedCondition"):
        found["condition"] = float(str(condition.get("value")))
    return found


def test_negative_speeds_import_as_they_are_and_validate() -> None:
    scenario = import_file(SOURCE).scenario
    reverse = _node(scenario, "Reverse")
    assert isinstance(reverse, scm.Decelerate) and reverse.targetSpeed.value == -3.0
    compared = _node(scenario, "EgoReversesFast")
    assert isinstance(compared, scm.SpeedCondition) and compared.speed.value == -2.0
    assert compared.rule == scm.ComparisonRule.lessThan
    assert [d.code for d in validate(scenario) if d.severity.name == "ERROR"] == []


@pytest.mark.parametrize("version", ("1.0", "1.1", "1.2", "1.3"))
def test_they_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    model = tmp_path / "reversing.xmi"
    import_to_file(SOURCE, model)
    exported = tmp_path / "reversing.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    assert _speeds(SOURCE) == {"Reverse": -3.0, "LeadSetsOff": 10.0, "condition": -2.0}
    assert _speeds(exported) == _speeds(SOURCE)
    first, again = import_file(SOURCE).scenario, import_file(exported).scenario
    for scenario in (first, again):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first, again)


def test_the_preview_drives_backwards() -> None:
    run = simulate(import_file(SOURCE).scenario, SOURCE)
    ego = run.actor_index("Ego")

    def at(t: float) -> np.ndarray:
        return run.states[ego, int(np.argmin(np.abs(run.times - t)))]

    assert at(3.5)[0] == pytest.approx(61.25, abs=1e-6)  # standing, furthest on
    assert at(5.0)[0] == pytest.approx(59.0, abs=1e-6)
    assert at(7.0)[0] == pytest.approx(53.0, abs=1e-6)
    assert at(7.0)[3] == pytest.approx(-3.0)
    assert at(7.0)[2] == pytest.approx(0.0)  # facing the way it came: backwards, not turned
    assert run.node("Reverse").finished == pytest.approx(5.0)
    assert run.node("LeadSetsOff").started == pytest.approx(4.5 + STEP)


def test_labels_say_reverse() -> None:
    scenario = import_file(SOURCE).scenario
    reverse = dict(parameter_items(_node(scenario, "Reverse"), Scope()))
    assert reverse["targetSpeed"] == "reverse at 3 m/s = 10.8 km/h"
    compared = dict(parameter_items(_node(scenario, "EgoReversesFast"), Scope()))
    assert compared["speed"] == "-2 m/s = -7.2 km/h (reversing)"


def test_limits_judge_the_size_of_a_reverse_speed() -> None:
    scenario = import_file(SOURCE).scenario
    _node(scenario, "Reverse").targetSpeed.value = -80.0  # a car's limit is 70 m/s
    codes = {d.code for d in validate(scenario)}
    assert "SCEML-L001" in codes and "SCEML-P007" not in codes


def test_a_speed_to_drive_a_distance_at_stays_at_least_zero() -> None:
    scenario = import_file(SOURCE).scenario
    drive = scm.DriveDistance(name="Drive", speed=scm.Value(value=-2.0))
    drive.distance = scm.Value(value=10.0)
    drive.referenceActor = graph.root_node(scenario).actors[0]
    scenario.nodes.append(drive)
    assert any(d.code == "SCEML-P007" and "Drive.speed" in d.message for d in validate(scenario))

"""Applying sample values: the in-place flattened template equals flatten(apply(...))."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.levels.apply import FlatTemplate, apply
from sceml.levels.paths import LevelError
from sceml.levels.sampling import Plan, design
from sceml.levels.space import parameter_space
from sceml.model.compare import differences
from sceml.model.loading import load_scenario
from sceml.model.locating import model_path
from sceml.modules.flatten import flatten

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("name", ["uis1-logical.xmi", "uis2-logical.xmi"])
def test_template_equals_flatten_of_apply(name: str) -> None:
    logical = load_scenario(EXAMPLES / name).root
    space = parameter_space(logical)
    template = FlatTemplate(logical, space.paths)
    for row in design(space, Plan("random", 4, seed=9)):
        values = dict(zip(space.paths, (float(v) for v in row), strict=True))
        expected = flatten(apply(logical, values))
        assert differences(template.fill(row), expected) == []


def test_module_parameter_fills_every_place_it_is_used() -> None:
    logical = load_scenario(EXAMPLES / "uis2-logical.xmi").root
    paths = [*parameter_space(logical).paths, "CrossingManeuver_1.destinationX"]
    template = FlatTemplate(logical, paths)
    flat = template.fill([5.0] * (len(paths) - 1) + [-12.5])
    # destinationX is used by the Cross maneuver's destination and the arrival condition.
    names = sorted(model_path(v) for v in template.slots_of(len(paths) - 1))
    assert names == [
        "CrossingManeuver_1.Cross_1/destination/x",
        "CrossingManeuver_1.InLocationRadius_1/position/x",
    ]
    cross = next(n for n in flat.nodes if n.name == "CrossingManeuver_1.Cross_1")
    assert cross.destination.x.value == -12.5


def test_apply_gives_a_concrete_copy_and_leaves_the_input() -> None:
    logical = load_scenario(EXAMPLES / "uis2-logical.xmi").root
    space = parameter_space(logical)
    values = dict.fromkeys(space.paths, 5.0)
    concrete = apply(logical, values)
    assert concrete.nodes[0].level == scm.AbstractionLevel.concrete
    assert logical.nodes[0].level == scm.AbstractionLevel.logical
    assert isinstance(logical.nodes[0].actors[0].initialSpeed, scm.Range)
    override = concrete.nodes[-1].overrides[1]
    assert override.parameter == "crossingSpeed" and override.value.value == 5.0


def test_apply_needs_every_varied_value() -> None:
    logical = load_scenario(EXAMPLES / "uis2-logical.xmi").root
    with pytest.raises(LevelError, match="DriveDistance_1.speed"):
        apply(logical, {"ego.initialSpeed": 4.0})


def test_template_follows_overrides_through_modules_nested_three_deep() -> None:
    logical = load_scenario(EXAMPLES / "overtaking-logical.xmi").root
    space = parameter_space(logical)
    template = FlatTemplate(logical, space.paths)
    for row in design(space, Plan("random", 3, seed=4)):
        values = dict(zip(space.paths, (float(v) for v in row), strict=True))
        assert differences(template.fill(row), flatten(apply(logical, values))) == []
    speed = space.paths.index("Overtaking_1.passingSpeed")
    assert [model_path(v) for v in template.slots_of(speed)] == [
        "Overtaking_1.PassVehicle_1.Accelerate_1/targetSpeed"
    ]


def test_no_number_is_reserved_for_finding_where_values_land() -> None:
    # The template once marked varied slots with a sentinel number and refused models using it.
    logical = load_scenario(EXAMPLES / "uis2-logical.xmi").root
    next(n for n in logical.nodes if n.name == "DriveDistance_1").distance.value = -1.5e300
    space = parameter_space(logical)
    template = FlatTemplate(logical, space.paths)
    row = [5.0] * len(space.paths)
    expected = flatten(apply(logical, dict(zip(space.paths, row, strict=True))))
    assert differences(template.fill(row), expected) == []

"""Parameter paths and the parameter space of the example logical scenarios."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.levels.paths import UnknownPathError, resolve, slots
from sceml.levels.space import grid_levels, parameter_space
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture
def uis2() -> scm.Scenario:
    return load_scenario(EXAMPLES / "uis2-logical.xmi").root


def test_paths_cover_nodes_actors_positions_and_module_parameters(uis2: scm.Scenario) -> None:
    known = slots(uis2)
    for path in (
        "Root.maxDuration",
        "ego.initialSpeed",
        "ego.startPosition.s",
        "Accelerate_1.targetSpeed",
        "InLocationRadius_2.position.x",
        "CrossingManeuver_1.crossingSpeed",
        "CrossingManeuver_1.arrivalRadius",
    ):
        assert path in known
    assert isinstance(known["InLocationRadius_2.radius"].held(), scm.Range)
    # A module parameter without an override reads the module's default (2.0 in the library).
    arrival = known["CrossingManeuver_1.arrivalRadius"].held()
    assert isinstance(arrival, scm.Value) and arrival.value == 2.0


def test_actor_prefixed_path_is_accepted(uis2: scm.Scenario) -> None:
    slot = resolve(uis2, "ego.Accelerate_1.targetSpeed")
    assert slot.path == "Accelerate_1.targetSpeed"
    with pytest.raises(UnknownPathError):
        resolve(uis2, "car.Accelerate_1.targetSpeed")  # car is not its reference actor


def test_unknown_path_lists_the_valid_ones(uis2: scm.Scenario) -> None:
    with pytest.raises(UnknownPathError) as caught:
        resolve(uis2, "ego.topSpeed")
    assert "ego.initialSpeed" in caught.value.valid
    assert "CrossingManeuver_1.triggerRadius" in str(caught.value)


def test_space_of_uis2(uis2: scm.Scenario) -> None:
    space = parameter_space(uis2)
    assert space.paths == (
        "ego.initialSpeed",
        "Accelerate_1.targetSpeed",
        "InLocationRadius_2.radius",
        "DriveDistance_1.speed",
        "CrossingManeuver_1.triggerRadius",
        "CrossingManeuver_1.crossingSpeed",
    )
    kinds = [d.kind for d in space.dimensions]
    assert kinds == ["set", "normal", "set", "set", "set", "uniform"]
    # [3, 7] step 1, [3, 6] step 1, {8, 10, 12}, [10, 20] step 5
    assert space.grid_shape == (5, 4, 3, 3)
    assert space.grid_size == 180


def test_grid_levels_include_the_maximum_despite_float_steps() -> None:
    assert grid_levels("p", 0.0, 0.3, 0.1) == (0.0, 0.1, 0.2, 0.3)
    assert grid_levels("p", 1.0, 2.0, 0.4) == (1.0, 1.4, 1.8)

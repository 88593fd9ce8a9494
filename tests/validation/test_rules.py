"""Rules on hand-built models: examples are clean, dispatch, internal errors, simultaneity, limits."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.model.build import LibraryBuilder, ScenarioBuilder, lane
from sceml.model.loading import load, load_library
from sceml.model.params import span
from sceml.model.saving import save
from sceml.validation import (
    Limits,
    LimitsError,
    Registry,
    is_valid,
    iter_diagnostics,
    load_limits,
    validate,
)

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE_FILES = sorted(EXAMPLES.glob("*.xmi")) + sorted((EXAMPLES / "library").glob("*.xmi"))


def codes(model: object, **options: object) -> set[str]:
    return {d.code for d in validate(model, **options)}  # type: ignore[arg-type]


def scenario(level: str = "concrete") -> tuple[ScenarioBuilder, scm.Actor]:
    b = ScenarioBuilder("T", map="town.xodr", level=level)
    return b, b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=[p.name for p in EXAMPLE_FILES])
def test_reference_examples_have_no_diagnostics(path: Path) -> None:
    document = load(path)
    assert [str(d) for d in iter_diagnostics(document.root, document=document)] == []


def test_examples_validate_for_every_openscenario_version() -> None:
    document = load(EXAMPLES / "uis2-concrete.xmi")
    for version in ("1.0", "1.1", "1.2", "1.3"):
        assert is_valid(document.root, document=document, osc_version=version)


def test_rule_on_a_superclass_applies_to_subclasses() -> None:
    registry = Registry()
    seen: list[str] = []

    @registry.constraint("T-1", Severity.INFO, "Maneuver", "test")
    def record(node: scm.Maneuver, context: object) -> list:
        seen.append(node.eClass.name)
        return []

    b, ego = scenario()
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=5.0), b.add("Cross", ego), b.end)
    b.add("TimeElapsed", ego, duration=1.0)
    validate(b.scenario, registry=registry)
    assert seen == ["Accelerate", "Cross"]


def test_a_failing_rule_becomes_an_internal_error_and_the_others_still_run() -> None:
    registry = Registry()

    @registry.constraint("T-1", Severity.ERROR, "RootNode", "breaks")
    def broken(root: scm.RootNode, context: object) -> list:
        raise ZeroDivisionError("boom")

    @registry.constraint("T-2", Severity.WARNING, "EndNode", "works")
    def works(end: scm.EndNode, context: object) -> list:
        return [(end, "seen")]

    b, _ = scenario()
    found = validate(b.scenario, registry=registry)
    assert [(d.code, d.path) for d in found] == [("SCEML-X000", "Root"), ("T-2", "End")]
    assert "T-1 (broken): ZeroDivisionError: boom" in found[0].message


def test_missing_required_value_names_actor_node_and_parameter() -> None:
    b, ego = scenario("logical")
    b.chain(b.root, b.add("DriveDistance", ego, name="Drive", speed=5.0), b.end)
    [diagnostic] = validate(b.scenario)
    assert diagnostic.code == "SCEML-P002"
    assert diagnostic.message.startswith("ego.Drive.distance is missing")


def test_functional_scenarios_may_leave_values_out_and_hold_ranges() -> None:
    b, ego = scenario("functional")
    b.actor("Bicycle", "bike")
    turn = b.add("TurnRight", ego)
    b.chain(b.root, b.add("Accelerate", ego), turn, b.end)
    assert validate(b.scenario) == []
    turn.tolerance = span(1.0, 3.0)
    assert validate(b.scenario) == []


def parallel_then(join: str) -> scm.Scenario:
    """ego accelerates while a timer runs; both meet at a join, then ego decelerates."""
    b, ego = scenario()
    wait = b.add("TimeElapsed", ego, duration=2.0)
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    b.chain(b.root, wait)
    b.chain(b.root, speed_up)
    merge = b.join_all(wait, speed_up) if join == "all" else b.join_one(wait, speed_up)
    b.chain(merge, b.add("Decelerate", ego, targetSpeed=2.0), b.end)
    return b.scenario


def test_join_all_orders_what_follows_it() -> None:
    assert validate(parallel_then("all")) == []


def test_join_one_does_not_order_the_branch_that_may_still_run() -> None:
    assert codes(parallel_then("one")) == {"SCEML-C001"}


def test_join_one_orders_when_every_branch_comes_after_the_maneuver() -> None:
    b, ego = scenario()
    speed_up = b.add("Accelerate", ego, targetSpeed=8.0)
    first = b.add("TimeElapsed", ego, duration=1.0)
    second = b.add("SpeedCondition", ego, speed=7.0)
    b.chain(b.root, speed_up, first)
    b.chain(speed_up, second)
    b.chain(b.join_one(first, second), b.add("Decelerate", ego, targetSpeed=2.0), b.end)
    assert validate(b.scenario) == []


def test_different_actors_and_categories_may_overlap() -> None:
    b, ego = scenario()
    other = b.actor("Car", "other", start=lane(1, 1, 30.0))
    parts = [
        b.add("Accelerate", ego, targetSpeed=8.0),
        b.add("LaneChange", ego),
        b.add("Decelerate", other, targetSpeed=2.0),
    ]
    for part in parts:
        b.flow(b.root, part)
    b.chain(b.join_all(*parts), b.end)
    assert validate(b.scenario) == []


def test_duplicate_module_names_in_a_library_built_in_memory() -> None:
    library = LibraryBuilder("L")
    for _ in range(2):
        module = library.module("Wait")
        role = module.role("r")
        module.chain(module.in_port, module.add("TimeElapsed", role, duration=1.0), module.out_port)
    assert codes(library.library) == {"SCEML-M014"}


def test_kinds_a_profile_cannot_export() -> None:
    # Every kind maps in every version; the carla profile cannot express KeepVelocity.
    b, ego = scenario()
    b.chain(b.root, b.add("KeepVelocity", ego, duration=2.0), b.end)
    assert codes(b.scenario, osc_profile="carla") == {"SCEML-E003"}
    assert codes(b.scenario, osc_profile="carla", osc_version="1.0") == {"SCEML-E003"}
    assert codes(b.scenario, osc_version="1.0") == set()
    assert codes(b.scenario) == set()


def test_an_acceleration_direction_needs_1_2_and_a_light_1_3() -> None:
    b, ego = scenario()
    braking = b.add("AccelerationCondition", ego, acceleration=-3.0, direction="lateral")
    b.chain(b.root, braking, b.end)
    assert codes(b.scenario, osc_version="1.1") == {"SCEML-E008"}
    assert codes(b.scenario, osc_version="1.2") == set()
    braking.direction = scm.AccelerationDirection.total  # the magnitude: every version
    assert codes(b.scenario, osc_version="1.0") == set()
    b.chain(b.root, b.add("LightState", ego, lightType="brakeLights"), b.end)
    assert codes(b.scenario, osc_version="1.2") == {"SCEML-E003"}
    assert codes(b.scenario, osc_version="1.3") == set()


def test_settings_a_version_cannot_say() -> None:
    # OpenSCENARIO 1.0 has no relativeDistanceType: a longitudinal time to collision needs 1.1;
    # the carla profile writes 1.0, so it refuses it too.
    b, ego = scenario()
    lead = b.actor("Car", "lead", start=lane(1, -1, 40.0))
    b.chain(
        b.root,
        b.add("TimeToCollision", ego, target=lead, relativeDistanceType="longitudinal"),
        b.end,
    )
    assert codes(b.scenario, osc_version="1.0") == {"SCEML-E008"}
    assert codes(b.scenario, osc_profile="carla") == {"SCEML-E008"}
    assert codes(b.scenario, osc_version="1.1") == set()
    assert codes(b.scenario) == set()
    b.chain(
        b.root, b.add("TimeHeadway", ego, target=lead, time=1.0, coordinateSystem="lane"), b.end
    )
    assert {d.message.split(":")[-1] for d in validate(b.scenario, osc_version="1.0")} >= {
        " coordinateSystem lane needs OpenSCENARIO 1.1 or later (1.0 measures entity only)"
    }


def test_a_follows_jerks_and_side_need_the_versions_that_say_them() -> None:
    # DynamicConstraints' jerks came with OpenSCENARIO 1.2, the displacement with 1.1.
    b, ego = scenario()
    lead = b.actor("Car", "lead", start=lane(1, -1, 40.0))
    follow = b.add("Follow", ego, target=lead, maxDecelerationRate=4.0)
    b.chain(b.root, follow, b.end)
    assert codes(b.scenario, osc_version="1.1") == {"SCEML-E008"}
    assert codes(b.scenario, osc_version="1.2") == set()
    follow.maxDecelerationRate = None
    follow.displacement = scm.LongitudinalDisplacement.leading
    assert codes(b.scenario, osc_version="1.0") == {"SCEML-E008"}
    assert codes(b.scenario, osc_version="1.1") == set()
    follow.displacement = scm.LongitudinalDisplacement.trailing
    assert codes(b.scenario, osc_version="1.0") == set()


def test_library_internals_are_reported_in_the_library_file(tmp_path: Path) -> None:
    library = LibraryBuilder("L")
    module = library.module("Loose")
    role = module.role("r", "Car")
    module.chain(module.in_port, module.add("TimeElapsed", role, duration=1.0))
    save(library.library, tmp_path / "lib.xmi")
    definition = load_library(tmp_path / "lib.xmi").root.modules[0]
    b, ego = scenario()
    b.chain(b.root, b.use(definition, {"r": ego}), b.end)
    save(b.scenario, tmp_path / "s.xmi")
    document = load(tmp_path / "s.xmi")
    found = [d for d in validate(document.root, document=document) if d.code == "SCEML-M009"]
    assert [(Path(d.file).name, d.line) for d in found] == [("lib.xmi", 5)]


def test_limits_file_overrides_the_table(tmp_path: Path) -> None:
    b, _ = scenario()
    walker = b.actor("Pedestrian", "walker", start=lane(4, 2, 1.0))
    b.chain(b.root, b.add("Accelerate", walker, targetSpeed=4.0), b.end)
    assert codes(b.scenario) == set()
    strict = tmp_path / "limits.yaml"
    strict.write_text("Pedestrian:\n  max_speed: 3.0\n", encoding="utf-8")
    assert codes(b.scenario, limits=load_limits(strict)) == {"SCEML-L001"}
    on_abstract = tmp_path / "limits.toml"
    on_abstract.write_text("[Actor]\nmax_speed = 1.0\n", encoding="utf-8")
    merged = load_limits(on_abstract)
    assert merged.limit("Pedestrian", "max_speed") == 5.0  # the table names Pedestrian itself
    assert Limits({"Actor": {"max_speed": 1.0}}).limit("Bicycle", "max_speed") == 1.0


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("Robot:\n  max_speed: 1\n", "unknown actor kind 'Robot'"),
        ("Car:\n  top_speed: 1\n", "unknown limit 'top_speed'"),
        ("Car:\n  max_speed: -1\n", "a limit is a positive number"),
        ("Car: [1, 2\n", "malformed limits file"),
        ("!!python/object:os.system ls\n", "malformed limits file"),
    ],
)
def test_bad_limits_files_are_refused(tmp_path: Path, text: str, message: str) -> None:
    path = tmp_path / "limits.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(LimitsError, match=message) as raised:
        load_limits(path)
    assert raised.value.exit_code == 2

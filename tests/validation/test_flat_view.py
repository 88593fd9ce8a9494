"""The validator's flat view traces each expanded node by flatten's provenance, not by its name."""

from __future__ import annotations

from pathlib import Path

import scemlmodel as scm
from sceml.diagnostics import Diagnostic
from sceml.model.build import LibraryBuilder, ScenarioBuilder, lane
from sceml.model.loading import load
from sceml.validation import validate
from sceml.validation.context import Context
from sceml.validation.limits import Limits

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_nodes_nested_three_deep_trace_to_the_outermost_use() -> None:
    scenario = load(EXAMPLES / "overtaking-concrete.xmi").root
    flat = Context(scenario, None, Limits()).flat()
    assert flat is not None
    use = next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse))
    inner = next(n for n in flat.nodes if str(n.name).endswith("TimeToCollision_1"))
    assert flat.from_module(inner) and flat.origin(inner) is use


def test_plain_nodes_sharing_a_name_each_trace_to_themselves() -> None:
    scenario = load(EXAMPLES / "uis2-concrete.xmi").root
    first, second = [n for n in scenario.nodes if isinstance(n, scm.InLocationRadius)]
    second.name = first.name
    # A name that looks like an expanded node's is still a plain node of the scenario.
    plain = next(n for n in scenario.nodes if n.name == "DriveDistance_1")
    plain.name = "CrossingManeuver_1.Waiting"
    flat = Context(scenario, None, Limits()).flat()
    assert flat is not None
    copies = {flat.origin(n): n for n in flat.nodes if not flat.from_module(n)}
    assert first in copies and second in copies and plain in copies
    assert copies[second] is not copies[first]


REPO = EXAMPLES.parent


def _turn_twice(scenario_turns_first: bool) -> list[Diagnostic]:
    """The ego (south arm, heading north) turns right onto the east arm inside a module; when
    the scenario first turns it right onto that arm itself, the module's turn starts there."""
    library = LibraryBuilder("Turns")
    module = library.module("RightTurn")
    driver = module.role("driver", "Car")
    module.chain(
        module.in_port,
        module.add("TurnRight", driver, destination=lane("2", -1, 25.0)),
        module.out_port,
    )
    b = ScenarioBuilder("Turns", map=str(REPO / "maps" / "intersection.xodr"), level="concrete")
    ego = b.actor("Car", "ego", ego=True, start=lane("3", 1, 30.0), speed=8.0)
    steps: list[scm.GraphElement] = []
    if scenario_turns_first:
        steps.append(b.add("TurnRight", ego, destination=lane("2", -1, 25.0)))
    use = b.use(module.definition, {"driver": ego})
    b.chain(b.root, *steps, use, b.end)
    return [d for d in validate(b.scenario) if d.code == "SCEML-R006"]


def test_a_turn_inside_a_module_departs_from_where_the_scenario_left_the_actor() -> None:
    # From the south arm's inbound lane the junction leads right onto the east arm.
    assert _turn_twice(scenario_turns_first=False) == []
    # After the scenario's own right turn the ego drives away from the junction on the east
    # arm's outbound lane: the module's right turn cannot be reached from there, and the
    # finding is reported at the use, where the engineer can change it.
    found = _turn_twice(scenario_turns_first=True)
    assert len(found) == 1
    assert found[0].path is not None and found[0].path.endswith("RightTurn_1")

"""Parameters and variables in the preview: the declared values, changed by SetParameter and
SetVariable, read by ParameterCondition and VariableCondition. The times were checked by hand
against esmini 3.6's log of tests/importer/files/variables.xosc (Counter 1 x 3 + 2 = 5 > 4 at
0.10 s; the brake waits one step more in the model, whose flows each cost one)."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.build import ScenarioBuilder, world
from sceml.importer import import_file
from sceml.players.meaning import value_after, value_holds
from sceml.simulate import simulate
from sceml.simulate.world import SimulationError

FILES = Path(__file__).resolve().parents[1] / "importer" / "files"


@pytest.mark.parametrize("name", ("parameters", "variables"))
def test_a_condition_holds_once_the_actions_changed_the_value(name: str) -> None:
    source = FILES / f"{name}.xosc"
    run = simulate(import_file(source).scenario, source)
    times = {n: (run.node(n).started, run.node(n).finished) for n in ("SetCounter", "CounterHigh")}
    assert times == {"SetCounter": (0.05, 0.05), "CounterHigh": (0.05, 0.1)}
    # Mood is "calm" until Calm sets it: StillCalm holds at once.
    assert run.node("StillCalm").finished == 0.05
    # CounterHigh is written into Brake's trigger (players.flows): Brake starts when it holds.
    assert run.node("Brake").started == 0.1


def test_the_meaning_of_the_rules_and_changes() -> None:
    assert value_holds("5", "greaterThan", "4") and not value_holds("4", "greaterThan", "4")
    assert value_holds("4.0", "equalTo", "4") and value_holds("true", "equalTo", "True")
    assert not value_holds("calm", "lessThan", "relieved")  # text compares by equality only
    assert value_after("1", "multiply", "3") == "3" and value_after("3", "add", "2.5") == "5.5"
    assert value_after("calm", "set", "relieved") == "relieved"
    with pytest.raises(ValueError, match="both must be numbers"):
        value_after("calm", "add", "1")


def test_changing_an_undeclared_parameter_stops_the_preview_with_the_node_named() -> None:
    b = ScenarioBuilder("Undeclared", level="concrete", max_duration=1.0)
    b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=1.0)
    setter = b.add("SetParameter", None, name="SetIt", parameter="Nowhere", value="1")
    b.chain(b.root, setter, b.end)
    with pytest.raises(SimulationError, match="SetIt: changes the parameter 'Nowhere'"):
        simulate(b.scenario)

"""SCEML-P009: a parameter or variable node names one the root declares; CARLA's empty names
are left alone; a parameter of that name does not declare a variable."""

from __future__ import annotations

from sceml.build import ScenarioBuilder, world
from sceml.validation import validate


def p009(**declared: bool) -> list[str]:
    """The P009 messages of a scenario declaring `declared` (name: variable?) whose nodes
    read Counter, write the variable Counter, and check an empty name."""
    b = ScenarioBuilder("Declared", level="concrete", max_duration=5.0)
    b.actor("Car", "ego", ego=True, start=world(0.0, 0.0), speed=1.0)
    for name, variable in declared.items():
        b.declare(name, 0, variable=variable)
    read = b.add("ParameterCondition", None, name="Reads", parameter="Counter", value="1")
    write = b.add("SetVariable", None, name="Writes", variable="Counter", value="2")
    criterion = b.add("ParameterCondition", None, name="Criterion", parameter="", value="")
    b.chain(b.root, read, write, criterion, b.end)
    return sorted(d.message for d in validate(b.scenario) if d.code == "SCEML-P009")


def test_undeclared_names_are_errors_and_empty_ones_are_not() -> None:
    assert p009() == [
        "'Reads' names the parameter 'Counter', which the root does not declare",
        "'Writes' names the variable 'Counter', which the root does not declare",
    ]
    # A parameter Counter is not the variable Counter.
    assert p009(Counter=False) == [
        "'Writes' names the variable 'Counter', which the root does not declare"
    ]

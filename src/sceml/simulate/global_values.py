"""The global kinds in the preview: a store of the scenario's parameters and variables, set from
the root's declarations, changed by SetParameter and SetVariable, read by ParameterCondition and
VariableCondition (their meaning is `players.meaning.value_holds` and `value_after`)."""

from __future__ import annotations

from pyecore.ecore import EObject

import scemlmodel as scm

from ..players import meaning
from .conditions import Test, kind
from .world import SimulationError, World

#: Each global kind: the feature naming what it reads or changes, and whether it is a variable.
_NAMED = {
    "ParameterCondition": ("parameter", False),
    "SetParameter": ("parameter", False),
    "VariableCondition": ("variable", True),
    "SetVariable": ("variable", True),
}


def initial_values(root: scm.RootNode) -> dict[tuple[bool, str], str]:
    """The store at the start: each declared parameter and variable with its initial value."""
    return {(bool(d.variable), str(d.name)): str(d.value or "") for d in root.declarations}


def _key(node: EObject) -> tuple[bool, str]:
    feature, variable = _NAMED[node.eClass.name]
    return variable, str(node.eGet(feature) or "")


#: What the timeline says of a traffic signal node: the preview has no signal model.
NO_SIGNALS = "the preview has no traffic signals: {what}"


def apply(node: EObject, world: World) -> str | None:
    """Perform a global action (it finishes at once); a note for the timeline when the preview
    cannot (a traffic signal state)."""
    if node.eClass.name not in _NAMED:
        return NO_SIGNALS.format(what="not simulated, it finishes at once")
    key = _key(node)
    if key not in world.values:
        what = "variable" if key[0] else "parameter"
        raise SimulationError(
            f"{node.name}: changes the {what} {key[1]!r}, which the scenario does not declare",
            element=str(node.name),
        )
    try:
        world.values[key] = meaning.value_after(world.values[key], node.modify.name, node.value)
    except ValueError as error:
        raise SimulationError(f"{node.name}: {error}", element=str(node.name)) from None
    return None


@kind("ParameterCondition")
@kind("VariableCondition")
def value_condition(node: EObject, world: World) -> Test:
    """Holds once the declared value compares by the rule; an undeclared name (CARLA's criteria
    name none) never holds."""
    key, rule, value = _key(node), node.rule.name, str(node.value or "")
    return lambda w: key in w.values and meaning.value_holds(w.values[key], rule, value)

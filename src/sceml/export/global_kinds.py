"""The global kinds (no actor performs them): parameter and variable conditions and actions with
the declarations they read and change, and traffic signal states and conditions.

A global action is an event in the ego's maneuver group (OpenSCENARIO wants every event in one;
the action itself names no entity); a global condition is a marker event there that fires once
the node is activated and the condition holds, as every condition node does, or, where
`xosc.flows.inlined` says so, no event: its test goes into its successor's trigger.
"""

from __future__ import annotations

from typing import Any

import scemlmodel as scm

from .actions import Plan, marker_plan, planner
from .context import Action, Context, Event
from .triggers import Condition, Group

#: The OpenSCENARIO element and reference attribute of each kind, and the feature naming it.
_TARGETS = {
    "ParameterCondition": ("Parameter", "parameter"),
    "SetParameter": ("Parameter", "parameter"),
    "VariableCondition": ("Variable", "variable"),
    "SetVariable": ("Variable", "variable"),
}


@planner("ParameterCondition", "VariableCondition")
def plan_value_condition(ctx: Context, node: scm.ActionNode, groups: list[Group]) -> Plan:
    """A marker on ParameterCondition or VariableCondition."""
    name = ctx.event_names[node]
    element, feature = _TARGETS[node.eClass.name]
    data = {
        "element": element,
        "ref": str(node.eGet(feature) or ""),
        "value": str(node.value or ""),
        "rule": node.rule.name,
    }
    check = Condition(f"{name}_{feature}", "value_condition", data)
    return marker_plan(ctx, node, groups, ctx.ego, check)


@planner("SetParameter", "SetVariable", one_event=True)
def plan_value_action(ctx: Context, node: scm.ActionNode, groups: list[Group]) -> Plan:
    """A ParameterAction or VariableAction: SetAction, or ModifyAction's AddValue or
    MultiplyByValue; it completes at once."""
    name = ctx.event_names[node]
    element, feature = _TARGETS[node.eClass.name]
    data = {
        "element": element,
        "ref": str(node.eGet(feature) or ""),
        "value": str(node.value or ""),
        "modify": node.modify.name,
    }
    action = Action(ctx.action_name(name), "value_action", data)
    return [Event(name, ctx.ego, [action], groups)], name


@planner("TrafficSignalState", one_event=True)
def plan_signal_state(ctx: Context, node: scm.TrafficSignalState, groups: list[Group]) -> Plan:
    """A TrafficSignalStateAction (InfrastructureAction in every version); it completes at once."""
    name = ctx.event_names[node]
    data = {"signal": str(node.signalId or ""), "state": str(node.state or "")}
    action = Action(ctx.action_name(name), "signal_state", data)
    return [Event(name, ctx.ego, [action], groups)], name


@planner("TrafficSignalCondition")
def plan_signal_condition(
    ctx: Context, node: scm.TrafficSignalCondition, groups: list[Group]
) -> Plan:
    """A marker on TrafficSignalCondition."""
    name = ctx.event_names[node]
    data = {"signal": str(node.signalId or ""), "state": str(node.state or "")}
    check = Condition(f"{name}_signal", "signal_condition", data)
    return marker_plan(ctx, node, groups, ctx.ego, check)


def declarations(root: scm.RootNode, variables_allowed: bool) -> dict[str, list[dict[str, Any]]]:
    """The root's declarations as the template writes them: `parameters` and `variables`.

    ValueError for a variable where the version has none (before 1.2).
    """
    found: dict[str, list[dict[str, Any]]] = {"parameters": [], "variables": []}
    for declaration in root.declarations:
        if declaration.variable and not variables_allowed:
            raise ValueError(
                f"the variable {declaration.name!r} needs OpenSCENARIO 1.2 or later "
                "(earlier versions have no variables)"
            )
        found["variables" if declaration.variable else "parameters"].append(
            {
                "name": str(declaration.name),
                "type": declaration.type.name,
                "value": str(declaration.value or ""),
            }
        )
    return found

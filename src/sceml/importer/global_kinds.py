"""Parameter and variable conditions and actions to the global kinds (no actor performs them),
with the declarations they name kept on the root node; traffic signal states and conditions.

A ParameterCondition or VariableCondition becomes the node of that name, a ParameterAction or
VariableAction (SetAction, or ModifyAction's AddValue or MultiplyByValue) SetParameter or
SetVariable. The parameter or variable they name is declared on the root with the type and the
initial value the file declares, so that the export declares it again; an empty name (CARLA's
criteria name their check by the condition, not by a parameter) declares nothing.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from .actions import Motion, Request, add_node, maps
from .context import Build

#: OpenSCENARIO's element word -> (the node feature naming it, is a variable).
_WORDS = {"Parameter": ("parameter", False), "Variable": ("variable", True)}


def value_condition(
    build: Build, test: etree._Element, wanted: str, rules: dict[str, tuple[str, bool]]
) -> scm.ActionNode | str:
    """The node of a ParameterCondition or VariableCondition, or why it has none."""
    word = str(test.tag).removesuffix("Condition")
    feature, variable = _WORDS[word]
    rule = rules.get(str(test.get("rule")))
    if rule is None:
        return f"the rule {test.get('rule')} has no SceML form"
    if rule[1]:
        build.report.add(
            "guessed", f"{wanted}: {test.get('rule')} read as {rule[0]}", build.where(test)
        )
    name = str(test.get(f"{feature}Ref", ""))
    node: scm.ActionNode = getattr(scm, f"{word}Condition")()
    node.eSet(feature, name)
    node.value = str(test.get("value", ""))
    node.rule = scm.ComparisonRule.getEEnumLiteral(rule[0])
    build.add(node, wanted)
    declare(build, name, variable)
    return node


def declare(build: Build, name: str, variable: bool) -> None:
    """Keep the declaration of `name` on the root (once), as the file declares it at the top."""
    if not name or any(d.name == name for d in build.root.declarations):
        return
    word = "Variable" if variable else "Parameter"
    found = next(
        (
            d
            for d in build.source.root.iterfind(f"{word}Declarations/{word}Declaration")
            if d.get("name") == name
        ),
        None,
    )
    kind = None if found is None else found.get(f"{word.lower()}Type")
    declaration = scm.Declaration(
        name=name,
        type=scm.DeclarationType.getEEnumLiteral(kind or "double") or scm.DeclarationType.double,
        value=None if found is None else str(found.get("value", "")),
        variable=variable,
    )
    build.root.declarations.append(declaration)
    if found is None:
        build.report.add(
            "guessed",
            f"the {word.lower()} {name!r} is not declared at the top of the file: declared "
            "as a double without a value",
        )


def _value_action(build: Build, request: Request, element: etree._Element) -> scm.ActionNode | str:
    word = str(element.tag).removesuffix("Action")
    feature, variable = _WORDS[word]
    set_to = element.find("SetAction")
    add = element.find("ModifyAction/Rule/AddValue")
    times = element.find("ModifyAction/Rule/MultiplyByValue")
    change = next(
        (
            (modify, found)
            for modify, found in (("set", set_to), ("add", add), ("multiply", times))
            if found is not None
        ),
        None,
    )
    if change is None:
        return f"this {element.tag} has no SceML form"
    name = str(element.get(f"{feature}Ref", ""))
    node = add_node(
        build,
        request,
        f"Set{word}",
        **{feature: name, "value": str(change[1].get("value", "")), "modify": change[0]},
    )
    declare(build, name, variable)
    return node


@maps("GlobalAction/ParameterAction")
def _parameter_action(
    build: Build, request: Request, element: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return _value_action(build, request, element)


@maps("GlobalAction/VariableAction")
def _variable_action(
    build: Build, request: Request, element: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return _value_action(build, request, element)


@maps("GlobalAction/InfrastructureAction/TrafficSignalAction/TrafficSignalStateAction")
def _signal_state(
    build: Build, request: Request, element: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return add_node(
        build,
        request,
        "TrafficSignalState",
        signalId=str(element.get("name", "")),
        state=str(element.get("state", "")),
    )


def signal_condition(build: Build, test: etree._Element, wanted: str) -> scm.ActionNode:
    """The node of a TrafficSignalCondition."""
    node = scm.TrafficSignalCondition(
        signalId=str(test.get("name", "")), state=str(test.get("state", ""))
    )
    build.add(node, wanted)
    return node

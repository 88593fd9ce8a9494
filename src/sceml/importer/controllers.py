"""Controllers: an entity's ObjectController and the Init ones to the actor, the storyboard's
controller actions to ActivateController, AssignController and OverrideController nodes.

Catalog references to controllers are already replaced by their entries (`catalogs.py`) and
parameters resolved in place, so a Controller element is read as it stands. OpenSCENARIO 1.0
requires an OverrideControllerValueAction with all six inputs beside every assignment; when
all of them are released (the usual filler) they say nothing and the assignment maps alone.
"""

from __future__ import annotations

from lxml import etree

import scemlmodel as scm

from ..xosc.meaning import CONTROLLER_DOMAINS as DOMAINS
from ..xosc.meaning import OVERRIDE_ELEMENTS
from .actions import Motion, Request, _add, _maps
from .context import Build

#: ControllerOverrideKind of each OverrideControllerValueAction element.
_OVERRIDE_KINDS = {element: kind for kind, element in OVERRIDE_ELEMENTS.items()}


def flag(element: etree._Element, attribute: str) -> bool | None:
    """An xsd:boolean attribute (true/false/1/0), or None when it is not given."""
    text = element.get(attribute)
    return None if text is None else text.strip() in ("true", "1")


def read_controller(build: Build, element: etree._Element) -> scm.Controller | None:
    """The Controller inside an ObjectController or AssignControllerAction (None if there is
    none: a catalog reference that was not resolved stays for the caller to report)."""
    held = element if element.tag == "Controller" else element.find("Controller")
    if held is None:
        held = element.find("ObjectController/Controller")
    if held is None:
        return None
    made = scm.Controller(name=held.get("name"), controllerType=held.get("controllerType"))
    for item in held.iterfind("Properties/*"):
        if item.tag == "Property":
            made.properties.append(scm.Property(name=item.get("name"), value=item.get("value")))
        elif item.tag == "File" and made.file is None:
            made.file = item.get("filepath")
        elif isinstance(item.tag, str):
            build.report.add(
                "not represented",
                f"controller {made.name!r}: its <{item.tag}> (SceML keeps name and value "
                "pairs and one file)",
                build.where(item),
            )
    return made


def read_activation(element: etree._Element, prefix: str = "") -> scm.ControllerActivation | None:
    """The domains an element switches (`activateLateral` etc. with prefix `activate`)."""
    found = {}
    for domain in DOMAINS:
        name = f"{prefix}{domain[0].upper()}{domain[1:]}" if prefix else domain
        found[domain] = flag(element, name)
    if all(value is None for value in found.values()):
        return None
    return scm.ControllerActivation(**found)


def only_released(override: etree._Element | None) -> bool:
    """Whether an OverrideControllerValueAction releases every input it names (1.0's filler)."""
    return override is None or all(flag(item, "active") is False for item in override)


def object_controller(build: Build, actor: scm.Actor, item: etree._Element) -> None:
    """The ScenarioObject's (first) ObjectController as the actor's controller."""
    holders = item.findall("ObjectController")
    if not holders:
        return
    made = read_controller(build, holders[0])
    if made is None:
        build.report.add(
            "not represented",
            f"entity {actor.name!r}: its controller (no Controller element found)",
            build.where(holders[0]),
        )
        return
    actor.controller = made
    build.report.add(
        "mapped", f"entity {actor.name!r}: controller {made.name!r}", build.where(holders[0])
    )
    for extra in holders[1:]:
        build.report.add(
            "not represented",
            f"entity {actor.name!r}: a further ObjectController (a SceML actor has one)",
            build.where(extra),
        )


def init_controller(build: Build, actor: scm.Actor, private: etree._Element) -> bool:
    """An Init assignment or activation applied to the actor; False for anything else."""
    activate = _activation_element(private)
    group = private.find("ControllerAction")
    assign = None if group is None else group.find("AssignControllerAction")
    if activate is not None and (group is None or len(group) == 1):
        actor.controllerActivation = _merged(actor.controllerActivation, read_activation(activate))
        build.report.add("mapped", f"{actor.name}: controller activation", build.where(activate))
        return True
    if (
        assign is None
        or group is None
        or not only_released(group.find("OverrideControllerValueAction"))
    ):
        return False
    if group.find("ActivateControllerAction") is not None:
        return False
    made = read_controller(build, assign)
    if made is None:
        return False
    actor.controller = made
    switched = read_activation(assign, "activate")
    if switched is not None:
        actor.controllerActivation = _merged(actor.controllerActivation, switched)
    build.report.add("mapped", f"{actor.name}: controller {made.name!r}", build.where(assign))
    return True


def _merged(
    before: scm.ControllerActivation | None, switched: scm.ControllerActivation | None
) -> scm.ControllerActivation:
    """The domains after a further Init activation: those it sets, the others as they were
    (`distance_test` switches longitudinal and lateral on in two actions)."""
    merged = scm.ControllerActivation()
    for domain in DOMAINS:
        value = None if switched is None else switched.eGet(domain)
        if value is None and before is not None:
            value = before.eGet(domain)
        merged.eSet(domain, value)
    return merged


def controls_speed(actor: scm.Actor) -> bool:
    """Whether an Init action read so far switched the actor's longitudinal domain on."""
    activation = actor.controllerActivation
    return activation is not None and activation.longitudinal is True


def _activation_element(private: etree._Element) -> etree._Element | None:
    direct = private.find("ActivateControllerAction")
    return (
        direct if direct is not None else private.find("ControllerAction/ActivateControllerAction")
    )


def _one_action(group: etree._Element) -> bool:
    """A ControllerAction of one action (an assignment with only released inputs counts)."""
    children = [child for child in group if isinstance(child.tag, str)]
    if len(children) == 1:
        return True
    tags = sorted(child.tag for child in children)
    return tags == ["AssignControllerAction", "OverrideControllerValueAction"] and only_released(
        group.find("OverrideControllerValueAction")
    )


@_maps("PrivateAction/ActivateControllerAction")
def _activate_direct(
    build: Build, request: Request, activate: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    return _activate(build, request, activate)


@_maps("PrivateAction/ControllerAction/AssignControllerAction")
def _assign(
    build: Build, request: Request, assign: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    group = assign.getparent()
    assert group is not None
    if not _one_action(group):
        return "a ControllerAction of several actions, or an assignment with active overrides"
    made = read_controller(build, assign)
    if made is None:
        return "an assignment without a Controller has no SceML form"
    return _add(
        build,
        request,
        "AssignController",
        controller=made,
        activation=read_activation(assign, "activate"),
    )


@_maps("PrivateAction/ControllerAction/ActivateControllerAction")
def _activate_wrapped(
    build: Build, request: Request, activate: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    group = activate.getparent()
    assert group is not None
    if not _one_action(group):
        return "a ControllerAction of several actions has no single SceML node"
    return _activate(build, request, activate)


def _activate(build: Build, request: Request, activate: etree._Element) -> scm.ActionNode | str:
    for reference in ("controllerRef", "objectControllerRef"):
        if activate.get(reference):
            build.report.add(
                "guessed",
                f"{request.name}: {reference} {activate.get(reference)!r} read as the actor's "
                "controller (a SceML actor has one)",
                build.where(activate),
            )
    values = {domain: flag(activate, domain) for domain in DOMAINS}
    return _add(build, request, "ActivateController", **values)


@_maps("PrivateAction/ControllerAction/OverrideControllerValueAction")
def _override(
    build: Build, request: Request, override: etree._Element, motion: Motion
) -> scm.ActionNode | str:
    group = override.getparent()
    assert group is not None
    if not _one_action(group):
        return "a ControllerAction of several actions has no single SceML node"
    inputs = []
    for item in override:
        if not isinstance(item.tag, str):
            continue
        value = _input_value(item)
        if value is None:
            return f"an override of {item.tag} by a force or an automatic gear has no SceML form"
        kind = scm.ControllerOverrideKind.getEEnumLiteral(_OVERRIDE_KINDS[item.tag])
        active = flag(item, "active") is True
        inputs.append(scm.ControllerOverride(kind=kind, active=active, value=value))
    node = _add(build, request, "OverrideController")
    node.overrides.extend(inputs)
    return node


def _input_value(item: etree._Element) -> float | None:
    """An input's value: the attribute (value; a gear's number) or, from 1.2, BrakePercent's
    value or ManualGear's number. None for a brake force or an automatic gear."""
    for path, attribute in (
        (".", "value"),
        (".", "number"),
        ("BrakePercent", "value"),
        ("ManualGear", "number"),
    ):
        holder = item.find(path)
        if holder is not None and holder.get(attribute) is not None:
            return float(str(holder.get(attribute)))
    if len(item) == 0:
        return 0.0
    return None

"""Node labels for the diagrams: kind, actors and key parameters, as the abstraction level has them.

Labels show what is set in the model: values at the concrete level, ranges and distributions at
the logical level, nothing at the functional level. Unset parameters (language defaults) are left
out to keep boxes small; the HTML report's parameter table lists them. Inside an expanded module
use, roles are shown with the actor bound to them and parameter references with the value the use
gives them (override, else the module's default).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field

from lxml import etree
from pyecore.ecore import EAttribute, EEnum, EObject, EReference

import scemlmodel as scm

from ..errors import SceMLError
from ..files.safexml import hardened_parser
from ..model import catalog, params
from ..model.axes import maneuver_axes
from ..model.graph import actors, root_level, root_node
from ..modules.resolve import resolved_definition
from ..xosc.kept import key_values, kind_text
from ..xosc.meaning import CONTROLLER_DOMAINS

#: Features every action node has that labels show in other ways, or never.
_NOT_PARAMETERS = {
    "name",
    "referenceActor",
    "targetActor",
    "incoming",
    "outgoing",
    *catalog.NOTATION_FEATURES,
}


@dataclass(frozen=True)
class Scope:
    """What a module use binds: its roles to actor names, its parameters to values.

    The top level of a scenario has an empty scope; `chain` holds the definitions being expanded,
    so a module that uses itself is drawn collapsed instead of looping.
    """

    roles: Mapping[EObject, str] = field(default_factory=dict)
    parameters: Mapping[EObject, scm.ParameterValue | None] = field(default_factory=dict)
    chain: tuple[EObject, ...] = ()
    prefix: str = ""


def participant_text(participant: EObject | None, scope: Scope) -> str:
    """An actor's name, or a role's name with the actor bound to it where known."""
    if participant is None:
        return "(no actor)"
    name = str(participant.name or "?")
    if isinstance(participant, scm.ActorRole):
        bound = scope.roles.get(participant)
        return f"{bound} ({name})" if bound else name
    return name


def bound_actor(participant: EObject | None, scope: Scope) -> str | None:
    """The actor name a participant stands for in this scope (a role resolves through bindings)."""
    if isinstance(participant, scm.ActorRole):
        return scope.roles.get(participant)
    return str(participant.name) if participant is not None else None


def actor_line(node: scm.ActionNode, scope: Scope) -> str:
    """`bike` or `bike, target ego`: who performs the node, and whom it refers to."""
    text = participant_text(node.referenceActor, scope)
    if node.targetActor is not None:
        text += f", target {participant_text(node.targetActor, scope)}"
    return text


def _resolve(value: scm.ParameterValue | None, scope: Scope) -> scm.ParameterValue | None:
    if isinstance(value, scm.ParameterRef) and value.parameter in scope.parameters:
        return scope.parameters[value.parameter]
    return value


def _kmh(value: scm.ParameterValue | None) -> str:
    def k(number: float | None) -> str:
        return "?" if number is None else f"{round(number * 3.6, 1):g}"

    if isinstance(value, scm.Value):
        return f"{k(value.value)} km/h"
    if isinstance(value, scm.Range | scm.UniformDistribution):
        return f"{k(value.min)}–{k(value.max)} km/h"
    if isinstance(value, scm.NormalDistribution):
        return f"mean {k(value.mean)} km/h"
    return ""


def unit_text(unit: str) -> str:
    """A unit as people write it (`m/s2` -> `m/s²`; a ratio's `1` is not written)."""
    return "" if unit == "1" else unit.replace("m/s2", "m/s²")


def describe_value(value: scm.ParameterValue | None, unit: str, scope: Scope) -> str:
    """A parameter as text with its unit; speeds also in km/h; references show what they get."""
    resolved = _resolve(value, scope)
    if isinstance(value, scm.ParameterRef) and resolved is not value:
        reference = params.describe(value)
        if resolved is None:
            return f"{reference} (unset)"
        return f"{describe_value(resolved, unit, scope)} ({reference})"
    if isinstance(value, scm.ParameterRef):
        parameter = value.parameter
        default = getattr(parameter, "default", None)
        unit = str(getattr(parameter, "unit", None) or unit)
        text = params.describe(value)
        return f"{text}, default {params.describe(default, unit)}" if default is not None else text
    text = params.describe(value, unit_text(unit))
    if unit == "m/s":
        speed = _kmh(value)
        if speed:
            text += f" = {speed}"
    return text


def describe_position(position: EObject | None, scope: Scope) -> str:
    """`(x, y) m, h 1.57 rad` for world positions, `road 3 lane 1 s 30 m` for lane positions,
    `road 3 s 30 m t -1.75 m` for road positions."""
    if isinstance(position, scm.WorldPosition):
        x = describe_value(position.x, "", scope)
        y = describe_value(position.y, "", scope)
        text = f"({x}, {y}) m"
        if position.h is not None and not _is_zero(_resolve(position.h, scope)):
            text += f", h {describe_value(position.h, 'rad', scope)}"
        return text
    if isinstance(position, scm.LanePosition):
        text = f"road {position.roadId} lane {position.laneId} s {describe_value(position.s, 'm', scope)}"
        if position.offset is not None and not _is_zero(_resolve(position.offset, scope)):
            text += f" offset {describe_value(position.offset, 'm', scope)}"
        if position.h is not None:
            text += f", h {describe_value(position.h, 'rad', scope)}"
        return text
    if isinstance(position, scm.RoadPosition):
        text = f"road {position.roadId} s {describe_value(position.s, 'm', scope)}"
        text += (
            f" t {describe_value(position.t, 'm', scope)}" if position.t is not None else " t 0 m"
        )
        if position.h is not None:
            text += f", h {describe_value(position.h, 'rad', scope)}"
        return text
    if position is not None and position.eClass.name in _RELATIVE_WORDS:
        return _describe_relative(position, scope)
    if isinstance(position, scm.RoutePosition):
        where = f"route {position.routeName or '?'} ({len(position.waypoints)} waypoints)"
        where += f" pathS {describe_value(position.pathS, 'm', scope)}"
        if position.laneId is not None:
            return f"{where} lane {position.laneId}"
        return f"{where} t {describe_value(position.t, 'm', scope)}"
    return "(none)" if position is None else position.eClass.name


#: The offsets each relative position shows, in order.
_RELATIVE_WORDS = {
    "RelativeLanePosition": ("ds", "offset"),
    "RelativeRoadPosition": ("ds", "dt"),
    "RelativeObjectPosition": ("dx", "dy", "dz", "h"),
    "RelativeWorldPosition": ("dx", "dy", "dz"),
}


def _describe_relative(position: EObject, scope: Scope) -> str:
    """`from ego: lane +1, ds 30 m` (only what is set and not zero), as it reads on a box."""
    parts = []
    if position.eClass.name == "RelativeLanePosition":
        parts.append(f"lane {int(position.dLane or 0):+d}")
    for feature in _RELATIVE_WORDS[position.eClass.name]:
        held = position.eGet(feature)
        if held is not None and not _is_zero(_resolve(held, scope)):
            unit = "rad" if feature == "h" else "m"
            parts.append(f"{feature} {describe_value(held, unit, scope)}")
    frame = "in world axes " if position.eClass.name == "RelativeWorldPosition" else ""
    entity = getattr(position.entity, "name", None) or "?"
    return f"{frame}from {entity}: " + (", ".join(parts) if parts else "its own place")


def _is_zero(value: scm.ParameterValue | None) -> bool:
    return isinstance(value, scm.Value) and value.value == 0.0


#: How a measuring condition measures, with OpenSCENARIO's defaults: one `measured` line shows
#: what differs, so a box with the defaults stays as small as before.
_MEASURE = {"freespace": True, "relativeDistanceType": "euclidean", "coordinateSystem": "entity"}


#: Attributes shown only when they differ from these defaults (a LaneChange of one lane
#: stays the box it was before these features existed).
_QUIET_DEFAULTS: dict[str, object] = {
    "lanes": 1,
    "maxRuns": 1,
    "edge": "none",
    "interrupts": False,
}
#: Attributes shown only when they differ from their feature's own default, which differs by
#: kind: a LaneChange is sinusoidal unless it says otherwise, a speed change linear (release
#: 1.4), a trajectory followed by position, a gap kept behind the target, a trajectory from
#: where the actor is (release 1.5).
_QUIET_AT_OWN_DEFAULT = ("shape", "followingMode", "displacement", "fromFirstWaypoint")


def _quiet(node: EObject, name: str, held: object) -> bool:
    """Whether an attribute says nothing worth a line: its quiet default, or a LaneChange's
    direction when an absolute target lane makes it unused."""
    if name == "direction" and getattr(node, "targetLane", None) is not None:
        return True
    value = getattr(held, "name", held)
    if name == "rule" and node.eClass.name == "InVehicleRadius":
        return value == "lessThan"  # within the radius: what the kind's name says
    if name in _QUIET_AT_OWN_DEFAULT:
        feature = node.eClass.findEStructuralFeature(name)
        default = None if feature is None else feature.get_default_value()
        return value == getattr(default, "name", default)
    return name in _QUIET_DEFAULTS and value == _QUIET_DEFAULTS[name]


def measure_text(node: EObject) -> str | None:
    """`reference points, longitudinal, lane` for what a measuring condition sets apart from
    its kind's defaults (between the boxes for the time conditions, between reference points
    for InVehicleRadius; straight line; the actor's frame); None when all are."""
    parts = []
    freespace = node.eClass.findEStructuralFeature("freespace")
    # Each kind's own default is quiet: InVehicleRadius measures between reference points
    # unless it says otherwise, the time conditions between the boxes.
    if freespace is not None and bool(node.freespace) != bool(freespace.get_default_value()):
        parts.append("bounding boxes" if node.freespace else "reference points")
    for name in ("relativeDistanceType", "coordinateSystem"):
        if node.eClass.findEStructuralFeature(name) is None:
            continue
        literal = node.eGet(name).name
        if literal != _MEASURE[name]:
            parts.append(f"{literal} coordinates" if name == "coordinateSystem" else literal)
    return ", ".join(parts) or None


def parameter_items(node: EObject, scope: Scope) -> Iterator[tuple[str, str]]:
    """(name, text) for every parameter the model sets on a node: numbers, positions, literals."""
    units = {spec.name: spec.unit for spec in catalog.parameters(node)}
    measured = measure_text(node)
    if measured:
        yield "measured", measured
    for feature in node.eClass.eAllStructuralFeatures():
        name = str(feature.name)
        if name in _NOT_PARAMETERS or name in _MEASURE or getattr(feature, "derived", False):
            continue
        held = node.eGet(feature)
        if isinstance(feature, EAttribute) and _quiet(node, name, held):
            continue
        if isinstance(feature, EAttribute):
            if name == "interrupts":
                yield name, interrupted_text(node)
            elif isinstance(feature.eType, EEnum) and held is not None:
                yield name, str(held.name if hasattr(held, "name") else held)
            elif held is not None and name != "description":
                yield name, str(held)
        elif isinstance(feature, EReference) and feature.containment:
            if name == "distance" and getattr(node, "timeGap", None) is not None:
                continue  # a time gap is kept instead (Follow, Approach)
            if units.get(name) == "m/s" and _backwards(_resolve(held, scope)):
                yield name, _reverse_text(node, held, scope)
                continue
            yield from _reference_items(name, held, units.get(name, ""), scope)


def interrupted_text(node: EObject) -> str:
    """What an interrupting maneuver ends when it starts: `the running longitudinal one`."""
    axes = " and ".join(sorted(maneuver_axes(node)))
    return f"the running {axes} one" if axes else "the running one"


def _backwards(value: scm.ParameterValue | None) -> bool:
    """A single speed below zero: driving backwards (release 1.4)."""
    return isinstance(value, scm.Value) and value.value is not None and value.value < 0


def _reverse_text(node: EObject, held: scm.ParameterValue, scope: Scope) -> str:
    """A negative speed as people say it: `reverse at 3 m/s = 10.8 km/h` for a speed to drive,
    `-0.01 m/s (reversing)` for a speed a condition compares with (its rule reads signed)."""
    resolved = _resolve(held, scope)
    assert isinstance(resolved, scm.Value) and resolved.value is not None
    if isinstance(node, scm.Condition):
        return f"{describe_value(held, 'm/s', scope)} (reversing)"
    size = scm.Value(value=-resolved.value)
    return f"reverse at {describe_value(size, 'm/s', scope)}"


def _reference_items(name: str, held: object, unit: str, scope: Scope) -> Iterator[tuple[str, str]]:
    if held is None:
        return
    if isinstance(held, scm.ParameterValue):
        yield name, describe_value(held, unit, scope)
    elif isinstance(held, scm.Position):
        yield name, describe_position(held, scope)
    elif isinstance(held, EObject):
        yield name, held.eClass.name
    else:
        points = list(held)  # type: ignore[call-overload]
        if points:
            yield name, f"{len(points)} points"


def action_lines(node: scm.ActionNode, scope: Scope) -> list[str]:
    """The lines under an action node's kind: its actors, then `name: value` per set parameter."""
    if isinstance(node, scm.OpaqueAction):
        runs = [f"maxRuns: {node.maxRuns}"] if node.maxRuns != 1 else []
        return [actor_line(node, scope), *opaque_lines(node), *runs]
    if not catalog.performed_by_actor(node):
        return global_lines(node)
    if isinstance(node, scm.ControllerManeuver):
        return [actor_line(node, scope), *controller_lines(node)]
    if isinstance(node, scm.CouplingManeuver):
        return [participant_text(node.referenceActor, scope), coupling_line(node, scope)]
    return [actor_line(node, scope), *(f"{k}: {v}" for k, v in parameter_items(node, scope))]


def coupling_line(node: scm.CouplingManeuver, scope: Scope) -> str:
    """What a trailer coupling does: `tows: trailer` (its target), or `uncouples its trailer`."""
    if isinstance(node, scm.ConnectTrailer):
        return f"tows: {participant_text(node.targetActor, scope)}"
    return "uncouples its trailer"


#: How a global node reads: a rule or change as its operator.
_OPERATORS = {
    "greaterThan": ">",
    "lessThan": "<",
    "equalTo": "==",
    "greaterOrEqual": ">=",
    "lessOrEqual": "<=",
    "set": "=",
    "add": "+=",
    "multiply": "*=",
}


def global_lines(node: scm.ActionNode) -> list[str]:
    """`global`, then what it reads or changes: `parameter Counter > 4`, `variable Counter += 2`,
    `signal 1 = off;off;on` (a state set), `signal 1 == off;off;on` (a state awaited)."""
    if isinstance(node, scm.TrafficSignalState | scm.TrafficSignalCondition):
        operator = "==" if isinstance(node, scm.Condition) else "="
        return ["global", f"signal {node.signalId or '(unnamed)'} {operator} {node.state or ''}"]
    word = "variable" if node.eClass.findEStructuralFeature("variable") else "parameter"
    named = str(node.eGet(word) or "") or "(unnamed)"
    how = node.rule if isinstance(node, scm.Condition) else node.modify
    operator = _OPERATORS.get(getattr(how, "name", ""), "?")
    return ["global", f"{word} {named} {operator} {node.value or ''}".rstrip()]


def controller_lines(node: scm.ControllerManeuver) -> list[str]:
    """A controller change: the controller assigned, the domains switched, the inputs overridden."""
    lines = []
    if isinstance(node, scm.AssignController) and node.controller is not None:
        lines.append(f"controller: {describe_controller(node.controller)}")
        lines.extend(f"  {p.name} = {p.value}" for p in node.controller.properties)
    switched = describe_activation(
        node.activation if isinstance(node, scm.AssignController) else node
    )
    if switched:
        lines.append(f"domains: {switched}")
    if isinstance(node, scm.OverrideController):
        lines.extend(describe_override(o) for o in node.overrides)
    return lines


def describe_controller(controller: scm.Controller) -> str:
    """`ACCController`, with its type when it has one: `ACCController (longitudinal)`."""
    kind = f" ({controller.controllerType})" if controller.controllerType else ""
    return f"{controller.name or '?'}{kind}"


def describe_activation(holder: object) -> str:
    """The domains a node or an actor switches: `lateral on, longitudinal off`."""
    parts = []
    for domain in CONTROLLER_DOMAINS:
        value = getattr(holder, domain, None)
        if value is not None:
            parts.append(f"{domain} {'on' if value else 'off'}")
    return ", ".join(parts)


def describe_override(override: scm.ControllerOverride) -> str:
    """One overridden input: `brake = 0.5` or `throttle released`."""
    kind = override.kind.name
    if not override.active:
        return f"{kind} released"
    value = f"{override.value:g}" + (" rad" if kind == "steeringWheel" else "")
    return f"{kind} = {value}"


def root_lines(root: scm.RootNode | None, scenario: scm.Scenario) -> list[str]:
    """The root box: level, map, duration and one line per actor."""
    if root is None:
        return ["(no root node)"]
    lines = [f"level: {root_level(root)}"]
    lines.append(f"map: {root.map or '(none)'}")
    if root.vehicleCatalog:
        lines.append(f"vehicle catalog: {root.vehicleCatalog}")
    if root.maxDuration is not None:
        lines.append(f"max duration: {params.describe(root.maxDuration, 's')}")
    lines.append("actors:")
    for actor in actors(scenario):
        ego = ", ego" if actor.isEgo else ""
        driven = f", {describe_controller(actor.controller)}" if actor.controller else ""
        tows = f", tows {actor.trailer.name}" if actor.trailer is not None else ""
        limits = _own_limits(actor)
        entry = f", catalog entry {actor.catalogEntry}" if actor.catalogEntry else ""
        lines.append(f"  {actor.name}: {actor.eClass.name}{ego}{driven}{tows}{limits}{entry}")
    return lines


def _own_limits(actor: scm.Actor) -> str:
    """`, top speed 70 m/s, max acceleration 5 m/s2`: the limits an actor states itself (release 1.4), which the
    players hold it to instead of its kind's."""
    parts = [
        f"{what} {params.describe(actor.eGet(feature), unit)}"
        for feature, what, unit in (
            ("maxSpeed", "top speed", "m/s"),
            ("maxAcceleration", "max acceleration", "m/s2"),
            ("maxDeceleration", "max deceleration", "m/s2"),
        )
        if actor.eGet(feature) is not None
    ]
    return "".join(f", {part}" for part in parts)


def scenario_title(scenario: scm.Scenario) -> str:
    """The scenario's name as its root node gives it."""
    root = root_node(scenario)
    return str(root.scenarioName or root.name or "Scenario") if root else "Scenario"


def loaded_definition(use: scm.ModuleUse) -> scm.ModuleDefinition | None:
    """The definition a use refers to, or None when it cannot be loaded (drawn as broken)."""
    try:
        return resolved_definition(use)
    except SceMLError:
        return None


def use_lines(use: scm.ModuleUse, scope: Scope) -> list[str]:
    """Role bindings and parameter overrides of a module use, one per line."""
    lines = [f"{b.role} = {participant_text(b.actor, scope)}" for b in use.bindings]
    definition = loaded_definition(use)
    parameters = definition.parameters if definition is not None else ()
    units = {str(p.name): str(p.unit or "") for p in parameters}
    for override in use.overrides:
        unit = units.get(str(override.parameter), "")
        lines.append(f"{override.parameter}: {describe_value(override.value, unit, scope)}")
    return lines


def definition_lines(definition: scm.ModuleDefinition) -> list[str]:
    """Roles with their allowed kinds and parameters with units and defaults."""
    lines = []
    for role in definition.roles:
        kinds = " | ".join(str(k.kind.name) for k in role.allowedKinds if k.kind is not None)
        lines.append(f"role {role.name}: {kinds or 'any'}")
    for parameter in definition.parameters:
        default = parameter.default
        unit = str(parameter.unit or "")
        shown = params.describe(default, unit_text(unit)) if default is not None else "required"
        lines.append(f"${parameter.name} ({unit or 'no unit'}): {shown}")
    return lines


def opaque_lines(node: scm.OpaqueAction) -> list[str]:
    """What an opaque node keeps: the OpenSCENARIO element's kind, its key values (the same
    words as the import report, `xosc.kept`) and the line it came from."""
    where = f"OpenSCENARIO {node.sourceVersion or '?'}, line {node.sourceLine or '?'}"
    try:
        element = etree.fromstring(str(node.xml or "").encode("utf-8"), hardened_parser())
    except etree.XMLSyntaxError:
        return ["(not well-formed)", where]  # SCEML-E006 says why
    values = key_values(element)
    return [kind_text(element), *([values] if values else []), where]

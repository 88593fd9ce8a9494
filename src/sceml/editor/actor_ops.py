"""Operations on actors and on module uses (role bindings and parameter overrides)."""

from __future__ import annotations

from typing import Any

from pyecore.ecore import EAttribute

import scemlmodel as scm

from ..model.traversal import attributes, containments
from ..modules import naming
from ..modules.library import definition_named
from ..modules.resolve import resolved_definition
from ..render.labels import loaded_definition
from .context import EditContext, argument, check_text, referrers, require
from .errors import OperationError
from .fields import actor_kind_names
from .node_ops import adopt, attribute_value, nested_holder, place, set_attribute
from .values import position_from_json, value_from_json

_ACTOR_TEXT_FIELDS = ("name", "isEgo", "model", "catalogEntry")
_ACTOR_PARAMETERS = (
    "initialSpeed",
    "length",
    "width",
    "height",
    "boxCenterX",
    "hitchX",
    "couplerX",
    "maxSpeed",
    "maxAcceleration",
    "maxDeceleration",
)


def _root(ctx: EditContext) -> scm.RootNode:
    root = ctx.root
    require(root is not None, "a module's roles are edited in its library, not here")
    return root


def _kind(kind: object) -> type:
    require(kind in actor_kind_names(), f"unknown actor kind {kind!r}")
    cls: type = getattr(scm, str(kind))
    return cls


def add_actor(ctx: EditContext, op: dict[str, Any]) -> None:
    """A new actor of a kind, named `car_1`, ... unless given a free name."""
    root = _root(ctx)
    cls = _kind(argument(op, "kind"))
    taken = {str(actor.name) for actor in root.actors}
    name = op.get("name") or naming.numbered(cls.__name__.lower(), taken)
    require(isinstance(name, str), "an actor's name must be text")
    check_text("name", name)
    require(name not in taken, f"an actor is already named {name!r}")
    actor = cls(name=name)
    ctx.rec.insert(root, "actors", actor)
    ctx.ids.of(actor, "a")


def remove_actor(ctx: EditContext, op: dict[str, Any]) -> None:
    """Remove an actor; nodes and role bindings referring to it lose the reference."""
    actor = ctx.actor(argument(op, "actor"))
    for holder, feature in list(referrers(ctx.graph, actor)):
        ctx.rec.set(holder, feature, None)
    ctx.rec.remove(_root(ctx), "actors", actor)


def set_actor(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set an actor's name, kind, ego flag, simulator model, catalog entry (release 1.5), or a
    field of its controller or of the domains switched at the start (`controller.name`,
    `controllerActivation.lateral`)."""
    actor = ctx.actor(argument(op, "actor"))
    field, value = argument(op, "field"), op.get("value")
    if field == "kind":
        _change_kind(ctx, actor, _kind(value))
        return
    nested = nested_holder(ctx, actor, str(field))
    if nested is not None:
        owner, name = nested
        feature = owner.eClass.findEStructuralFeature(name)
        require(isinstance(feature, EAttribute), f"an actor has no field {field!r} to set")
        set_attribute(ctx, owner, feature, attribute_value(feature, value))
        return
    if field == "trailer":
        _set_trailer(ctx, actor, value)
        return
    require(field in _ACTOR_TEXT_FIELDS, f"an actor has no field {field!r} to set")
    if field == "name":
        others = {str(a.name) for a in _root(ctx).actors if a is not actor}
        require(isinstance(value, str) and value.strip() != "", "an actor needs a name")
        require(value not in others, f"an actor is already named {value!r}")
    feature = actor.eClass.findEStructuralFeature(field)
    ctx.rec.set(actor, field, attribute_value(feature, value))


def _set_trailer(ctx: EditContext, actor: scm.Actor, value: object) -> None:
    """The actor this one tows, by name (null: none); SCEML-A009 judges chains and loops."""
    if value is None:
        ctx.rec.set(actor, "trailer", None)
        return
    towed = next((a for a in _root(ctx).actors if a.name == value), None)
    require(towed is not None, f"no actor is named {value!r}")
    require(towed is not actor, "an actor cannot tow itself")
    ctx.rec.set(actor, "trailer", towed)


def _change_kind(ctx: EditContext, actor: scm.Actor, cls: type) -> None:
    """Replace the actor by one of another class that keeps its values and every reference."""
    if actor.eClass.name == cls.__name__:
        return
    root = _root(ctx)
    index = list(root.actors).index(actor)
    replacement = cls()
    for feature in attributes(actor.eClass):
        if actor.eIsSet(feature):
            replacement.eSet(feature.name, actor.eGet(feature))
    referring = list(referrers(ctx.graph, actor))
    ctx.rec.remove(root, "actors", actor)
    ctx.rec.insert(root, "actors", replacement, index)
    for feature in containments(actor.eClass):
        held = actor.eGet(feature)
        if held is not None:
            ctx.rec.set(replacement, feature.name, held)
    for holder, name in referring:
        ctx.rec.set(holder, name, replacement)
    ctx.ids.of(actor, "a")
    ctx.ids.inherit(replacement, actor)


def set_actor_parameter(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set (or unset) an actor's initial speed, bounding-box dimension, hitch or coupler, or
    its own performance limit (release 1.4)."""
    actor = ctx.actor(argument(op, "actor"))
    field = argument(op, "field")
    require(field in _ACTOR_PARAMETERS, f"an actor has no parameter {field!r}")
    ctx.rec.set(actor, field, value_from_json(op.get("value")))


def set_actor_position(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set (or unset) an actor's start position."""
    actor = ctx.actor(argument(op, "actor"))
    ctx.rec.set(
        actor, "startPosition", position_from_json(op.get("value"), participants=ctx.participants())
    )


def add_module_use(ctx: EditContext, op: dict[str, Any]) -> None:
    """A use of a library module, named `<Module>_<n>`, with role bindings and overrides."""
    library, _ = ctx.find_library(str(argument(op, "library")), False)
    try:
        definition = definition_named(library, str(argument(op, "module")))
    except Exception as error:
        raise OperationError(str(getattr(error, "message", error))) from None
    require(
        not _uses_itself(ctx.graph, definition),
        f"{definition.name} cannot be used inside its own definition",
    )
    bindings, overrides = op.get("bindings") or {}, op.get("overrides") or {}
    require(isinstance(bindings, dict) and isinstance(overrides, dict), "bad bindings/overrides")
    roles = [str(role.name) for role in definition.roles]
    unknown = sorted(set(bindings) - set(roles))
    require(not unknown, f"{definition.name} has no role {', '.join(unknown)}")
    declared = {str(p.name) for p in definition.parameters}
    unknown = sorted(set(overrides) - declared)
    require(not unknown, f"{definition.name} has no parameter {', '.join(unknown)}")
    use = scm.ModuleUse(name=naming.numbered(str(definition.name), ctx.node_names()))
    use.definition = definition
    for role in roles:
        use.bindings.append(scm.RoleBinding(role=role, actor=ctx.participant(bindings.get(role))))
    for name, given in overrides.items():
        value = value_from_json(given, ctx.parameter_lookup)
        if value is not None:
            use.overrides.append(scm.ParameterOverride(parameter=name, value=value))
    adopt(ctx, use)
    if op.get("position") is not None:
        place(ctx, use, op["position"])


def _uses_itself(graph: scm.Graph, definition: scm.ModuleDefinition) -> bool:
    """Whether using `definition` in `graph` would make a module use itself (through others)."""
    if not isinstance(graph, scm.ModuleDefinition):
        return False
    pending, seen = [definition], set()
    while pending:
        current = pending.pop()
        if current is graph:
            return True
        if id(current) in seen:
            continue
        seen.add(id(current))
        for node in current.nodes:
            inner = loaded_definition(node) if isinstance(node, scm.ModuleUse) else None
            if inner is not None:
                pending.append(inner)
    return False


def _use(ctx: EditContext, op: dict[str, Any]) -> tuple[scm.ModuleUse, scm.ModuleDefinition]:
    use = ctx.node(argument(op, "node"))
    require(isinstance(use, scm.ModuleUse), f"{use.name} is not a module use")
    try:
        return use, resolved_definition(use)
    except Exception as error:
        raise OperationError(str(getattr(error, "message", error))) from None


def bind_role(ctx: EditContext, op: dict[str, Any]) -> None:
    """Bind a role of a module use to an actor (null unbinds it)."""
    use, definition = _use(ctx, op)
    role = argument(op, "role")
    require(
        role in {str(r.name) for r in definition.roles}, f"{definition.name} has no role {role!r}"
    )
    actor = ctx.participant(op.get("actor"))
    binding = next((b for b in use.bindings if b.role == role), None)
    if binding is None:
        ctx.rec.insert(use, "bindings", scm.RoleBinding(role=role, actor=actor))
    else:
        ctx.rec.set(binding, "actor", actor)


def set_override(ctx: EditContext, op: dict[str, Any]) -> None:
    """Override a module parameter in a use (null removes the override: the default applies)."""
    use, definition = _use(ctx, op)
    name = argument(op, "parameter")
    declared = {str(p.name) for p in definition.parameters}
    require(name in declared, f"{definition.name} has no parameter {name!r}")
    value = value_from_json(op.get("value"), ctx.parameter_lookup)
    override = next((o for o in use.overrides if o.parameter == name), None)
    if value is None:
        if override is not None:
            ctx.rec.remove(use, "overrides", override)
    elif override is None:
        ctx.rec.insert(use, "overrides", scm.ParameterOverride(parameter=name, value=value))
    else:
        ctx.rec.set(override, "value", value)

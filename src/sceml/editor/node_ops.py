"""Operations on nodes and flows: add, delete, connect, move, and set a node's fields."""

from __future__ import annotations

import math
from typing import Any

from pyecore.ecore import EAttribute, EEnum, EObject, EReference, EStructuralFeature

import scemlmodel as scm

from .. import catalog
from ..modules import naming
from .context import EditContext, argument, check_text, require
from .errors import OperationError
from .fields import type_name
from .nested import blank, nested_feature, removes
from .values import position_from_json, value_from_json

#: Node kinds the palette adds besides the action nodes.
JOIN_KINDS = ("JoinAllFinished", "JoinOneFinished")
#: Nodes every graph keeps: they cannot be deleted, added or pasted.
FIXED = (scm.RootNode, scm.EndNode, scm.InPort, scm.OutPort)


def addable_kinds() -> list[str]:
    """Every node kind `add_node` accepts: the concrete action nodes, then the joins."""
    return [cls.__name__ for cls in catalog.action_node_kinds()] + list(JOIN_KINDS)


def place(ctx: EditContext, node: scm.GraphElement, position: object) -> None:
    """Set a node's diagram position from `{"x", "y"}` (None: laid out automatically)."""
    if position is None:
        ctx.rec.set(node, "diagramPosition", None)
        return
    x, y = _coordinates(position)
    held = node.diagramPosition
    if held is None:
        ctx.rec.set(node, "diagramPosition", scm.DiagramPosition(x=x, y=y))
    else:
        ctx.rec.set(held, "x", x)
        ctx.rec.set(held, "y", y)


def _coordinates(position: object) -> tuple[float, float]:
    if not isinstance(position, dict):
        raise OperationError(f"a position must be {{'x': ..., 'y': ...}}, not {position!r}")
    found = []
    for key in ("x", "y"):
        given = position.get(key)
        if isinstance(given, bool) or not isinstance(given, int | float):
            raise OperationError(f"position {key} must be a number, not {given!r}")
        require(math.isfinite(given), f"position {key} must be finite")
        found.append(float(given))
    return found[0], found[1]


def adopt(ctx: EditContext, node: scm.GraphElement) -> str:
    """Put a new node in the graph and note its id among the created ones."""
    ctx.rec.insert(ctx.graph, "nodes", node)
    made = ctx.ids.of(node, "n")
    ctx.created.append(made)
    return made


def add_node(ctx: EditContext, op: dict[str, Any]) -> None:
    """A new action node or join, named `<Kind>_<n>`, optionally performed by `actor`."""
    kind = argument(op, "kind")
    require(kind in addable_kinds(), f"cannot add a node of kind {kind!r}")
    node = getattr(scm, kind)(name=naming.numbered(kind, ctx.node_names()))
    # The palette adds with the actor in view; a global kind (SetParameter, ...) takes none.
    if op.get("actor") is not None and catalog.performed_by_actor(kind):
        require(isinstance(node, scm.ActionNode), f"a {kind} has no actor")
        node.referenceActor = ctx.participant(op["actor"])
    adopt(ctx, node)
    if op.get("position") is not None:
        place(ctx, node, op["position"])


def detach_flow(ctx: EditContext, flow: scm.Flow) -> None:
    """Take a flow out of the graph and off both its ends (undo puts it back as it was)."""
    ctx.rec.remove(ctx.graph, "flows", flow)
    ctx.rec.set(flow, "source", None)
    ctx.rec.set(flow, "target", None)


def delete(ctx: EditContext, op: dict[str, Any]) -> None:
    """Delete nodes (with their flows) and flows; the root, end and ports stay."""
    nodes = [ctx.node(i) for i in op.get("nodes") or []]
    nodes = [node for node in nodes if not isinstance(node, FIXED)]
    flows = [ctx.flow(i) for i in op.get("edges") or []]
    doomed = set(nodes)
    # graph.flows is what validation reads, so every flow touching a deleted node leaves it.
    flows += [f for f in ctx.graph.flows if f.source in doomed or f.target in doomed]
    for flow in dict.fromkeys(flows):
        detach_flow(ctx, flow)
    for node in dict.fromkeys(nodes):
        ctx.rec.remove(ctx.graph, "nodes", node)


def connect(ctx: EditContext, op: dict[str, Any]) -> None:
    """A flow from `source` to `target`: refused for loops, duplicates, into root, out of end."""
    source, target = ctx.node(argument(op, "source")), ctx.node(argument(op, "target"))
    require(source is not target, "a node cannot lead to itself")
    require(not isinstance(target, scm.RootNode | scm.InPort), "nothing can lead into the start")
    require(not isinstance(source, scm.EndNode | scm.OutPort), "nothing can follow the end")
    duplicate = any(f.source is source and f.target is target for f in ctx.graph.flows)
    require(not duplicate, f"{source.name} already leads to {target.name}")
    flow = scm.Flow()
    ctx.rec.insert(ctx.graph, "flows", flow)
    ctx.rec.set(flow, "source", source)
    ctx.rec.set(flow, "target", target)
    ctx.ids.of(flow, "f")


def move(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set the diagram positions of nodes."""
    positions = argument(op, "positions")
    require(isinstance(positions, dict), "'positions' must map node ids to {x, y}")
    for identifier, position in positions.items():
        place(ctx, ctx.node(identifier), position)


def _holder(ctx: EditContext, node: scm.GraphElement, field: str) -> tuple[EObject, str]:
    """The object and feature a field name means (`environment.x` is the root's environment,
    `controller.name` an AssignController's controller)."""
    if isinstance(node, scm.RootNode) and field.startswith("environment."):
        if node.environment is None:
            ctx.rec.set(node, "environment", scm.Environment())
        return node.environment, field.removeprefix("environment.")
    return nested_holder(ctx, node, field) or (node, field)


def nested_holder(ctx: EditContext, owner: EObject, field: str) -> tuple[EObject, str] | None:
    """The contained object a prefixed field is an attribute of, made when still unset."""
    found = nested_feature(owner, field)
    if found is None:
        return None
    feature, attribute = found
    if owner.eGet(feature) is None:
        ctx.rec.set(owner, str(feature.name), blank(feature))
    return owner.eGet(feature), attribute


def _feature(owner: EObject, name: str, node: scm.GraphElement) -> EStructuralFeature:
    feature = owner.eClass.findEStructuralFeature(name)
    hidden = ("incoming", "outgoing", "diagramPosition", "actors", "definition")
    if feature is None or name in hidden:
        raise OperationError(f"a {node.eClass.name} has no field {name!r}")
    return feature


def set_field(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set a text, enum, bool or actor field of a node."""
    node = ctx.node(argument(op, "node"))
    name, value = argument(op, "field"), op.get("value")
    owner, feature_name = _holder(ctx, node, str(name))
    feature = _feature(owner, feature_name, node)
    if isinstance(feature, EReference) and type_name(feature) == "Participant":
        ctx.rec.set(owner, feature_name, ctx.participant(value))
        return
    require(isinstance(feature, EAttribute), f"{name!r} is not set with 'set'; see its type")
    if feature_name == "name" and owner is node:
        _check_name(ctx, node, value)
    set_attribute(ctx, owner, feature, attribute_value(feature, value))


def set_attribute(ctx: EditContext, owner: EObject, feature: EAttribute, value: object) -> None:
    """Set an attribute; a controller whose name is emptied is removed from its holder."""
    holder, containment = owner.eContainer(), owner.eContainmentFeature()
    if holder is not None and removes(containment, str(feature.name), value):
        ctx.rec.set(holder, str(containment.name), None)
        return
    ctx.rec.set(owner, str(feature.name), value)


def attribute_value(feature: EAttribute, value: object) -> object:
    """A JSON value as the attribute's type: an enum literal, a bool, a string."""
    kind = feature.eType
    if isinstance(kind, EEnum):
        literal = kind.getEEnumLiteral(value) if isinstance(value, str) else None
        options = ", ".join(str(item.name) for item in kind.eLiterals)
        require(literal is not None, f"{feature.name} must be one of {options}, not {value!r}")
        return literal
    if type_name(feature) == "EBooleanObject" and value is None:
        return None  # unset: e.g. a controller domain left as it is
    if type_name(feature) in ("EBoolean", "EBooleanObject"):
        require(isinstance(value, bool), f"{feature.name} must be true or false")
        return value
    if type_name(feature) in ("EInt", "EIntegerObject"):
        return _integer(feature, value)
    require(value is None or isinstance(value, str), f"{feature.name} must be text")
    if isinstance(value, str):
        check_text(str(feature.name), value)
    return value or None


def _integer(feature: EAttribute, value: object) -> int | None:
    """A whole number, given as a number or as the text of a text field (a lane id, a count);
    empty unsets an optional one (EIntegerObject)."""
    optional = type_name(feature) == "EIntegerObject"
    if optional and (value is None or (isinstance(value, str) and not value.strip())):
        return None
    number: int | None = None
    if isinstance(value, str):
        try:
            number = int(value.strip())
        except ValueError:
            number = None
    elif isinstance(value, int) and not isinstance(value, bool):
        number = value
    wanted = f"{feature.name} must be a whole number" + (" or empty" if optional else "")
    require(number is not None and abs(number) < 2**31, wanted)
    return number


def _check_name(ctx: EditContext, node: scm.GraphElement, value: object) -> None:
    require(isinstance(value, str) and value.strip() != "", "a node needs a name")
    others = {str(n.name) for n in ctx.graph.nodes if n is not node}
    require(value not in others, f"another node is already named {value!r}")


def set_parameter(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set (or unset, with null) a numeric parameter of a node or of the root's environment."""
    node = ctx.node(argument(op, "node"))
    owner, name = _holder(ctx, node, str(argument(op, "field")))
    if name not in {spec.name for spec in catalog.parameters(owner)}:
        raise OperationError(f"a {node.eClass.name} has no parameter {op['field']!r}")
    ctx.rec.set(owner, name, value_from_json(op.get("value"), ctx.parameter_lookup))


def set_position(ctx: EditContext, op: dict[str, Any]) -> None:
    """Set (or unset) a position field of a node (destination, position)."""
    node = ctx.node(argument(op, "node"))
    name = str(argument(op, "field"))
    feature = _feature(node, name, node)
    if type_name(feature) != "Position" or feature.many:
        raise OperationError(f"{name!r} of a {node.eClass.name} is not a position")
    ctx.rec.set(
        node, name, position_from_json(op.get("value"), ctx.parameter_lookup, ctx.participants())
    )


def set_waypoints(ctx: EditContext, op: dict[str, Any]) -> None:
    """Replace the waypoints of a trajectory."""
    node = ctx.node(argument(op, "node"))
    given = argument(op, "value")
    require(node.eClass.findEStructuralFeature("waypoints") is not None, "no waypoints here")
    require(isinstance(given, list), "'value' must be a list of positions")
    made = [position_from_json(item, ctx.parameter_lookup, ctx.participants()) for item in given]
    require(all(p is not None for p in made), "a waypoint cannot be empty")
    for old in list(node.waypoints):
        ctx.rec.remove(node, "waypoints", old)
    for position in made:
        ctx.rec.insert(node, "waypoints", position)

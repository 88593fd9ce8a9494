"""The protocol's operations by name, and the one function that applies one of them."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from . import actor_ops, node_ops
from .clipboard import paste
from .context import EditContext
from .errors import OperationError
from .extracting import extract_module

Operation = Callable[[EditContext, dict[str, Any]], None]

OPERATIONS: dict[str, Operation] = {
    "add_node": node_ops.add_node,
    "add_module_use": actor_ops.add_module_use,
    "delete": node_ops.delete,
    "connect": node_ops.connect,
    "move": node_ops.move,
    "set": node_ops.set_field,
    "set_parameter": node_ops.set_parameter,
    "set_position": node_ops.set_position,
    "set_waypoints": node_ops.set_waypoints,
    "add_actor": actor_ops.add_actor,
    "remove_actor": actor_ops.remove_actor,
    "set_actor": actor_ops.set_actor,
    "set_actor_parameter": actor_ops.set_actor_parameter,
    "set_actor_position": actor_ops.set_actor_position,
    "bind_role": actor_ops.bind_role,
    "set_override": actor_ops.set_override,
    "paste": paste,
    "extract_module": extract_module,
}


#: Operations that also change what the undo records do not show (extract_module writes the new
#: module into its library): the editor validates the whole model after them.
OUTSIDE = frozenset({"extract_module"})


def apply(ctx: EditContext, op: object) -> None:
    """Apply one operation (a dict with an `op` name) to the context's graph."""
    if not isinstance(op, dict):
        raise OperationError(f"an operation must be an object, not {op!r}")
    name = op.get("op")
    if name not in OPERATIONS:
        raise OperationError(f"unknown operation {name!r}")
    OPERATIONS[name](ctx, op)


def label_of(ops: list[Any]) -> str:
    """An undo label for a request without one: `Add Accelerate`, `Delete`, `Move`, ..."""
    if not ops or not isinstance(ops[0], dict) or ops[0].get("op") not in OPERATIONS:
        return "Edit"  # a request the first op of which is refused, so no step is made
    first = ops[0]
    name = str(first["op"])
    words = name.replace("_", " ").capitalize()
    if name == "add_node" and first.get("kind"):
        words = f"Add {first['kind']}"
    elif name == "add_module_use" and first.get("module"):
        words = f"Add {first['module']}"
    return words if len(ops) == 1 else f"{words} (+{len(ops) - 1})"

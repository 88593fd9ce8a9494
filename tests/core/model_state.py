"""The full internal pyecore state of a model, as plain data two models can be compared by.

Written for the fast reader and copier tests: it reads pyecore's private fields directly (never
through descriptors, which would create holders) so that the state compared is the state built,
and it names objects by their containment path, so that two separately built models compare.
"""

from __future__ import annotations

from typing import Any

from pyecore.ecore import EEnumLiteral, EObject, EProxy, EReference
from pyecore.valuecontainer import ECollection, EValue

Names = dict[int, str]


def _own(obj: Any, name: str) -> Any:
    # Reads through object.__getattribute__, so a proxy is never resolved by looking at it.
    return object.__getattribute__(obj, name)


def paths(roots: dict[str, EObject]) -> Names:
    """Every object below each named root, by id, named `<root>//@feature.index/...`."""
    names: Names = {}
    pending = [(root, label) for label, root in roots.items()]
    while pending:
        obj, name = pending.pop()
        names[id(obj)] = name
        for feature in obj.eClass.eAllStructuralFeatures():
            if not isinstance(feature, EReference) or not feature.containment:
                continue
            held = _own(obj, "__dict__").get(feature.name)
            if held is None:
                continue
            if isinstance(held, ECollection):
                for index, child in enumerate(held.items):
                    pending.append((child, f"{name}/@{feature.name}.{index}"))
            elif held._value is not None:
                pending.append((held._value, f"{name}/@{feature.name}"))
    return names


def feature_name(feature: Any) -> str:
    """A feature as `Class.name` (features are compared by identity, shown by name)."""
    return f"{feature.eContainingClass.name}.{feature.name}#{id(feature)}"


def outside_name(obj: EObject) -> str:
    """An object that is not below the compared roots, named by its own root and path."""
    steps = []
    while True:
        container = _own(obj, "_container")
        feature = _own(obj, "_containment_feature")
        if container is None or feature is None:
            break
        held = _own(container, "__dict__").get(feature.name)
        index = held.items.index(obj) if isinstance(held, ECollection) else None
        steps.append(f"@{feature.name}" + ("" if index is None else f".{index}"))
        obj = container
    label = _own(obj, "__dict__").get("name")
    top = f"{type(obj).__name__}({label._value if isinstance(label, EValue) else ''})"
    return "outside:" + "/".join([top, *reversed(steps)])


def value(item: Any, names: Names) -> Any:
    """A value of a feature, a reference or a container as comparable data."""
    if item is None or isinstance(item, bool | int | float | str):
        return (type(item).__name__, repr(item))
    if type(item) is EProxy:
        return (
            "proxy",
            _own(item, "_proxy_path"),
            _own(item, "resolved"),
            sorted(
                (names.get(id(o), "?"), feature_name(f)) for o, f in _own(item, "_inverse_rels")
            ),
        )
    if isinstance(item, EEnumLiteral):
        return ("literal", item.eContainer().name, item.name, id(item))
    if isinstance(item, EObject):
        return ("object", names.get(id(item)) or outside_name(item))
    return ("other", type(item).__name__, repr(item))


def holder_state(holder: Any, owner: EObject, names: Names) -> dict[str, Any]:
    """An EValue or collection: its class, fields in order, and what it holds."""
    fields = dict(_own(holder, "__dict__"))
    state: dict[str, Any] = {
        "class": type(holder).__name__,
        "fields": list(fields),
        "owner is the object": fields.pop("owner") is owner,
        "feature": feature_name(fields.pop("feature")),
        "is_ref": fields.pop("is_ref"),
        "is_cont": fields.pop("is_cont"),
        "generic_type": fields.pop("generic_type"),
    }
    if isinstance(holder, EValue):
        state["value"] = value(fields.pop("_value"), names)
    else:
        items = fields.pop("items")
        index = fields.pop("map")
        state["items"] = [value(item, names) for item in items]
        state["map matches items"] = index == {item: i for i, item in enumerate(items)}
        state["_orderedset_update"] = fields.pop("_orderedset_update", None)
    state["other fields"] = sorted(fields)
    return state


def _untouched(obj: EObject, name: str, held: Any) -> bool:
    # A holder pyecore made only because the feature was read: not set, holding nothing new.
    feature = held.feature
    if feature in _own(obj, "_isset"):
        return False
    if isinstance(held, ECollection):
        return not held.items
    return bool(held._value is None or held._value == feature.get_default_value())


def object_state(obj: EObject, names: Names, read_holders: bool = True) -> dict[str, Any]:
    """One object's whole state: class, bookkeeping fields, holders, inverse relations.

    With `read_holders=False`, holders that only reading a feature creates are left out (two
    models that differ only in which unset features were read compare equal).
    """
    fields = dict(_own(obj, "__dict__"))
    if not read_holders:
        fields = {
            name: held
            for name, held in fields.items()
            if not (isinstance(held, EValue | ECollection) and _untouched(obj, name, held))
        }
    holders = {
        name: holder_state(held, obj, names)
        for name, held in fields.items()
        if isinstance(held, EValue | ECollection)
    }
    return {
        "class": type(obj).__name__,
        "fields": list(fields),
        "_internal_id": fields["_internal_id"],
        "_isset": [feature_name(f) for f in fields["_isset"]],
        "_isset values": list(fields["_isset"].values()),
        "_container": value(fields["_container"], names),
        "_containment_feature": (
            None
            if fields["_containment_feature"] is None
            else feature_name(fields["_containment_feature"])
        ),
        "_eresource": fields["_eresource"] is not None,
        "listeners": fields["listeners"],
        "_eternal_listener": fields["_eternal_listener"],
        "_inverse_rels": sorted(
            (value(o, names), feature_name(f)) for o, f in fields["_inverse_rels"]
        ),
        "_staticEClass": fields["_staticEClass"],
        "dyn_inst is itself": fields["dyn_inst"] is obj,
        "registered": obj in EObject._instances,
        "holders": holders,
    }


def model_state(roots: dict[str, EObject], read_holders: bool = True) -> dict[str, dict[str, Any]]:
    """The state of every object below the named roots, by path (see `object_state`)."""
    names = paths(roots)
    by_id = {}
    pending = list(roots.values())
    while pending:
        obj = pending.pop()
        by_id[id(obj)] = obj
        for feature in obj.eClass.eAllStructuralFeatures():
            if isinstance(feature, EReference) and feature.containment:
                held = _own(obj, "__dict__").get(feature.name)
                if isinstance(held, ECollection):
                    pending.extend(held.items)
                elif held is not None and held._value is not None:
                    pending.append(held._value)
    return {names[key]: object_state(obj, names, read_holders) for key, obj in by_id.items()}


def resource_state(resource: Any, names: Names) -> dict[str, Any]:
    """What a loaded resource holds besides its objects."""
    return {
        "contents": [value(root, names) for root in resource.contents],
        "uuid_dict": [(key, value(obj, names)) for key, obj in resource.uuid_dict.items()],
        "use_uuid": resource.use_uuid,
        "sceml_ids": [
            (key, value(obj, names), line) for key, (obj, line) in resource._sceml_ids.items()
        ],
        "_later": list(resource._later),
        "_resolve_mem": dict(resource._resolve_mem),
        "prefixes": dict(resource.prefixes),
        "cache_enabled": resource.cache_enabled,
        "last node": resource._sceml_node.sourceline,
        "tree": resource.sceml_tree is not None,
        "lines": sorted(
            (value(obj, names), line) for obj, line in getattr(resource, "sceml_lines", {}).items()
        ),
    }


def difference(left: Any, right: Any, where: str = "") -> str | None:
    """The first place two states differ, readably, or None."""
    if isinstance(left, dict) and isinstance(right, dict):
        if list(left) != list(right):
            return f"{where}: keys {list(left)} != {list(right)}"
        for key in left:
            found = difference(left[key], right[key], f"{where}/{key}")
            if found:
                return found
        return None
    if isinstance(left, list) and isinstance(right, list) and len(left) == len(right):
        for index, (a, b) in enumerate(zip(left, right, strict=True)):
            found = difference(a, b, f"{where}[{index}]")
            if found:
                return found
        return None
    return None if left == right else f"{where}: {left!r} != {right!r}"

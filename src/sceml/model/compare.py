"""Compare two models object by object: every attribute, containment and reference."""

from __future__ import annotations

import math
from pathlib import Path

from pyecore.ecore import EAttribute, EObject, EProxy, EReference


def _same_value(left: object, right: object) -> bool:
    if isinstance(left, float) and isinstance(right, float):
        return left == right or (math.isnan(left) and math.isnan(right))
    return left == right


def reference_key(target: EObject | None, holder: EObject | None = None) -> str | None:
    """How a reference target is identified: its URI fragment, plus its file name when the target
    lives in another file than `holder`."""
    if target is None:
        return None
    if isinstance(target, EProxy):
        try:
            target.force_resolve()
        except Exception:
            return f"unresolved:{target._proxy_path}"
    resource = target.eResource
    if holder is not None and resource is holder.eResource:
        return f"#{target.eURIFragment()}"
    file = Path(resource.uri.normalize()).name if resource is not None else ""
    return f"{file}#{target.eURIFragment()}"


def differences(left: EObject, right: EObject, path: str = "") -> list[str]:
    """Where two models differ, as readable lines; empty when they are equal."""
    found: list[str] = []
    _compare(left, right, path or "/", found)
    return found


def _compare(left: EObject, right: EObject, path: str, found: list[str]) -> None:
    if left.eClass.name != right.eClass.name:
        found.append(f"{path}: {left.eClass.name} != {right.eClass.name}")
        return
    for feature in left.eClass.eAllStructuralFeatures():
        if feature.derived or feature.transient:
            continue
        here = f"{path}/{feature.name}"
        a, b = left.eGet(feature), right.eGet(feature.name)
        if isinstance(feature, EAttribute):
            a_values = list(a) if feature.many else [a]
            b_values = list(b) if feature.many else [b]
            if len(a_values) != len(b_values) or not all(
                _same_value(x, y) for x, y in zip(a_values, b_values, strict=True)
            ):
                found.append(f"{here}: {a!r} != {b!r}")
        elif isinstance(feature, EReference):
            a_items = list(a) if feature.many else ([a] if a is not None else [])
            b_items = list(b) if feature.many else ([b] if b is not None else [])
            if len(a_items) != len(b_items):
                found.append(f"{here}: {len(a_items)} items != {len(b_items)}")
                continue
            for index, (x, y) in enumerate(zip(a_items, b_items, strict=True)):
                where = f"{here}[{index}]" if feature.many else here
                if feature.containment:
                    _compare(x, y, where, found)
                elif reference_key(x, left) != reference_key(y, right):
                    key_x, key_y = reference_key(x, left), reference_key(y, right)
                    found.append(f"{where}: -> {key_x} != {key_y}")

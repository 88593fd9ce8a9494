"""Which differences between two releases of the metamodel break files saved with the older one.

Breaking: a class or feature removed or renamed, a class made abstract, a feature's type or kind
changed, a multiplicity narrowed, a feature made required, a required feature added without a
default, an enum literal removed. Additive changes (new classes, new optional features, new
literals, wider multiplicities) leave every old file readable and need no migration.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from .ecore import Feature, Metamodel


@dataclass(frozen=True)
class BreakingChange:
    kind: str  # class-removed, class-abstract, feature-removed, feature-type,
    #            multiplicity-narrowed, made-required, required-added, literal-removed
    cls: str  # the class that declared the feature (the enum, for literals)
    feature: str | None
    detail: str

    def describe(self) -> str:
        return self.detail


def breaking_changes(
    old: Metamodel, new: Metamodel, renamed: Mapping[str, str] | None = None
) -> list[BreakingChange]:
    """What in `new` would make files saved with `old` unreadable, ignoring migrations.

    `renamed` maps old class names to new ones (a step's renames), so that the features of a
    renamed class are compared with its new self.
    """
    renamed = renamed or {}
    found: dict[tuple[str, str, str | None], BreakingChange] = {}

    def add(kind: str, cls: str, feature: str | None, detail: str) -> None:
        found.setdefault((kind, cls, feature), BreakingChange(kind, cls, feature, detail))

    for name, info in old.classes.items():
        now = renamed.get(name, name)
        if now not in new.classes:
            add("class-removed", name, None, f"class {name} was removed or renamed")
            continue
        if not info.abstract and new.classes[now].abstract:
            add("class-abstract", name, None, f"class {name} became abstract")
        if info.abstract:
            continue  # its features are compared through its concrete subclasses
        old_features, new_features = old.features(name), new.features(now)
        for feature_name, before in old_features.items():
            if before.transient:
                continue  # never written to a file
            owner = _declaring(old, name, feature_name)
            after = new_features.get(feature_name)
            if after is None:
                add(
                    "feature-removed",
                    owner,
                    feature_name,
                    f"feature {owner}.{feature_name} was removed or renamed",
                )
                continue
            _compare(new, owner, before, after, renamed, add)
        for feature_name, after in new_features.items():
            if feature_name in old_features or after.transient:
                continue
            if after.lower >= 1 and after.default is None:
                owner = _declaring(new, now, feature_name)
                add(
                    "required-added",
                    owner,
                    feature_name,
                    f"feature {owner}.{feature_name} is new and required, with no default",
                )
    for enum, literals in old.enums.items():
        for literal in literals:
            if literal not in new.enums.get(enum, ()):
                add(
                    "literal-removed",
                    enum,
                    literal,
                    f"literal {enum}.{literal} was removed or renamed",
                )
    return list(found.values())


def _compare(
    new: Metamodel,
    owner: str,
    before: Feature,
    after: Feature,
    renamed: Mapping[str, str],
    add: Callable[[str, str, str | None, str], None],
) -> None:
    name = f"{owner}.{before.name}"
    same_type = renamed.get(before.type, before.type) == after.type
    widened = (
        before.kind == after.kind == "reference"
        and renamed.get(before.type, before.type) in new.classes
        and after.type in new.ancestors(renamed.get(before.type, before.type))
    )
    if before.kind != after.kind or before.containment != after.containment:
        add(
            "feature-type",
            owner,
            before.name,
            f"feature {name} changed from {before.describe()} to {after.describe()}",
        )
    elif not (same_type or widened):
        add(
            "feature-type",
            owner,
            before.name,
            f"feature {name} changed type from {before.type} to {after.type}",
        )
    if before.upper == -1 and after.upper != -1 or 0 < after.upper < before.upper:
        add(
            "multiplicity-narrowed",
            owner,
            before.name,
            f"feature {name} narrowed from {before.describe()} to {after.describe()}",
        )
    if after.lower > before.lower:
        add(
            "made-required",
            owner,
            before.name,
            f"feature {name} became required ({before.describe()} -> {after.describe()})",
        )


def _declaring(metamodel: Metamodel, cls: str, feature: str) -> str:
    for ancestor in metamodel.ancestors(cls):
        if feature in metamodel.classes[ancestor].own:
            return ancestor
    return cls

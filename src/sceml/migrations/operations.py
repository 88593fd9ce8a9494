"""The operations a migration step is made of, each a small rewrite of the parsed file.

Every operation names classes and features as they were in the release the step starts from,
and knows which breaking changes of the metamodel it accounts for (`covers`), so that the release
check can tell a migrated change from a forgotten one.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

from lxml import etree

from .compat import BreakingChange
from .ecore import Metamodel
from .report import Change
from .tree import XSI_TYPE, TreeModel, path

#: Functions that compute a value for an element of an old file, named in migrations as
#: `compute: NAME`. They receive the element and the tree model and return the attribute's text.
COMPUTED: dict[str, Callable[[etree._Element, TreeModel], str | None]] = {}
#: Conversions named in migrations as `convert: {function: NAME}`: old text to new text.
CONVERSIONS: dict[str, Callable[[str], str]] = {}


class Recorder:
    """Collects the changes of one step, located in the file as it was read."""

    def __init__(self, step: str) -> None:
        self.step = step
        self.changes: list[Change] = []

    def add(self, operation: str, element: etree._Element, detail: str, note: str = "") -> None:
        self.changes.append(
            Change(self.step, operation, path(element), element.sourceline, detail, note)
        )


@dataclass(frozen=True)
class Operation:
    """The base of every operation: apply it, check it names real things, say what it covers."""

    name: ClassVar[str]

    def apply(self, model: TreeModel, record: Recorder) -> None:
        raise NotImplementedError

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        """What the operation names that the releases do not have."""
        return []

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return False

    def describe(self) -> str:
        raise NotImplementedError


def _related(old: Metamodel, a: str, b: str) -> bool:
    return old.is_kind_of(a, b) or old.is_kind_of(b, a)


def _accounts_for_removal(change: BreakingChange, old: Metamodel, cls: str, feature: str) -> bool:
    """Whether `change` is the removal of `feature` from `cls` (or a class related to it)."""
    return (
        change.kind == "feature-removed"
        and change.feature == feature
        and _related(old, change.cls, cls)
    )


def _new_child(model: TreeModel, parent: etree._Element, tag: str, kind: str) -> etree._Element:
    """A contained element of class `kind`, placed at its parent's line (it has none of its own)."""
    child = etree.SubElement(parent, tag)
    child.set(XSI_TYPE, f"{model.prefix}:{kind}")
    child.sourceline = parent.sourceline
    model.classes[child] = kind
    return child


def _need_class(old: Metamodel, cls: str, what: str) -> list[str]:
    return [] if cls in old.classes else [f"{what}: release {old.version} has no class {cls}"]


def _need_feature(old: Metamodel, cls: str, feature: str, what: str) -> list[str]:
    missing = _need_class(old, cls, what)
    if missing:
        return missing
    if old.feature(cls, feature) is None:
        return [f"{what}: {cls} has no feature {feature!r} in release {old.version}"]
    return []


def _values(element: etree._Element, feature: str) -> tuple[str | None, list[etree._Element]]:
    return element.get(feature), [child for child in element if child.tag == feature]


def _describe_value(text: str | None, children: list[etree._Element]) -> str:
    if text is not None:
        return repr(text)
    if len(children) == 1:
        value = children[0].get("value")
        kind = (children[0].get(XSI_TYPE) or "").rpartition(":")[2]
        return f"{kind} {value}" if value is not None else kind or "an element"
    return f"{len(children)} elements"


@dataclass(frozen=True)
class RenameClass(Operation):
    name: ClassVar[str] = "rename_class"
    old_name: str
    new_name: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.old_name, exact=True):
            if element is model.root or element.get(XSI_TYPE) is not None:
                model.set_class(element, self.new_name)
                record.add(self.name, element, f"{self.old_name} -> {self.new_name}")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_class(old, self.old_name, self.describe())
        if self.new_name not in new.classes:
            found.append(f"{self.describe()}: the current release has no class {self.new_name}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return change.kind in ("class-removed", "class-abstract") and change.cls == self.old_name

    def describe(self) -> str:
        return f"rename class {self.old_name} to {self.new_name}"


@dataclass(frozen=True)
class RenameFeature(Operation):
    name: ClassVar[str] = "rename_feature"
    cls: str
    old_name: str
    new_name: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls):
            text, children = _values(element, self.old_name)
            if text is not None:
                del element.attrib[self.old_name]
                element.set(self.new_name, text)
            for child in children:
                child.tag = self.new_name
            if text is not None or children:
                record.add(self.name, element, f"{self.old_name} -> {self.new_name}")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        return _need_feature(old, self.cls, self.old_name, self.describe())

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return _accounts_for_removal(change, old, self.cls, self.old_name)

    def describe(self) -> str:
        return f"rename {self.cls}.{self.old_name} to {self.new_name}"


@dataclass(frozen=True)
class MoveFeature(Operation):
    """Move a feature's value into a contained element (made when missing, of `into_type`)."""

    name: ClassVar[str] = "move_feature"
    cls: str
    feature: str
    into: str
    into_type: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls):
            text, children = _values(element, self.feature)
            if text is None and not children:
                continue
            holder = next((c for c in element if c.tag == self.into), None)
            if holder is None:
                holder = _new_child(model, element, self.into, self.into_type)
            if text is not None:
                del element.attrib[self.feature]
                holder.set(self.feature, text)
            for child in children:
                holder.append(child)
            record.add(self.name, element, f"{self.feature} -> {self.into}.{self.feature}")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_feature(old, self.cls, self.feature, self.describe())
        if self.into_type not in new.classes:
            found.append(f"{self.describe()}: the current release has no class {self.into_type}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return _accounts_for_removal(change, old, self.cls, self.feature)

    def describe(self) -> str:
        return f"move {self.cls}.{self.feature} into {self.into} ({self.into_type})"


@dataclass(frozen=True)
class AddFeature(Operation):
    """Give old elements a value for a feature they lack: a default or a computed value.

    `default` is attribute text, or a mapping with `type` (and attributes) for a contained
    element, e.g. `{type: Value, value: "2.0"}`.
    """

    name: ClassVar[str] = "add_feature"
    cls: str
    feature: str
    default: str | Mapping[str, str] | None = None
    compute: str | None = None
    note: str = ""

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls):
            text, children = _values(element, self.feature)
            if text is not None or children:
                continue
            self._fill(model, element, record)

    def _fill(self, model: TreeModel, element: etree._Element, record: Recorder) -> None:
        if self.compute is not None:
            value = COMPUTED[self.compute](element, model)
            if value is None:
                return
            element.set(self.feature, value)
            record.add(self.name, element, f"{self.feature} = {value!r} (computed)", self.note)
        elif isinstance(self.default, Mapping):
            kind = self.default["type"]
            child = _new_child(model, element, self.feature, kind)
            for key, value in self.default.items():
                if key != "type":
                    child.set(key, str(value))
            shown = ", ".join(f"{k}={v}" for k, v in self.default.items() if k != "type")
            record.add(self.name, element, f"{self.feature} = {kind} {shown}".rstrip(), self.note)
        elif self.default is not None:
            element.set(self.feature, self.default)
            record.add(self.name, element, f"{self.feature} = {self.default!r}", self.note)

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = []
        if self.cls not in new.classes:
            found.append(f"{self.describe()}: the current release has no class {self.cls}")
        elif new.feature(self.cls, self.feature) is None:
            found.append(f"{self.describe()}: {self.cls} has no feature {self.feature!r} now")
        if (self.default is None) == (self.compute is None):
            found.append(f"{self.describe()}: give either a default or compute")
        if self.compute is not None and self.compute not in COMPUTED:
            found.append(f"{self.describe()}: no computed value named {self.compute!r}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return (
            change.kind == "required-added"
            and change.feature == self.feature
            and (change.cls not in old.classes or _related(old, change.cls, self.cls))
        )

    def describe(self) -> str:
        how = f"computed by {self.compute}" if self.compute else f"default {self.default}"
        return f"add {self.cls}.{self.feature} ({how})"


@dataclass(frozen=True)
class MakeRequired(AddFeature):
    """An optional feature becomes required: old elements without it get `default`."""

    name: ClassVar[str] = "make_required"

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_feature(old, self.cls, self.feature, self.describe())
        return found + super().problems(old, new)

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return change.kind in ("required-added", "made-required") and (
            change.feature == self.feature and _related(old, change.cls, self.cls)
        )

    def describe(self) -> str:
        how = f"computed by {self.compute}" if self.compute else f"{self.default} where unset"
        return f"make {self.cls}.{self.feature} required ({how})"


@dataclass(frozen=True)
class SplitClass(Operation):
    """One class becomes several: each element's new class is chosen by a feature's value."""

    name: ClassVar[str] = "split_class"
    cls: str
    by: str
    into: Mapping[str, str]
    otherwise: str
    drop: bool = True

    def apply(self, model: TreeModel, record: Recorder) -> None:
        feature = model.metamodel.feature(self.cls, self.by)
        unset = feature.default if feature is not None else None
        for element in model.instances(self.cls, exact=True):
            value = element.get(self.by, unset)
            target = self.into.get(value or "", self.otherwise)
            model.set_class(element, target)
            if self.drop and self.by in element.attrib:
                del element.attrib[self.by]
            record.add(self.name, element, f"{self.cls} ({self.by}={value}) -> {target}")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_feature(old, self.cls, self.by, self.describe())
        for target in {*self.into.values(), self.otherwise}:
            if target not in new.classes:
                found.append(f"{self.describe()}: the current release has no class {target}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        if change.kind in ("class-removed", "class-abstract"):
            return change.cls == self.cls
        return self.drop and change.kind == "feature-removed" and change.feature == self.by

    def describe(self) -> str:
        choices = ", ".join(f"{k}: {v}" for k, v in self.into.items())
        return f"split {self.cls} by {self.by} into {{{choices}}}, otherwise {self.otherwise}"


@dataclass(frozen=True)
class MergeClasses(Operation):
    """Several classes become one; `record` keeps which one each element was, in a feature."""

    name: ClassVar[str] = "merge_classes"
    classes: tuple[str, ...]
    into: str
    record: str | None = None
    values: Mapping[str, str] = field(default_factory=dict)

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for cls in self.classes:
            for element in model.instances(cls, exact=True):
                model.set_class(element, self.into)
                detail = f"{cls} -> {self.into}"
                if self.record is not None:
                    element.set(self.record, self.values.get(cls, cls))
                    detail += f" ({self.record}={self.values.get(cls, cls)})"
                record.add(self.name, element, detail)

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = [p for c in self.classes for p in _need_class(old, c, self.describe())]
        if self.into not in new.classes:
            found.append(f"{self.describe()}: the current release has no class {self.into}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return change.kind in ("class-removed", "class-abstract") and change.cls in self.classes

    def describe(self) -> str:
        return f"merge {', '.join(self.classes)} into {self.into}"


@dataclass(frozen=True)
class ChangeType(Operation):
    """A feature's type changes; each old value is converted.

    `convert` is `{scale: K}` (numbers times K), `{map: {old: new}}` (enum literals or text),
    `{function: NAME}` (a function of CONVERSIONS), or `{first: true}` (many values become one:
    the first is kept, the rest are reported).
    """

    name: ClassVar[str] = "change_type"
    cls: str
    feature: str
    to: str
    convert: Mapping[str, Any]

    def _converted(self, text: str) -> str:
        if "scale" in self.convert:
            return repr(float(text) * float(self.convert["scale"]))
        if "map" in self.convert:
            return str(self.convert["map"].get(text, text))
        if "function" in self.convert:
            return CONVERSIONS[self.convert["function"]](text)
        return text

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls):
            text, children = _values(element, self.feature)
            if self.convert.get("first"):
                words = (text or "").split()
                if len(words) > 1:
                    element.set(self.feature, words[0])
                    record.add(
                        self.name,
                        element,
                        f"{self.feature}: kept {words[0]!r}, dropped {' '.join(words[1:])!r}",
                    )
                for child in children[1:]:
                    element.remove(child)
                    record.add(
                        self.name,
                        element,
                        f"{self.feature}: dropped a second value "
                        f"({_describe_value(None, [child])})",
                    )
                continue
            if text is None:
                continue
            new = " ".join(self._converted(word) for word in text.split())
            if new != text:
                element.set(self.feature, new)
                record.add(self.name, element, f"{self.feature}: {text!r} -> {new!r} ({self.to})")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_feature(old, self.cls, self.feature, self.describe())
        known = {"scale", "map", "function", "first"}
        if not self.convert or not set(self.convert) <= known:
            found.append(f"{self.describe()}: convert must be one of {', '.join(sorted(known))}")
        elif "function" in self.convert and self.convert["function"] not in CONVERSIONS:
            found.append(f"{self.describe()}: no conversion named {self.convert['function']!r}")
        return found

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return (
            change.kind in ("feature-type", "multiplicity-narrowed")
            and change.feature == self.feature
            and _related(old, change.cls, self.cls)
        )

    def describe(self) -> str:
        return f"change {self.cls}.{self.feature} to {self.to}"


@dataclass(frozen=True)
class RenameLiteral(Operation):
    name: ClassVar[str] = "rename_literal"
    enum: str
    old_name: str
    new_name: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element, cls in list(model.classes.items()):
            for name, feature in model.metamodel.features(cls).items():
                text = element.get(name)
                if feature.type != self.enum or text is None:
                    continue
                words = [self.new_name if w == self.old_name else w for w in text.split()]
                if words != text.split():
                    element.set(name, " ".join(words))
                    record.add(self.name, element, f"{name}: {self.old_name} -> {self.new_name}")

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        if self.old_name not in old.enums.get(self.enum, ()):
            return [f"{self.describe()}: release {old.version} has no such literal"]
        return []

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return change.kind == "literal-removed" and (change.cls, change.feature) == (
            self.enum,
            self.old_name,
        )

    def describe(self) -> str:
        return f"rename literal {self.enum}.{self.old_name} to {self.new_name}"


@dataclass(frozen=True)
class DeleteFeature(Operation):
    name: ClassVar[str] = "delete_feature"
    cls: str
    feature: str
    note: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls):
            text, children = _values(element, self.feature)
            if text is None and not children:
                continue
            if text is not None:
                del element.attrib[self.feature]
            for child in children:
                element.remove(child)
            shown = _describe_value(text, children)
            record.add(self.name, element, f"{self.feature} ({shown}) removed", self.note)

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_feature(old, self.cls, self.feature, self.describe())
        return found + ([] if self.note else [f"{self.describe()}: a deletion needs a note"])

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return _accounts_for_removal(change, old, self.cls, self.feature)

    def describe(self) -> str:
        return f"delete {self.cls}.{self.feature}"


@dataclass(frozen=True)
class DeleteClass(Operation):
    name: ClassVar[str] = "delete_class"
    cls: str
    note: str

    def apply(self, model: TreeModel, record: Recorder) -> None:
        for element in model.instances(self.cls, exact=True):
            parent = element.getparent()
            if parent is None:
                continue  # the model root itself: the loader refuses the file by its class
            record.add(self.name, element, f"{self.cls} removed", self.note)
            parent.remove(element)

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        found = _need_class(old, self.cls, self.describe())
        return found + ([] if self.note else [f"{self.describe()}: a deletion needs a note"])

    def covers(self, change: BreakingChange, old: Metamodel) -> bool:
        return change.kind in ("class-removed", "class-abstract") and change.cls == self.cls

    def describe(self) -> str:
        return f"delete class {self.cls}"


#: Operation name -> class, for reading migrations.
OPERATIONS: dict[str, type[Operation]] = {
    op.name: op
    for op in (
        RenameClass,
        RenameFeature,
        MoveFeature,
        AddFeature,
        MakeRequired,
        SplitClass,
        MergeClasses,
        ChangeType,
        RenameLiteral,
        DeleteFeature,
        DeleteClass,
    )
}

"""Migration steps: one YAML file per release, `metamodel/migrations/<from>-to-<to>.yaml`.

A step lists the operations that take files saved with release `from` to release `to`, in the
order they run, naming classes and features as they were in `from`. The files are meant to be
read by a person as the list of what changed between two releases.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from ..errors import LoadError
from .ecore import Metamodel
from .operations import (
    OPERATIONS,
    AddFeature,
    ChangeType,
    DeleteClass,
    DeleteFeature,
    MakeRequired,
    MergeClasses,
    MoveFeature,
    Operation,
    Recorder,
    RenameClass,
    RenameFeature,
    RenameLiteral,
    SplitClass,
)
from .report import Change
from .tree import Fragments, TreeModel


@dataclass(frozen=True)
class Step:
    source: Path
    from_release: str
    to_release: str
    summary: str
    operations: tuple[Operation, ...] = field(default_factory=tuple)

    @property
    def label(self) -> str:
        return f"{self.from_release} -> {self.to_release}"

    def renamed_classes(self) -> dict[str, str]:
        return {op.old_name: op.new_name for op in self.operations if isinstance(op, RenameClass)}

    def apply(self, model: TreeModel) -> list[Change]:
        """Rewrite the tree of a file saved with `from_release`; the changes made."""
        record = Recorder(self.label)
        for operation in self.operations:
            fragments = Fragments(model)
            operation.apply(model, record)
            for holder, attribute in fragments.restore():
                record.add(
                    operation.name,
                    holder,
                    f"{attribute}: a reference to an element removed by this step was dropped",
                )
        return record.changes

    def problems(self, old: Metamodel, new: Metamodel) -> list[str]:
        return [f"{self.source.name}: {p}" for op in self.operations for p in op.problems(old, new)]


def read_step(path: Path) -> Step:
    """Read one migration file; LoadError names the file and the operation that is wrong."""
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError) as error:
        raise LoadError(f"cannot read the migration: {error}", file=path) from None
    if not isinstance(data, dict) or not {"from", "to"} <= set(data):
        raise LoadError("a migration needs 'from', 'to' and 'operations'", file=path)
    operations = []
    for index, entry in enumerate(data.get("operations") or []):
        if not isinstance(entry, dict) or len(entry) != 1:
            raise LoadError(f"operation {index + 1}: write it as `- NAME: {{...}}`", file=path)
        ((name, arguments),) = entry.items()
        try:
            operations.append(_operation(name, arguments or {}))
        except (KeyError, TypeError, ValueError) as error:
            raise LoadError(f"operation {index + 1} ({name}): {error}", file=path) from None
    return Step(
        path,
        str(data["from"]),
        str(data["to"]),
        str(data.get("summary", "")).strip(),
        tuple(operations),
    )


def _operation(name: str, a: dict[str, Any]) -> Operation:
    if name not in OPERATIONS:
        raise ValueError(f"unknown operation; known: {', '.join(OPERATIONS)}")
    match name:
        case "rename_class":
            return RenameClass(a["from"], a["to"])
        case "rename_feature":
            return RenameFeature(a["class"], a["from"], a["to"])
        case "move_feature":
            return MoveFeature(a["class"], a["feature"], a["into"], a["into_type"])
        case "add_feature" | "make_required":
            kind = AddFeature if name == "add_feature" else MakeRequired
            return kind(
                a["class"], a["feature"], a.get("default"), a.get("compute"), a.get("note", "")
            )
        case "split_class":
            return SplitClass(
                a["class"], a["by"], dict(a["into"]), a["otherwise"], bool(a.get("drop", True))
            )
        case "merge_classes":
            return MergeClasses(
                tuple(a["classes"]), a["into"], a.get("record"), dict(a.get("values") or {})
            )
        case "change_type":
            return ChangeType(a["class"], a["feature"], a["to"], dict(a["convert"]))
        case "rename_literal":
            return RenameLiteral(a["enum"], a["from"], a["to"])
        case "delete_feature":
            return DeleteFeature(a["class"], a["feature"], a["note"])
        case "delete_class":
            return DeleteClass(a["class"], a["note"])
    raise ValueError(name)  # pragma: no cover (OPERATIONS and the match list the same names)

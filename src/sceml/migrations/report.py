"""What a migration did to one file: the releases and every change, with element and line."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any


@dataclass(frozen=True)
class Change:
    """One change made to one element of a file."""

    step: str  # "1.0 -> 1.1"
    operation: str  # the operation's name, e.g. "rename_feature"
    element: str  # the element's path of names, e.g. "UIS2/Accelerate_1"
    line: int | None  # where the element was written in the file as read
    detail: str  # what changed, e.g. "rate -> acceleration"
    note: str = ""  # the migration's own word on it (deletions say why)

    def describe(self) -> str:
        where = f"line {self.line}: " if self.line else ""
        note = f" ({self.note})" if self.note else ""
        return f"{where}{self.element}: {self.operation}: {self.detail}{note}"


@dataclass
class Report:
    """The migration of one file from its release to the current one."""

    file: Path
    from_release: str
    to_release: str
    changes: list[Change] = field(default_factory=list)

    def summary(self) -> str:
        count = len(self.changes)
        changes = f"{count} change{'s' if count != 1 else ''}"
        return (
            f"saved with metamodel release {self.from_release}; read as release "
            f"{self.to_release} ({changes})"
        )

    def lines(self) -> list[str]:
        return [f"{self.file}: {self.summary()}", *(f"  {c.describe()}" for c in self.changes)]

    def to_json(self) -> dict[str, Any]:
        return {
            "file": str(self.file),
            "from": self.from_release,
            "to": self.to_release,
            "changes": [asdict(change) for change in self.changes],
        }

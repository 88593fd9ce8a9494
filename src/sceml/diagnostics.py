"""The one Diagnostic type: what is wrong, how badly, under which rule code, and where."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

from pyecore.ecore import EObject


class Severity(IntEnum):
    """How bad a finding is; ordered so that `max()` gives the worst."""

    INFO = 0
    WARNING = 1
    ERROR = 2

    def __str__(self) -> str:
        return self.name.lower()


@dataclass(frozen=True)
class Diagnostic:
    """One finding about a model or file.

    `fragment` is the element's EMF URI fragment (e.g. `//@nodes.3`), `path` a readable path of
    element names (e.g. `Root/ego`); `file` and `line` locate it on disk where known.
    """

    severity: Severity
    code: str
    message: str
    fragment: str | None = None
    path: str | None = None
    file: str | None = None
    line: int | None = None
    element: EObject | None = field(default=None, compare=False, repr=False)

    def to_json(self) -> dict[str, object]:
        """The diagnostic as a JSON object (docs/validation-json.md; the editor sends a subset)."""
        return {
            "severity": str(self.severity),
            "code": self.code,
            "message": self.message,
            "file": self.file,
            "line": self.line,
            "fragment": self.fragment,
            "path": self.path,
        }

    def __str__(self) -> str:
        """The one text form, gcc style: `file:line: severity[CODE] message (path)`."""
        where = (self.file or "<model>") + (f":{self.line}" if self.line else "")
        suffix = f" ({self.path})" if self.path else ""
        return f"{where}: {self.severity}[{self.code}] {self.message}{suffix}"

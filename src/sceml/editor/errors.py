"""What the editor refuses, each error with the HTTP status the protocol gives it."""

from __future__ import annotations

from typing import Any

from ..errors import SceMLError


class EditorError(SceMLError):
    """Base of the editor's refusals; `status` is the protocol's HTTP status for it."""

    status = 400


class OperationError(EditorError):
    """A bad operation: unknown node, a field the kind does not have, a value of the wrong type."""

    status = 400


class ReadOnlyError(EditorError):
    """A change asked of a session opened read-only."""

    status = 403


class ConflictError(EditorError):
    """Opening another file would drop unsaved changes."""

    status = 409


class ExportRefused(EditorError):
    """The export refused the model; `diagnostics` say why."""

    status = 422

    def __init__(self, message: str, diagnostics: list[dict[str, Any]]) -> None:
        super().__init__(message)
        self.diagnostics = diagnostics

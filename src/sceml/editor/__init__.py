"""The graphical editor's server side: a session that owns the model, and its HTTP protocol.

`EditorSession` (session.py) holds no HTTP; `app.py` puts docs/editor-protocol.md over it and
`server.py` runs it. See docs/editor-protocol.md for the contract with the browser page.
"""

from .errors import ConflictError, EditorError, OperationError, ReadOnlyError
from .session import EditorSession, SessionOptions

__all__ = [
    "ConflictError",
    "EditorError",
    "EditorSession",
    "OperationError",
    "ReadOnlyError",
    "SessionOptions",
]

"""Which files the editor may open and write: the same allowed folders as every reader.

A path in a request is whatever the page (or any program on this machine) sent. It is checked
as text first (type, NUL, length), resolved against the folder of the edited file, and must lie
in one of the session's allowed folders: `sceml.files.safefiles.reading_roots` of the file named when the
server started, plus each `--allow DIR`. What happens at the target itself (a device, a FIFO, a
symlink) is `sceml.files.writing.write_atomically`'s rule, which every save and export goes through.
"""

from __future__ import annotations

import os
from pathlib import Path

from .errors import OperationError

#: Longer than any real path (Linux's PATH_MAX); a longer text is a mistake or an attack.
MAX_PATH_LENGTH = 4096


def path_text(value: object, what: str) -> str:
    """`value` as the text of a path; OperationError naming `what` (`'path'`) otherwise."""
    if isinstance(value, Path):
        value = str(value)
    if not isinstance(value, str) or value.strip() == "":
        raise OperationError(f"{what} must name a file as text, not {_shown(value)}")
    if "\x00" in value:
        raise OperationError(f"{what} holds a NUL character, which no file name can")
    if len(value) > MAX_PATH_LENGTH:
        raise OperationError(
            f"{what} is {len(value):,} characters long; a path is at most {MAX_PATH_LENGTH:,}"
        )
    return value


def _shown(value: object) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


def inside_allowed(value: object, what: str, base: Path, roots: list[Path]) -> Path:
    """The absolute path `value` names (relative to `base`), if it lies in one of `roots`."""
    text = path_text(value, what)
    try:
        # strict=False: the target of a save may not exist yet; its folder's links are resolved.
        path = (base / os.path.expanduser(text)).resolve()
    except (OSError, RuntimeError) as error:
        raise OperationError(f"{what} {text!r} cannot be used: {error}") from None
    if any(name and len(name.encode("utf-8", "surrogateescape")) > 255 for name in path.parts):
        raise OperationError(f"{what} {_shown(text)} has a name longer than 255 bytes")
    if not any(path.is_relative_to(root) for root in roots):
        folders = ", ".join(str(root) for root in roots)
        raise OperationError(
            f"{path} is outside the folders the editor may use ({folders}); "
            "start `sceml edit` with --allow DIR to use another folder"
        )
    return path

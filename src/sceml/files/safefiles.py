"""The one rule for opening an input file and the one rule for choosing what an output replaces.

Reading: regular files only (a FIFO would block, a device such as /dev/zero never ends), inside
the allowed folders when the caller names them, and never more than a byte limit, counted while
reading: a special file's reported size means nothing (/dev/zero reports 0).

Writing: an output replaces a regular file (atomically, in `sceml.model`) or creates a new one. A
device, FIFO or socket is refused, never replaced or written through; a symbolic link is
followed to the regular file it names, which is replaced, and the link is left as it was.
"""

from __future__ import annotations

import errno
import os
import stat
from collections.abc import Iterable
from pathlib import Path

from ..errors import LoadError, SaveError
from .safexml import MAX_BYTES_VARIABLE, max_bytes_limit, size_problem

# Enough for one read of a typical model; a regular file is read in one call of its own size.
_CHUNK = 1 << 20

# Opening never blocks (a FIFO with no writer would) and never makes a terminal ours.
_READ_FLAGS = (
    os.O_RDONLY
    | getattr(os, "O_NONBLOCK", 0)
    | getattr(os, "O_NOCTTY", 0)
    | getattr(os, "O_CLOEXEC", 0)
    | getattr(os, "O_BINARY", 0)
)


def read_input(
    path: str | os.PathLike[str],
    *,
    roots: Iterable[str | os.PathLike[str]] | None = None,
    max_bytes: int | None = None,
    what: str = "file",
    error: type[LoadError] = LoadError,
) -> bytes:
    """The bytes of the input file at `path`, by the one reading rule of every SceML reader.

    Refused with `error` (naming the file, `what` naming its role): a path outside `roots` (when
    given, each folder with everything below it; links are resolved first), anything but a
    regular file (checked before opening, and again on the opened file), and more than
    `max_bytes` (default `max_bytes_limit()`), counted as the bytes arrive. A missing or
    unreadable file, or a folder, raises the OSError (FileNotFoundError, IsADirectoryError, ...)
    for the caller to word.
    """
    path = Path(path)
    limit = max_bytes_limit() if max_bytes is None else max_bytes
    if roots is not None:
        check_inside(path, roots, what=what, error=error)
    _require_regular(path, os.stat(path).st_mode, what, error)
    handle = os.open(path, _READ_FLAGS)
    try:
        # Checked again on what was opened: the path may have been swapped meanwhile.
        status = os.fstat(handle)
        _require_regular(path, status.st_mode, what, error)
        too_large = size_problem(status.st_size, limit)
        if too_large is not None:
            raise error(too_large, file=path)
        return _read_at_most(handle, status.st_size, limit, path, what, error)
    finally:
        os.close(handle)


def check_inside(
    path: str | os.PathLike[str],
    roots: Iterable[str | os.PathLike[str]],
    *,
    what: str = "file",
    error: type[LoadError] = LoadError,
) -> None:
    """Refuse `path` (with `error`) unless it lies, links resolved, below one of `roots`."""
    path = Path(path)
    real = Path(os.path.realpath(path))
    folders = [Path(os.path.realpath(root)) for root in roots]
    if is_inside(path, folders):
        return
    listed = ", ".join(str(folder) for folder in folders)
    raise error(
        f"the {what} is outside the allowed folders ({listed}); to read it, allow its folder "
        f"(--allow {real.parent})",
        file=path,
    )


def is_inside(path: str | os.PathLike[str], roots: Iterable[str | os.PathLike[str]]) -> bool:
    """Whether `path`, links resolved, lies below (or is) one of `roots`."""
    real = Path(os.path.realpath(path))
    folders = [Path(os.path.realpath(root)) for root in roots]
    return any(real == folder or folder in real.parents for folder in folders)


def _require_regular(path: Path, mode: int, what: str, error: type[LoadError]) -> None:
    if stat.S_ISREG(mode):
        return
    if stat.S_ISDIR(mode):
        raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
    raise error(f"the {what} is {file_kind(mode)}, not a regular file: it is not read", file=path)


def _read_at_most(
    handle: int, size: int, limit: int, path: Path, what: str, error: type[LoadError]
) -> bytes:
    # The first read asks for the whole reported size and one byte more, so a regular file
    # comes in one piece (no copy); whatever follows is counted against the limit as it comes.
    chunks: list[bytes] = []
    total = 0
    wanted = min(size, limit) + 1
    while True:
        chunk = os.read(handle, min(max(wanted - total, _CHUNK), limit + 1 - total))
        if not chunk:
            break
        chunks.append(chunk)
        total += len(chunk)
        if total > limit:
            raise error(
                f"the {what} holds more than the {limit}-byte limit (set {MAX_BYTES_VARIABLE} "
                "to change it)",
                file=path,
            )
    return chunks[0] if len(chunks) == 1 else b"".join(chunks)


def output_target(path: str | os.PathLike[str]) -> Path:
    """The file an output written to `path` replaces, by the one writing rule; SaveError if none.

    A new path, or a regular file, is itself. A symbolic link is followed to the regular file it
    names (the link stays a link); a link to nothing, or a loop, is refused. A folder, device,
    FIFO or socket is refused: it is never replaced and never written through.
    """
    path = Path(path)
    try:
        status = os.lstat(path)
    except (FileNotFoundError, NotADirectoryError):
        return path  # a new file; missing or blocked folders are reported by whoever makes them
    except OSError as failure:
        raise SaveError(f"cannot write: {failure.strerror or failure}", file=path) from None
    target = path
    if stat.S_ISLNK(status.st_mode):
        target = Path(os.path.realpath(path))
        try:
            status = os.stat(path)
        except OSError as failure:
            reason = "a link loop" if failure.errno == errno.ELOOP else f"missing file {target}"
            raise SaveError(
                f"cannot write: it is a symbolic link to {reason}; SceML follows links only to "
                "existing regular files",
                file=path,
            ) from None
    if stat.S_ISDIR(status.st_mode):
        raise SaveError("cannot write: it is a folder", file=path)
    if not stat.S_ISREG(status.st_mode):
        raise SaveError(
            f"cannot write: it is {file_kind(status.st_mode)}; SceML replaces regular files only "
            "and never writes to devices, FIFOs or sockets",
            file=path,
        )
    return target


def file_kind(mode: int) -> str:
    """What a file of this `st_mode` is, in words: 'a FIFO', 'a character device', ..."""
    kinds = (
        (stat.S_ISFIFO, "a FIFO (named pipe)"),
        (stat.S_ISCHR, "a character device"),
        (stat.S_ISBLK, "a block device"),
        (stat.S_ISSOCK, "a socket"),
        (stat.S_ISDIR, "a folder"),
        (stat.S_ISLNK, "a symbolic link"),
    )
    return next((name for test, name in kinds if test(mode)), "not a regular file")


#: What marks a project's root folder: a version control checkout, or SceML's own marker file.
PROJECT_MARKERS = (".git", ".hg", ".svn", ".sceml-root")


def project_root(path: str | Path) -> Path | None:
    """The nearest folder at or above `path`'s folder that holds one of PROJECT_MARKERS."""
    folder = Path(path).resolve().parent
    for candidate in [folder, *folder.parents]:
        if any((candidate / marker).exists() for marker in PROJECT_MARKERS):
            return candidate
    return None


def reading_roots(path: str | Path, allow: Iterable[str | Path] = ()) -> list[Path]:
    """The folders that files `path` refers to may be read from: the one rule of every reader.

    They are `path`'s own folder, its project root (see `project_root`), and the folders in
    `allow` (the CLI's `--allow`), each with everything below it.
    """
    roots: list[Path] = []
    for root in [Path(path).resolve().parent, project_root(path), *allow]:
        if root is not None and Path(root).resolve() not in roots:
            roots.append(Path(root).resolve())
    return roots

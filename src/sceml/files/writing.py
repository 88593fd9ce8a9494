"""Writing files atomically: an existing file is replaced only once the new one is complete."""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from ..errors import SaveError
from .safefiles import output_target


def make_folder(folder: str | Path, *, target: str | Path | None = None) -> list[Path]:
    """Create `folder` and missing parents; SaveError naming `target` (default: the folder).

    Returns the folders it created, outermost first, for `remove_folders` to undo.
    """
    folder = Path(folder)
    named = Path(target) if target is not None else folder
    missing = [p for p in [folder, *folder.parents] if not p.is_dir()]
    blocking = next((p for p in missing if p.exists() or p.is_symlink()), None)
    if blocking is not None:
        raise SaveError(f"cannot write: {blocking} is a file, not a folder", file=named)
    created: list[Path] = []
    for missing_folder in reversed(missing):
        try:
            missing_folder.mkdir()
        except FileExistsError:
            continue  # made by someone else meanwhile: fine
        except OSError as error:
            remove_folders(created)
            raise SaveError(f"cannot write: {_reason(error)}", file=named) from None
        created.append(missing_folder)
    return created


def remove_folders(created: list[Path]) -> None:
    """Remove folders `make_folder` created, innermost first, where they are still empty."""
    for folder in reversed(created):
        with contextlib.suppress(OSError):
            folder.rmdir()


def _reason(error: OSError) -> str:
    return error.strerror or str(error)


def write_atomically(path: str | Path, data: bytes) -> None:
    """Write bytes to `path` through a temporary file in the same folder and an atomic rename.

    What is replaced follows the one writing rule (`sceml.files.safefiles.output_target`): a regular
    file, or the regular file a symbolic link names; a folder, device, FIFO or socket is refused.
    Any failure is a SaveError naming `path` (`cannot write: reason`); the previous file, if
    any, stays as it was, and neither the temporary file nor folders made for it are left.
    """
    path = Path(path)
    target = output_target(path)
    created = make_folder(target.parent, target=path)
    try:
        handle, temporary = tempfile.mkstemp(
            prefix=f".{target.name}.", suffix=".tmp", dir=target.parent
        )
    except OSError as error:
        remove_folders(created)
        raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
    try:
        with os.fdopen(handle, "wb") as stream:
            # No fsync: the rename alone guarantees readers never see a half-written file, and
            # batch export of thousands of files would pay for a disk flush on every one.
            stream.write(data)
        os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    except BaseException as error:
        Path(temporary).unlink(missing_ok=True)
        remove_folders(created)
        if isinstance(error, OSError):
            raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
        raise


def _write_all(handle: int, data: bytes) -> None:
    """Every byte of `data` into the open file `handle` (os.write may take only part of it).
    No fsync, as in write_atomically: the name given last is the guarantee."""
    view = memoryview(data)
    while view:
        view = view[os.write(handle, view) :]


#: Whether this system makes unnamed files (Linux's O_TMPFILE) in the output folders; cleared at the
#: first refusal (another system, an old kernel, a file system without it).
_unnamed_files = hasattr(os, "O_TMPFILE") and os.path.isdir("/proc/self/fd")


@contextlib.contextmanager
def open_folder(folder: str | Path) -> Iterator[int | None]:
    """An open descriptor of `folder` for `write_staged`, closed afterwards; None where folders
    cannot be opened so (the writes then look the folder up by its path)."""
    try:
        handle = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        yield None
        return
    try:
        yield handle
    finally:
        os.close(handle)


def _write_unnamed(path: Path, data: bytes, folder: int | None = None) -> bool:
    """Write a new file `path` as an unnamed file in its folder, then give it its name; False
    when the name exists or the system makes no unnamed files (the caller writes another way).
    `folder`: an open descriptor of `path`'s folder, which saves looking the folder up per file.

    The file gets a name only once complete, so no reader ever sees it half-written and a killed
    process leaves nothing behind; and it touches the folder once, where a temporary name and a
    rename touch it (and, for a rename from another folder, the file system's rename lock) three
    times. That matters for the batch's workers, which create thousands of files in one folder at
    once: with names and renames, they queue on the folder's lock.
    """
    global _unnamed_files
    if not _unnamed_files:
        return False
    # Any failure here leaves nothing (an unnamed file vanishes with its handle) and hands the
    # file to the caller's other way, which reports a real problem (a full disk, a folder it may
    # not write) in the same words as everywhere else.
    try:
        if folder is None:
            handle = os.open(path.parent, os.O_TMPFILE | os.O_WRONLY, 0o644)
        else:
            handle = os.open(".", os.O_TMPFILE | os.O_WRONLY, 0o644, dir_fd=folder)
    except OSError as error:
        if error.errno in (errno.EOPNOTSUPP, errno.EISDIR, errno.EINVAL):
            _unnamed_files = False
        return False
    try:
        _write_all(handle, data)
        os.fchmod(handle, 0o644)  # as write_atomically leaves a file, whatever the umask
        # linkat(AT_SYMLINK_FOLLOW) names the file the descriptor's /proc entry stands for; os.link
        # calls it only when given a folder descriptor (ignored for an absolute path), and calls
        # plain link(), which links the /proc entry itself and fails, when not.
        # Refused (EEXIST) if the name exists, whatever it names: a file, a link, a folder.
        os.link(
            f"/proc/self/fd/{handle}",
            path if folder is None else path.name,
            src_dir_fd=handle,
            dst_dir_fd=folder,
            follow_symlinks=True,
        )
    except OSError:
        return False
    finally:
        os.close(handle)
    return True


def write_staged(
    path: str | Path, data: bytes, staging: str | Path, folder: int | None = None
) -> None:
    """Write bytes to `path` atomically, for writers of many files at once (the batch's workers).

    A new file is written unnamed in its folder and named once complete (`_write_unnamed`). An
    existing one, or any file where the system makes no unnamed files, goes through a file of
    the same name in `staging` and an atomic rename: `staging` is a private folder on the same
    file system as `path` (e.g. inside the output folder) that its owner creates beforehand and
    removes as a whole afterwards, so no temporary name has to be made up. `path`'s folder must
    exist; `folder` may be an open descriptor of it (see `open_folder`). What is replaced
    follows the writing rule of `write_atomically`.
    Any failure is a SaveError naming `path` (`cannot write: reason`); the previous file, if
    any, stays as it was and the staged file is removed. A process killed midway can leave a
    staged file, never a half-written `path`; removing `staging` removes that too.
    """
    path = Path(path)
    # Tried first: naming the file refuses any existing name, which then goes the staged way
    # under the writing rule (`output_target`); a new file, the usual case, needs no lookup.
    if _write_unnamed(path, data, folder):
        return
    target = output_target(path)
    staged = Path(staging) / path.name
    flags = os.O_WRONLY | os.O_CREAT | os.O_TRUNC | getattr(os, "O_BINARY", 0)  # (Windows)
    try:
        handle = os.open(staged, flags, 0o644)
    except OSError as error:
        raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
    try:
        try:
            _write_all(handle, data)
        finally:
            os.close(handle)
        os.chmod(staged, 0o644)  # as write_atomically leaves a file, whatever the umask
        os.replace(staged, target)
    except BaseException as error:
        staged.unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
        raise

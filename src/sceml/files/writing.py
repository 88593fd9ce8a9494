"""Writing files atomically: an existing file is replaced only once the new one is complete."""

from __future__ import annotations

import contextlib
import os
import tempfile
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


def write_staged(path: str | Path, data: bytes, staging: str | Path) -> None:
    """Write bytes to `path` through a file of the same name in `staging` and an atomic rename.

    For writers of many files at once (the batch's worker processes): `staging` is a private
    folder on the same file system as `path` (e.g. inside the output folder) that its owner
    creates beforehand and removes as a whole afterwards, so no temporary name has to be made
    up: one file creation and one rename. `path`'s folder must exist. What is replaced follows
    the writing rule of `write_atomically`.
    Any failure is a SaveError naming `path` (`cannot write: reason`); the previous file, if
    any, stays as it was and the staged file is removed. A process killed midway can leave a
    staged file, never a half-written `path`; removing `staging` removes that too.
    """
    path = Path(path)
    target = output_target(path)
    staged = Path(staging) / path.name
    flags = os.O_WRONLY | os.O_CREAT | os.O_TRUNC | getattr(os, "O_BINARY", 0)  # (Windows)
    try:
        handle = os.open(staged, flags, 0o644)
    except OSError as error:
        raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
    try:
        try:
            view = memoryview(data)
            while view:  # No fsync, as in write_atomically: the rename is the guarantee.
                view = view[os.write(handle, view) :]
        finally:
            os.close(handle)
        os.chmod(staged, 0o644)  # as write_atomically leaves a file, whatever the umask
        os.replace(staged, target)
    except BaseException as error:
        staged.unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise SaveError(f"cannot write: {_reason(error)}", file=path) from None
        raise

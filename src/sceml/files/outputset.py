"""Several output files of one command that appear together or not at all.

A command that writes a set (simulate's page, CSV and JSON; explore's runs, plot and critical
scenarios) writes each file under a staged name beside its target, through the usual atomic
writers, and renames them all into place only when every one was written. A failure or Ctrl-C
before that removes the staged files: no target is touched, none is left half-made. The renames
at the end are the one moment a failure could leave part of a set (a rename does not run out
of disk space, so it takes another process removing the folder meanwhile).
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from ..errors import SaveError
from .safefiles import output_target


class OutputSet:
    """The staged files of one set, by target; made by `output_set`."""

    def __init__(self) -> None:
        self._token = secrets.token_hex(4)
        self.staged: dict[Path, Path] = {}

    def stage(self, target: str | Path) -> Path:
        """The name to write `target` under until the set is complete: same folder and suffix,
        so relative references and formats chosen by suffix come out as for the target."""
        target = Path(target)
        output_target(target)  # a device or FIFO target is refused before anything is written
        staged = target.with_name(f".{target.stem}.{self._token}.staged{target.suffix}")
        self.staged[target] = staged
        return staged

    def _commit(self) -> None:
        for target, staged in self.staged.items():
            if not staged.exists():
                continue  # a member the command decided not to write
            try:
                os.replace(staged, output_target(target))
            except OSError as error:
                raise SaveError(f"cannot write: {error.strerror or error}", file=target) from None

    def _discard(self) -> None:
        for staged in self.staged.values():
            with contextlib.suppress(OSError):
                staged.unlink()


@contextmanager
def output_set() -> Iterator[OutputSet]:
    """Stage files with `.stage(target)`; all are renamed into place when the block succeeds."""
    outputs = OutputSet()
    try:
        yield outputs
        outputs._commit()
    finally:
        outputs._discard()  # after a commit only what failed to move is left

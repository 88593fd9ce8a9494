"""The recovery copy kept up to date after every change, off the request path.

After each change the session's unsaved model is written to `.NAME.recovered.xmi` beside the
file (or the copy is removed once everything is saved), by one background thread, so the answer
to the edit does not wait for the disk. Changes that arrive while a write runs are folded into
the next write: a SIGKILL loses at most the changes since the last write began, in practice the
last edit. The write itself is atomic (`sceml.files.writing.write_atomically`), so the copy is never torn.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

from ..errors import SceMLError


class Journal:
    """Runs `write` in a background thread after `changed()`, coalescing changes meanwhile."""

    def __init__(self, write: Callable[[], object]) -> None:
        self._write = write
        self._wanted = 0  # changes announced
        self._written = 0  # changes covered by a finished write
        self._stopping = False
        self._condition = threading.Condition()
        #: The last write's refusal (a full disk, a read-only folder), for the page to show.
        self.problem: str | None = None
        self._thread = threading.Thread(target=self._run, name="sceml-journal", daemon=True)
        self._thread.start()

    def changed(self) -> None:
        """The model changed: bring the copy up to date soon."""
        with self._condition:
            self._wanted += 1
            self._condition.notify_all()

    def flush(self, timeout: float | None = None) -> bool:
        """Wait until every change announced so far is written; False on timeout."""
        with self._condition:
            target = self._wanted
            return self._condition.wait_for(lambda: self._written >= target, timeout)

    def stop(self) -> None:
        """Write what is pending, then end the thread."""
        with self._condition:
            self._stopping = True
            self._condition.notify_all()
        self._thread.join()

    def _run(self) -> None:
        while True:
            with self._condition:
                self._condition.wait_for(lambda: self._wanted > self._written or self._stopping)
                if self._wanted == self._written:
                    return  # stopping, nothing pending
                target = self._wanted
            try:
                self._write()
                self.problem = None
            except SceMLError as error:
                self.problem = str(error)
            with self._condition:
                self._written = target
                self._condition.notify_all()

"""The checkpoint of the recovery copy, written off the request path once the edits pause.

Every change is first logged in `.NAME.journal` before its answer (`EditorSession.record`,
changelog.py); this thread writes the checkpoint, the whole unsaved model as
`.NAME.recovered.xmi` (or removes both once everything is saved), after which the log starts
again. The write holds the session's lock (it reads the model), a large fraction of a second at
500 nodes under load: started after every change, it made the next edit wait for it. So it
starts once the changes pause for `quiet` seconds, and at the latest `patience` seconds after
the first change it covers; at once (`now`) after a change the log cannot replay. Changes that
arrive while a write runs are folded into the next write. A SIGKILL loses nothing that was
answered: what the checkpoint does not hold yet is in the log. The write itself is atomic
(`sceml.files.writing.write_atomically`), so the copy is never torn.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from ..errors import SceMLError

#: How long the changes must pause before the copy is written (seconds).
QUIET = 0.5
#: How long a change may wait for its write however busy the user is (seconds).
PATIENCE = 3.0


class Journal:
    """Runs `write` in a background thread after `changed()`, once changes pause, coalescing."""

    def __init__(
        self, write: Callable[[], object], *, quiet: float = QUIET, patience: float = PATIENCE
    ) -> None:
        self._write = write
        self._quiet = quiet
        self._patience = patience
        self._wanted = 0  # changes announced
        self._taken = 0  # changes covered by the write under way (or the last one)
        self._written = 0  # changes covered by a finished write
        self._last_change = 0.0  # time.monotonic() of the last change announced
        self._first_pending = 0.0  # of the first change no write covers yet
        self._stopping = False
        self._urgent = False  # a checkpoint is due at once (`now`)
        self._condition = threading.Condition()
        #: The last write's refusal (a full disk, a read-only folder), for the page to show.
        self.problem: str | None = None
        self._thread = threading.Thread(target=self._run, name="sceml-journal", daemon=True)
        self._thread.start()

    def changed(self) -> None:
        """The model changed: bring the copy up to date once the changes pause."""
        with self._condition:
            now = time.monotonic()
            if self._wanted == self._taken:
                self._first_pending = now
            self._wanted += 1
            self._last_change = now
            self._condition.notify_all()

    def now(self) -> None:
        """A change the log cannot replay was made: write the checkpoint without waiting."""
        with self._condition:
            self._urgent = True
            self._wanted += 1
            self._last_change = time.monotonic()
            self._condition.notify_all()

    def flush(self, timeout: float | None = None) -> bool:
        """Wait until every change announced so far is written; False on timeout."""
        with self._condition:
            target = self._wanted
            return self._condition.wait_for(lambda: self._written >= target, timeout)

    def stop(self) -> None:
        """Write what is pending at once, then end the thread."""
        with self._condition:
            self._stopping = True
            self._condition.notify_all()
        self._thread.join()

    def _due_in(self) -> float:
        """Seconds until the pending changes are to be written (0: now). Under the condition."""
        if self._stopping or self._urgent:
            return 0.0
        now = time.monotonic()
        return max(
            0.0,
            min(self._last_change + self._quiet, self._first_pending + self._patience) - now,
        )

    def _run(self) -> None:
        while True:
            with self._condition:
                self._condition.wait_for(lambda: self._wanted > self._written or self._stopping)
                if self._wanted == self._written:
                    return  # stopping, nothing pending
                # Wait for the pause; every change (or the stop) wakes this up to recount.
                while (delay := self._due_in()) > 0:
                    self._condition.wait(delay)
                target = self._taken = self._wanted
                self._urgent = False
            try:
                self._write()
                self.problem = None
            except SceMLError as error:
                self.problem = str(error)
            with self._condition:
                self._written = target
                self._condition.notify_all()

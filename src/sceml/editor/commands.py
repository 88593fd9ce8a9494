"""The undo/redo history: one request's operations are one step, all applied or none.

Several tabs may edit one session. Each step remembers the tab that made it, and each tab undoes
its own last step, even when other tabs' steps came after it, as long as those later steps did
not change what it changed (`Recorder.footprint`); otherwise the undo is refused with the names
of the steps in the way. A new step in any tab clears every tab's redo: a redo replays old values
and would overwrite what was edited since.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TypeVar

from .changes import Recorder
from .errors import ConflictError

T = TypeVar("T")

#: The tab of callers that do not name one (the Python API, tests, an older page).
ANY_TAB = ""


@dataclass(eq=False)
class Step:
    """One undoable step: its label, the tab that made it, and the changes it made, in order."""

    label: str
    tab: str = ANY_TAB
    recorder: Recorder = field(default_factory=Recorder)


class CommandStack:
    """Runs edits as undoable steps and knows whether the model differs from its saved state."""

    def __init__(self) -> None:
        #: Applied steps, oldest first.
        self.done: list[Step] = []
        #: Undone steps per tab, the next to redo last.
        self.undone: dict[str, list[Step]] = {}
        # The applied steps when the model was saved (None: never saved since a restore).
        self._saved: frozenset[Step] | None = frozenset()

    def run(self, label: str, edit: Callable[[Recorder], T], tab: str = ANY_TAB) -> T:
        """Run `edit` as one step; if it raises, every change it made is reverted first."""
        step = Step(label, tab)
        try:
            result = edit(step.recorder)
        except BaseException:
            step.recorder.undo()
            raise
        if step.recorder.steps:
            self.done.append(step)
            self.undone.clear()
        return result

    def undo(self, tab: str = ANY_TAB) -> Step | None:
        """Revert `tab`'s last step; None when it has none; ConflictError if later steps
        (of other tabs) changed what it changed."""
        index = self._last_of(tab)
        if index is None:
            return None
        step = self.done[index]
        blocking = [
            later for later in self.done[index + 1 :] if step.recorder.overlaps(later.recorder)
        ]
        if blocking:
            labels = ", ".join(f"'{later.label}'" for later in blocking)
            raise ConflictError(
                f"'{step.label}' cannot be undone here: another tab changed the same things "
                f"since ({labels}); undo those there first"
            )
        del self.done[index]
        step.recorder.undo()
        self.undone.setdefault(tab, []).append(step)
        return step

    def redo(self, tab: str = ANY_TAB) -> Step | None:
        """Apply `tab`'s last undone step again; None when there is nothing to redo."""
        pending = self.undone.get(tab)
        if not pending:
            return None
        step = pending.pop()
        step.recorder.redo()
        self.done.append(step)
        return step

    def _last_of(self, tab: str) -> int | None:
        for index in range(len(self.done) - 1, -1, -1):
            if tab == ANY_TAB or self.done[index].tab == tab:
                return index
        return None

    def mark_saved(self) -> None:
        """Remember the current state as the saved one."""
        self._saved = frozenset(self.done)

    def mark_unsaved(self) -> None:
        """The model differs from its file whatever is undone (restored from a recovery copy)."""
        self._saved = None

    @property
    def dirty(self) -> bool:
        """Whether the model differs from the saved state (undoing back to it makes it clean)."""
        return self._saved is None or frozenset(self.done) != self._saved

    def undo_label_for(self, tab: str) -> str | None:
        """The label of the step Undo in `tab` would revert."""
        index = self._last_of(tab)
        return None if index is None else self.done[index].label

    def redo_label_for(self, tab: str) -> str | None:
        """The label of the step Redo in `tab` would apply."""
        pending = self.undone.get(tab)
        return pending[-1].label if pending else None

    @property
    def undo_label(self) -> str | None:
        """The label of the step Undo would revert (for a caller without tabs)."""
        return self.undo_label_for(ANY_TAB)

    @property
    def redo_label(self) -> str | None:
        """The label of the step Redo would apply (for a caller without tabs)."""
        return self.redo_label_for(ANY_TAB)

    def removal_of(self, obj: object) -> Step | None:
        """The applied step that took `obj` out of the model, if any (to explain a refusal)."""
        for step in reversed(self.done):
            if step.recorder.removed(obj):
                return step
        return None

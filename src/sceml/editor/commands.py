"""The undo/redo stack: one request's operations are one step, all applied or none."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TypeVar

from .changes import Recorder

T = TypeVar("T")


@dataclass(eq=False)
class Step:
    """One undoable step: its label and the changes it made, in order."""

    label: str
    recorder: Recorder = field(default_factory=Recorder)


class CommandStack:
    """Runs edits as undoable steps and knows whether the model differs from its saved state."""

    def __init__(self) -> None:
        self.done: list[Step] = []
        self.undone: list[Step] = []
        # The step on top of `done` when the model was saved (None: the opened state).
        self._saved: Step | None = None

    def run(self, label: str, edit: Callable[[Recorder], T]) -> T:
        """Run `edit` as one step; if it raises, every change it made is reverted first."""
        step = Step(label)
        try:
            result = edit(step.recorder)
        except BaseException:
            step.recorder.undo()
            raise
        if step.recorder.steps:
            self.done.append(step)
            self.undone.clear()
        return result

    def undo(self) -> Step | None:
        """Revert the last step; None when there is nothing to undo."""
        if not self.done:
            return None
        step = self.done.pop()
        step.recorder.undo()
        self.undone.append(step)
        return step

    def redo(self) -> Step | None:
        """Apply the last undone step again; None when there is nothing to redo."""
        if not self.undone:
            return None
        step = self.undone.pop()
        step.recorder.redo()
        self.done.append(step)
        return step

    def mark_saved(self) -> None:
        """Remember the current state as the saved one."""
        self._saved = self.done[-1] if self.done else None

    @property
    def dirty(self) -> bool:
        """Whether the model differs from the saved state (undoing back to it makes it clean)."""
        return (self.done[-1] if self.done else None) is not self._saved

    @property
    def undo_label(self) -> str | None:
        """The label of the step Undo would revert."""
        return self.done[-1].label if self.done else None

    @property
    def redo_label(self) -> str | None:
        """The label of the step Redo would apply."""
        return self.undone[-1].label if self.undone else None

"""What an imported scenario's validation means for `sceml import`: the findings the original
file has too, the ones the import causes, and the exit code they give.

A rule registered with `judges_stated_values` (sceml.validation.registry) judges a value as the
scenario states it against the world: the actor kind's limits, the map. The import copies such
values as the file writes them (a rate, a speed, a position), so the OpenSCENARIO file breaks
the same rule: its finding is the original's, and an import that means what the file means has
done its job. Every other error (an actor with no start, a graph that lost a construct) says
the model is not what the file meant: the import caused it. Only those fail the import, unless
it is strict.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ..diagnostics import Diagnostic, Severity
from ..validation.registry import REGISTRY, Registry


@dataclass(frozen=True)
class Verdict:
    """An imported scenario's findings, split by whose they are."""

    #: Findings of rules that judge stated values: the original file has these too.
    originals: tuple[Diagnostic, ...]
    #: Every other finding (errors, warnings, information), in the validator's order.
    own: tuple[Diagnostic, ...]

    @property
    def caused_errors(self) -> tuple[Diagnostic, ...]:
        """The errors the original does not deserve: the import caused them."""
        return tuple(d for d in self.own if d.severity is Severity.ERROR)

    @property
    def original_errors(self) -> tuple[Diagnostic, ...]:
        """The errors the original has too."""
        return tuple(d for d in self.originals if d.severity is Severity.ERROR)

    def exit_code(self, *, strict: bool = False) -> int:
        """1 when the import caused an error, or (strict) when there is any error; else 0."""
        failing = self.caused_errors + (self.original_errors if strict else ())
        return 1 if failing else 0


def judge(diagnostics: Iterable[Diagnostic], registry: Registry = REGISTRY) -> Verdict:
    """Split an imported scenario's diagnostics into the original's and the import's own."""
    originals: list[Diagnostic] = []
    own: list[Diagnostic] = []
    for diagnostic in diagnostics:
        (originals if _judges_stated_values(diagnostic.code, registry) else own).append(diagnostic)
    return Verdict(tuple(originals), tuple(own))


def _judges_stated_values(code: str, registry: Registry) -> bool:
    # Codes no rule owns (an internal error, an older release) are never the original's.
    try:
        return registry.rule(code).judges_stated_values
    except KeyError:
        return False

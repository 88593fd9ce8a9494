"""Incremental validation: after an edit, re-run only the rules whose inputs the edit changed.

A full run (`engine.iter_diagnostics`) applies every rule to every object of `engine.objects`,
then the through-modules rules, and drops repeated findings with `engine.unique`. An
`IncrementalValidator` keeps what each rule found on each object last time. Told what an edit
changed (a list of `Change`, as the editor's undo records them), it works out

- which objects were *touched*: the owner of a changed feature, an object moved into or out of a
  containment, and both ends of a flow whose source or target changed;
- which *aspects* of the model changed (`Aspect`): a graph's structure, names, who performs what,
  the cast, module uses, the scenario's level and map, positions, other parameter values, plain
  attributes (`aspects_of`).

It then re-runs a rule on an object only when the rule reads something that changed, as the rule
declares where it is registered (`constraint(reads=...)`, sceml.validation.reads): the object
itself and what it contains (SELF), the objects above it (ABOVE), the actors it or its node
refers to (ACTORS), or one of the aspects (then on every object it applies to). Every other
finding is taken from the last run, re-located when an index or a name on its way up from the
model's root changed (fragments, paths and lines depend on them). The findings are put together
in the full run's order and passed through `unique`, so the result is the same list, in the same
order, that `validate` gives. A rule that declares no reads re-runs everywhere, every time.

The through-modules pass (rules on the expanded copies of module uses) runs again as a whole when
an aspect it reads changed, or, for its rules reading ACTORS, when an actor or role a use binds was
touched: the copies perform as that actor (its own maxSpeed bounds their speeds, SCEML-L005).

A node dropped alone (`edits.placed_alone`: no flows, not a use) changes no aspect: its own rules
and every rule of its scenario run (`Impact.graphs`), and the expansion of the module uses kept
from the last run is patched rather than made again (sceml.validation.kept), unless the node's
name is one the expansion chose; then the drop counts as any other insertion.

What the validator cannot see makes the next run a full one: the first run, `forget()` (a file
was opened or saved, or an edit changed something the change list does not show), a map file
that changed on disk, and a module use whose definition did not resolve (its library may appear).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic
from ..maps.reference import map_reference
from ..model.collector import collector_paused
from ..model.documents import Document
from ..model.graph import root_node
from .context import Context
from .edits import EVERYTHING, Aspect, Change, Impact, refers_to
from .engine import Key, locate, objects, run_rule, through_modules, unique
from .kept import Kept
from .limits import Limits
from .reads import EXPANSION, Scope, stale_where
from .registry import REGISTRY, Registry, Rule

__all__ = [
    "Aspect",
    "Change",
    "IncrementalValidator",
    "RunStats",
    "through_modules_reads",
]


def through_modules_reads(registry: Registry = REGISTRY) -> Aspect:
    """What the through-modules pass reads: the expansion, and what its rules read there.

    Around an expanded copy there is only what the expansion made: copies of module internals
    (MODULES), bound to the scenario's actors (ROLES, CAST, NAMES). A rule among them that
    declares no reads makes the pass read everything.
    """
    found = EXPANSION
    for rule in registry.rules():
        if rule.through_modules:
            found |= rule.reads.aspects if rule.reads is not None else EVERYTHING
    return found


# --- the validator ------------------------------------------------------------------------------


@dataclass
class RunStats:
    """What the last run did: a full run or not, and how many rule checks ran or were reused."""

    full: bool = True
    checks_run: int = 0
    checks_reused: int = 0
    through_modules_run: bool = True


Findings = tuple[Diagnostic, ...]
#: Per object: the rules that applied (the registry's own tuple) and what each found, or None
#: when none found anything (most objects; it saves looking at each).
_Entry = tuple[tuple[Rule, ...], tuple[Findings, ...] | None]


class IncrementalValidator:
    """Validates one model again and again, re-running only what the changes noted since the
    last run can have changed; `validate()` equals `engine.validate` with the same options."""

    def __init__(
        self,
        model: EObject,
        *,
        document: Document | None = None,
        limits: Limits | None = None,
        osc_version: str | None = None,
        osc_profile: str | None = None,
        registry: Registry = REGISTRY,
    ) -> None:
        self.model = model
        self.document = document
        self.limits = limits or Limits()
        self.osc_version = osc_version
        self.osc_profile = osc_profile
        self.registry = registry
        self.stats = RunStats()
        self._through_reads = through_modules_reads(registry)
        self._through_always = any(
            rule.through_modules and rule.reads is None for rule in registry.rules()
        )
        self._all_classified = all(rule.reads is not None for rule in registry.rules())
        # Expanded copies perform as the actors their uses bind: a through-modules rule reading
        # ACTORS (L001..L005: the performer's own limits) is stale when a bound actor changed,
        # which no aspect says (an actor's maxSpeed is a parameter value like any other).
        self._through_actors = any(
            rule.through_modules and rule.reads is not None and rule.reads.scope & Scope.ACTORS
            for rule in registry.rules()
        )
        self._results: dict[EObject, _Entry] = {}
        self._through: Findings = ()
        self._pending: list[Change] = []
        self._found: list[Diagnostic] = []
        self._full = True
        self._outside: tuple[object, ...] | None = None
        self._unresolved = False
        # The last run's expansion of the module uses, while it still describes the model: a
        # node placed alone is patched into it rather than the uses expanded again (`Kept`).
        self._kept: Kept | None = None

    def note(self, changes: Iterable[Change]) -> None:
        """Remember changes made to the model since the last run (undone ones too)."""
        self._pending.extend(changes)

    def forget(self) -> None:
        """Make the next run a full one: something changed that no `Change` describes."""
        self._full = True

    def validate(self) -> list[Diagnostic]:
        """Every diagnostic of the model now, as `engine.validate` would give it."""
        with collector_paused():
            return self._run()

    def _run(self) -> list[Diagnostic]:
        outside = _outside_state(self.model, self.document)
        full = self._full or self._unresolved or outside != self._outside
        impact = Impact(() if full else self._pending)
        kept, self._kept = self._kept, None
        patch = bool(impact.alone) and kept is not None and kept.still_holds(impact, self.model)
        if impact.alone and not patch:
            # The expansion may change around the nodes placed alone (a name it chose is taken
            # now; it was not kept): what reads it runs again.
            impact = Impact(self._pending, alone=False)
        self._pending, self._full, self._outside = [], False, outside
        self.stats = RunStats(full=full)
        if not (full or impact.touched or impact.aspects) and self._all_classified:
            # Nothing but the layout changed, if anything: every finding stands where it was.
            self.stats.checks_reused = sum(len(rules) for rules, _ in self._results.values())
            self.stats.through_modules_run = False
            self._kept = kept  # nothing it reads changed
            return list(self._found)
        context = Context(
            self.model, self.document, self.limits, self.osc_version, self.osc_profile
        )
        if patch and kept is not None:
            context.reuse_flat(kept.patched(impact))
        run = _Pass(self, context, impact)
        try:
            return self._checked(run, context, impact, full)
        finally:
            context.release()
            self._kept = Kept.after(context, kept, impact, full)

    def _checked(
        self, run: _Pass, context: Context, impact: Impact, full: bool
    ) -> list[Diagnostic]:
        previous = {} if full else self._results
        results: dict[EObject, _Entry] = {}
        seen: set[Key] = set()
        found: list[Diagnostic] = []
        self._unresolved = False
        binds_touched = False  # a use binds an actor or role this edit touched
        for obj in objects(self.model, context):
            rules = self.registry.rules_for(obj.eClass)
            if isinstance(obj, scm.ModuleUse):
                self._note_unresolved(obj, context)
                if impact.participants and not binds_touched:
                    binds_touched = refers_to(obj, impact.participants)
            if not rules:
                continue
            entry = run.check(obj, rules, previous.get(obj))
            results[obj] = entry
            for findings in entry[1] or ():
                found.extend(unique(findings, seen))
        self._results = results
        stale_actors = self._through_actors and binds_touched
        if full or self._through_always or impact.aspects & self._through_reads or stale_actors:
            self._through = tuple(through_modules(context, self.document, self.registry))
        else:
            self._through = run.relocated(self._through)
            self.stats.through_modules_run = False
        found.extend(unique(self._through, seen))
        self._found = found
        return list(found)

    def _note_unresolved(self, use: scm.ModuleUse, context: Context) -> None:
        # A definition that did not resolve may resolve later (its library file appears): the
        # next run starts over rather than trust what was found without it.
        if use.definition is not None and context.definition_of(use) is None:
            self._unresolved = True


class _Pass:
    """One incremental run: which rules are stale where, and the checks that follow."""

    def __init__(self, validator: IncrementalValidator, context: Context, impact: Impact) -> None:
        self.validator = validator
        self.context = context
        self.impact = impact
        self.stats = validator.stats
        # Per rule code: (re-run everywhere, on SELF hits, on ABOVE hits, on ACTORS hits).
        self.plan: dict[str, tuple[bool, bool, bool, bool]] = {}
        for rule in validator.registry.rules():
            self.plan[rule.code] = stale_where(rule.reads, impact)
        # Per tuple of rules (by id; the registry hands out the same tuple per class): whether
        # any of them re-runs everywhere or on ACTORS hits this time.
        self._loud: dict[int, bool] = {}

    def check(self, obj: EObject, rules: tuple[Rule, ...], before: _Entry | None) -> _Entry:
        """One object's findings: re-run where stale, else the last run's, re-located."""
        if before is None or before[0] is not rules or obj in self.impact.graphs:
            return _entry(rules, [self.run(rule, obj) for rule in rules])
        around, inside = obj in self.impact.around, obj in self.impact.inside
        if not (around or inside or self.loud(rules)):
            self.stats.checks_reused += len(rules)
            if before[1] is None or not self.impact.touched:
                return before
            return _entry(rules, [self.relocated(findings) for findings in before[1]])
        last = before[1] or ((),) * len(rules)
        refers: bool | None = None  # worked out only if a rule needs it
        out: list[Findings] = []
        for index, rule in enumerate(rules):
            everywhere, on_self, on_above, on_actors = self.plan[rule.code]
            stale = everywhere or (on_self and around) or (on_above and inside)
            if not stale and on_actors:
                if refers is None:
                    refers = refers_to(obj, self.impact.participants)
                stale = refers
            if stale:
                out.append(self.run(rule, obj))
            else:
                out.append(self.relocated(last[index]))
                self.stats.checks_reused += 1
        return _entry(rules, out)

    def loud(self, rules: tuple[Rule, ...]) -> bool:
        """Whether one of these rules re-runs everywhere or on ACTORS hits in this run."""
        known = self._loud.get(id(rules))
        if known is None:
            known = any(self.plan[r.code][0] or self.plan[r.code][3] for r in rules)
            self._loud[id(rules)] = known
        return known

    def run(self, rule: Rule, obj: EObject) -> Findings:
        self.stats.checks_run += 1
        return tuple(run_rule(rule, obj, self.context, self.validator.document))

    def relocated(self, findings: Findings) -> Findings:
        """Findings of the last run, located again where an index or name above them changed."""
        if not findings or not self.impact.touched:
            return findings
        document = self.validator.document
        return tuple(
            locate(d.code, d.severity, d.message, d.element, document)
            if d.element is not None and self.impact.moved(d.element)
            else d
            for d in findings
        )


def _entry(rules: tuple[Rule, ...], found: list[Findings]) -> _Entry:
    return rules, (tuple(found) if any(found) else None)


def _outside_state(model: EObject, document: Document | None) -> tuple[object, ...]:
    """What a run depends on outside the model: the file's path, and the map file's state."""
    path = document.path if document is not None else None
    state: tuple[object, ...] = (path,)
    root = root_node(model) if isinstance(model, scm.Scenario) else None
    if root is None:
        return state
    try:
        reference = map_reference(root.map, path)
    except Exception:  # whatever the map text is, the map rules say what is wrong with it
        return (*state, root.map)
    if reference is None or reference.path is None:
        return (*state, root.map)
    try:
        stat = reference.path.stat()
    except OSError:
        return (*state, str(reference.path))
    return (*state, str(reference.path), stat.st_mtime_ns, stat.st_size)

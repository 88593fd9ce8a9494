"""The constraint registry: rules registered per metaclass, dispatched along the superclass chain.

A rule is a plain function `check(obj, context)` that yields `(element, message)` pairs, one per
violation. The decorator gives it a stable code, a severity, the metaclass it applies to (and so to
every subclass) and a one-line description for docs/validation-rules.md; and, stated once here
beside the rule, what it reads (for incremental validation), whether an export checks it, and
whether it judges values as stated (then an imported file has its findings too).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeAlias

from pyecore.ecore import EClass, EObject

from ..diagnostics import Severity
from .reads import Reads

if TYPE_CHECKING:
    from .context import Context

Finding: TypeAlias = tuple[EObject, str]
Check: TypeAlias = Callable[[Any, "Context"], Iterable[Finding]]


@dataclass(frozen=True)
class Rule:
    """One registered constraint with everything the rules table shows about it.

    `through_modules` rules also run on the nodes a module use expands to (on the flattened
    scenario), because only there do module parameters have the values a use gives them.
    `reads` says what the rule reads (sceml.validation.reads); None makes incremental validation
    re-run it everywhere, every time. `export` rules are what an export checks on the flattened
    scenario beyond a valid graph (sceml.export.checks).

    `judges_stated_values` rules judge a value as the scenario states it against the world (the
    actor kind's limits, the map), not how the model is built or whether it is complete: an
    OpenSCENARIO file that states the same value breaks the same rule, so on a scenario
    `sceml import` read from a file their findings are the original's too
    (sceml.importer.verdict).
    """

    code: str
    severity: Severity
    metaclasses: tuple[str, ...]
    description: str
    source: str
    check: Check = field(compare=False, repr=False)
    through_modules: bool = False
    reads: Reads | None = None
    export: bool = False
    judges_stated_values: bool = False

    @property
    def name(self) -> str:
        """The constraint's function name, e.g. `join_has_two_inputs`."""
        return str(getattr(self.check, "__name__", self.code))


class Registry:
    """Rules by metaclass name; `rules_for` resolves an EClass to every rule that applies to it."""

    def __init__(self) -> None:
        self._rules: dict[str, Rule] = {}
        self._by_eclass: dict[EClass, tuple[Rule, ...]] = {}

    def register(self, rule: Rule) -> None:
        """Add a rule; codes are unique."""
        if rule.code in self._rules:
            raise ValueError(f"rule code {rule.code} is registered twice")
        self._rules[rule.code] = rule
        self._by_eclass.clear()

    def rules(self) -> list[Rule]:
        """Every rule, ordered by code."""
        return sorted(self._rules.values(), key=lambda rule: rule.code)

    def rule(self, code: str) -> Rule:
        """One rule by its code."""
        return self._rules[code]

    def subset(
        self,
        *,
        codes: Iterable[str] = (),
        families: Iterable[str] = (),
        export: bool = False,
        severity: Severity = Severity.INFO,
    ) -> Registry:
        """A registry of some of these rules: those named in `codes`, whose code starts with one
        of `families` (e.g. `SCEML-P`), or (with `export`) that an export checks; at `severity`
        or above. The rules are the same objects."""
        wanted, prefixes = set(codes), tuple(families)
        chosen = Registry()
        for rule in self.rules():
            picked = (
                rule.code in wanted or rule.code.startswith(prefixes) or (export and rule.export)
            )
            if picked and rule.severity >= severity:
                chosen.register(rule)
        return chosen

    def rules_for(self, eclass: EClass) -> tuple[Rule, ...]:
        """The rules registered on `eclass` or any of its superclasses, ordered by code."""
        cached = self._by_eclass.get(eclass)
        if cached is None:
            names = {eclass.name, *(s.name for s in eclass.eAllSuperTypes())}
            cached = tuple(r for r in self.rules() if names.intersection(r.metaclasses))
            self._by_eclass[eclass] = cached
        return cached

    def constraint(
        self,
        code: str,
        severity: Severity,
        metaclass: str | tuple[str, ...],
        description: str,
        *,
        paper_rule: str | None = None,
        source: str | None = None,
        through_modules: bool = False,
        reads: Reads | None = None,
        export: bool = False,
        judges_stated_values: bool = False,
    ) -> Callable[[Check], Check]:
        """Register the decorated function as a constraint; see `Rule`."""
        metaclasses = (metaclass,) if isinstance(metaclass, str) else metaclass
        origin = source or (f"paper rule {paper_rule}" if paper_rule else "SPEC §6")

        def decorate(check: Check) -> Check:
            self.register(
                Rule(
                    code,
                    severity,
                    metaclasses,
                    description,
                    origin,
                    check,
                    through_modules=through_modules,
                    reads=reads,
                    export=export,
                    judges_stated_values=judges_stated_values,
                )
            )
            return check

        return decorate


#: The registry the rule modules of this package fill when they are imported.
REGISTRY = Registry()


def constraint(
    code: str,
    severity: Severity,
    metaclass: str | tuple[str, ...],
    description: str,
    *,
    paper_rule: str | None = None,
    source: str | None = None,
    through_modules: bool = False,
    reads: Reads | None = None,
    export: bool = False,
    judges_stated_values: bool = False,
) -> Callable[[Check], Check]:
    """Register a constraint in the package registry (see `Registry.constraint`)."""
    return REGISTRY.constraint(
        code,
        severity,
        metaclass,
        description,
        paper_rule=paper_rule,
        source=source,
        through_modules=through_modules,
        reads=reads,
        export=export,
        judges_stated_values=judges_stated_values,
    )


def findings(check: Check, obj: EObject, context: Context) -> Iterator[Finding]:
    """The findings of one check, materialised so that a failure midway is caught as a whole."""
    yield from list(check(obj, context))

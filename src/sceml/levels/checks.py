"""Per-sample checks: is a sampled concrete scenario one that should be written?

Sampling changes numbers only, never the graph, so what can go wrong per sample is a value:
a radius or duration that is not positive, a negative speed (the wide tails of a distribution
reach there), or a value the validation rules find implausible for its actor. Those are the
validation registry's value rules (parameters and plausibility), run here on the sampled values
only; this module has no rules of its own, so a sample is skipped exactly when `sceml validate`
would refuse it for its values.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cache
from typing import Any

from pyecore.ecore import EObject

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..model.traversal import all_contents
from ..validation import REGISTRY, Registry, validate
from ..validation.context import Context
from ..validation.edits import Change, Impact
from ..validation.limits import Limits
from ..validation.reads import stale
from ..validation.registry import Check
from .apply import FlatTemplate
from .paths import slots

#: The rule families whose outcome depends on parameter values: parameters and plausibility.
VALUE_RULE_PREFIXES = ("SCEML-P", "SCEML-L")

Validator = Callable[[scm.Scenario], list[str]]


class SampleChecker:
    """Decides, per sample, whether it is skipped and why (a short, countable reason)."""

    def __init__(self, template: FlatTemplate, validator: Validator | None = None) -> None:
        self.validator = validator if validator is not None else _validation_hook(template)

    def problem(self, scenario: scm.Scenario, row: Sequence[float]) -> str | None:
        """Why this sample must be skipped, or None if it may be written."""
        reasons = self.validator(scenario)
        if reasons:
            return "validation: " + ", ".join(sorted(set(reasons)))
        return None


def validate_model(scenario: scm.Scenario) -> list[Diagnostic]:
    """Every diagnostic of a model."""
    return validate(scenario)


@cache
def value_rules() -> Registry:
    """The registry's value-dependent error rules: the only ones a sample can newly break."""
    return REGISTRY.subset(families=VALUE_RULE_PREFIXES, severity=Severity.ERROR)


def _validation_hook(template: FlatTemplate) -> Validator:
    """Reasons (rule code, and the sampled path it is about) of the value rules for one sample.

    Sampling changes numbers, never the graph, actors or modules, so structure, actor, module,
    simultaneity and readiness rules are checked once on the logical scenario (by the caller).
    Per sample only the parameter and plausibility families run, and of those only the rules
    that read a sampled value, where they read it: each rule declares what it reads
    (`sceml.validation.reads`), and a sample is to these rules what an edit of each sampled
    value is to incremental validation (`edits.Impact`), an edit of numbers alone. So a rule
    runs on the objects that hold a sampled value and their containers, and, when the value
    lies in an actor (its own maxSpeed), the rules reading ACTOR_VALUES run on every node that
    actor performs: that node's speeds are held to the actor's limit. Every other object's
    values are the logical scenario's and were checked with it.
    Walking the whole model with every rule for every sample cost more than the export itself.

    Each sample is a validation run of its own, with a Context of its own: a memo of one
    sample (an actor's limit) must not answer for the next.
    """
    limits = Limits()
    # What a reason names: a sampled value by its sampled path, any other value (one a sampled
    # number is judged against, say an initial speed over the sample's own limit) by its own.
    paths: dict[Any, str] = {
        held: path
        for path, slot in slots(template.scenario).items()
        if (held := slot.held()) is not None
    }
    paths.update(
        (target, path)
        for path, targets in zip(template.paths, template.targets, strict=True)
        for target in targets
    )
    plan = _plan(template)

    def reasons(scenario: scm.Scenario) -> list[str]:
        context = Context(template.scenario, None, limits, None)
        found = []
        for obj, checks in plan:
            for code, check in checks:
                try:
                    # Only whether the rule finds anything, and its first finding, matter here.
                    first = next(iter(check(obj, context)), None)
                except Exception:  # a rule that breaks on odd values skips the sample, loudly
                    found.append("SCEML-X000")
                    continue
                if first is not None:
                    found.append(_reason(code, first[0], paths))
        return found

    return reasons


def _plan(template: FlatTemplate) -> list[tuple[EObject, tuple[tuple[str, Check], ...]]]:
    """Each object of the template with the value rules (code, check) that read one of its
    sampled values."""
    impact = Impact(
        [Change(target, "value") for targets in template.targets for target in targets],
        alone=False,
    )
    plan = []
    for obj in (template.scenario, *all_contents(template.scenario)):
        rules = value_rules().rules_for(obj.eClass)
        checks = tuple(
            (r.code, r.check) for r in rules if stale(r.reads, obj, impact, values_only=True)
        )
        if checks:
            plan.append((obj, checks))
    return plan


def _reason(code: str, element: EObject, paths: dict[Any, str]) -> str:
    path = paths.get(element)
    return f"{code} at {path}" if path is not None else code

"""Per-sample checks: is a sampled concrete scenario one that should be written?

Sampling changes numbers only, never the graph, so what can go wrong per sample is a value:
a radius or duration that is not positive, a negative speed (the wide tails of a distribution
reach there), or a value the validation rules find implausible for its actor. The physical
checks here are cheap and always run; the validation package's parameter and plausibility
rules then skip a sample too.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import cache
from typing import Any

import scemlmodel as scm

from ..diagnostics import Diagnostic, Severity
from ..validation import REGISTRY, Registry, validate
from ..validation.context import Context
from ..validation.limits import Limits
from ..validation.registry import findings
from .apply import FlatTemplate

#: Features whose value must be > 0, and the fragments of names whose value must be >= 0.
_POSITIVE = frozenset({"radius", "tolerance", "duration", "distance", "maxDuration", "time"})
_NON_NEGATIVE = ("speed", "Speed", "rate", "length", "width", "height", "gap")

Validator = Callable[[scm.Scenario], list[str]]


class SampleChecker:
    """Decides, per sample, whether it is skipped and why (a short, countable reason)."""

    def __init__(self, template: FlatTemplate, validator: Validator | None = None) -> None:
        self.rules: list[tuple[str, str]] = []
        for path, targets in zip(template.paths, template.targets, strict=True):
            features = {t.eContainmentFeature().name for t in targets}
            self.rules.append((path, _rule_for(features)))
        self.validator = validator if validator is not None else _validation_hook(template)

    def problem(self, scenario: scm.Scenario, row: Sequence[float]) -> str | None:
        """Why this sample must be skipped, or None if it may be written."""
        for (path, rule), number in zip(self.rules, row, strict=True):
            if rule == ">0" and not number > 0:
                return f"{path} must be > 0"
            if rule == ">=0" and not number >= 0:
                return f"{path} must be >= 0"
        if self.validator is not None:
            codes = self.validator(scenario)
            if codes:
                return "validation: " + ", ".join(sorted(set(codes)))
        return None


def _rule_for(features: set[str]) -> str:
    if features & _POSITIVE:
        return ">0"
    if any(fragment in name for name in features for fragment in _NON_NEGATIVE):
        return ">=0"
    return ""


#: The rule families whose outcome depends on parameter values: parameters and plausibility.
VALUE_RULE_PREFIXES = ("SCEML-P", "SCEML-L")


def validate_model(scenario: scm.Scenario) -> list[Diagnostic]:
    """Every diagnostic of a model."""
    return validate(scenario)


@cache
def _value_registry() -> Registry:
    registry = Registry()
    for rule in REGISTRY.rules():
        if rule.code.startswith(VALUE_RULE_PREFIXES):
            registry.register(rule)
    return registry


def _validation_hook(template: FlatTemplate) -> Validator:
    """Error codes of the value-dependent rules for one sample.

    Sampling changes numbers, never the graph, actors or modules, so structure, actor, module,
    simultaneity and readiness rules are checked once on the logical scenario (by the caller).
    Per sample only the parameter and plausibility families run, and only on the objects that
    hold a sampled value and their containers up to the scenario: every other object's values
    are the logical scenario's and were checked with it. Walking the whole model with pyecore's
    eAllContents for every sample cost more than the export itself.
    """
    context = Context(template.scenario, None, Limits(), None)
    plan = []
    for obj in _holders(template):
        rules = tuple(
            rule
            for rule in _value_registry().rules_for(obj.eClass)
            if rule.severity >= Severity.ERROR
        )
        if rules:
            plan.append((obj, rules))

    def codes(scenario: scm.Scenario) -> list[str]:
        found = []
        for obj, rules in plan:
            for rule in rules:
                try:
                    if next(iter(findings(rule.check, obj, context)), None) is not None:
                        found.append(rule.code)
                except Exception:  # a rule that breaks on odd values skips the sample, loudly
                    found.append("SCEML-X000")
        return found

    return codes


def _holders(template: FlatTemplate) -> list[Any]:
    """Each sampled Value and all of its containers, each once, innermost first."""
    seen: dict[int, Any] = {}
    for targets in template.targets:
        for target in targets:
            obj = target
            while obj is not None and id(obj) not in seen:
                seen[id(obj)] = obj
                obj = obj.eContainer()
    return list(seen.values())

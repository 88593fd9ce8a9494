"""Validation: constraint functions registered per metaclass, collected into diagnostics.

    from sceml.model.loading import load
    from sceml.validation import validate
    for diagnostic in validate(load("uis1-concrete.xmi").root):
        print(diagnostic)

Importing this package registers every rule of SPEC §6 (one module per area) in `REGISTRY`.
"""

from . import (
    actors,
    catalogs,
    controllers,
    map_rules,
    map_turns,
    modules,
    opaque,
    parameters,
    plausibility,
    players,
    readiness,
    simultaneity,
    structure,
)
from .engine import INTERNAL_ERROR, OLDER_RELEASE, is_valid, iter_diagnostics, validate
from .limits import DEFAULT_LIMITS, Limits, LimitsError, load_limits
from .registry import REGISTRY, Registry, Rule, constraint

__all__ = [
    "DEFAULT_LIMITS",
    "INTERNAL_ERROR",
    "OLDER_RELEASE",
    "REGISTRY",
    "Limits",
    "LimitsError",
    "Registry",
    "Rule",
    "constraint",
    "is_valid",
    "iter_diagnostics",
    "load_limits",
    "validate",
]

# The rule modules register themselves on import; naming them keeps linters from dropping them.
_RULE_MODULES = (
    actors,
    catalogs,
    controllers,
    map_rules,
    map_turns,
    modules,
    opaque,
    parameters,
    players,
    plausibility,
    readiness,
    simultaneity,
    structure,
)

"""What every constraint may ask about the model under validation: level, limits, modules, flat view."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from typing import TypeVar

from pyecore.ecore import EObject, EProxy

import scemlmodel as scm

from ..model import catalog
from ..model.documents import Document
from ..model.graph import scenario_level
from ..modules.expansion import Expansion, expansion
from .limits import Limits

T = TypeVar("T")


@cache
def is_kind(class_name: str, kind: str) -> bool:
    """`catalog.is_kind_of` by class name, cached: rules ask it for every node."""
    return catalog.is_kind_of(class_name, kind)


def performer(owner: EObject) -> scm.Actor | None:
    """The actor whose values `owner` holds: itself, or the node's reference actor.

    Inside a module definition the performer is a role; the flattened scenario binds it.
    """
    if isinstance(owner, scm.Actor):
        return owner
    actor = getattr(owner, "referenceActor", None)
    return actor if isinstance(actor, scm.Actor) else None


@dataclass
class Context:
    """Shared state of one validation run; rules read it and never change the model."""

    root: EObject
    document: Document | None
    limits: Limits
    osc_version: str | None = None
    osc_profile: str | None = None
    flat_failure: str | None = None
    _memo: dict[object, object] = field(default_factory=dict)
    _definitions: dict[EObject, scm.ModuleDefinition | None] = field(default_factory=dict)
    _levels: dict[EObject, str | None] = field(default_factory=dict)
    _flat: Expansion | None = None
    _flat_done: bool = False

    def memo(self, key: object, compute: Callable[[], T]) -> T:
        """`compute()` once per run and key: lets per-node rules share per-graph tables."""
        if key not in self._memo:
            self._memo[key] = compute()
        return self._memo[key]  # type: ignore[return-value]

    def home(self, obj: EObject) -> EObject:
        """The model `obj` belongs to: its outermost container, or for a module internal copied
        by the expansion (see `flat`), which has no container, the scenario it was expanded in."""
        top = obj
        while (container := top.eContainer()) is not None:
            top = container
        return self._expanded_in(top)

    def _expanded_in(self, top: EObject) -> EObject:
        if self._flat is not None and self._flat.holds(top):
            return self._flat.scenario
        return top

    def level_of(self, obj: EObject) -> str | None:
        """The abstraction level governing `obj`; None inside module definitions, which have none."""
        top = obj
        while True:  # one climb: both a definition on the way and the top are needed
            if isinstance(top, scm.ModuleDefinition):
                return None
            container = top.eContainer()
            if container is None:
                break
            top = container
        top = self._expanded_in(top)
        if top not in self._levels:
            self._levels[top] = scenario_level(top) if isinstance(top, scm.Scenario) else None
        return self._levels[top]

    def definition_of(self, use: scm.ModuleUse) -> scm.ModuleDefinition | None:
        """The definition a use refers to, loaded if needed, or None when it cannot be had."""
        if use not in self._definitions:
            self._definitions[use] = _resolve(use)
        return self._definitions[use]

    def flat(self) -> Expansion | None:
        """The scenario with its module uses expanded (computed once), or None when the root is
        not a scenario with module uses or they cannot be expanded (`flat_failure` says why).

        The expansion copies only module internals; the scenario's own nodes are its originals.
        """
        if self._flat_done:
            return self._flat
        self._flat_done = True
        scenario = self.root
        if not isinstance(scenario, scm.Scenario):
            return None
        if not any(isinstance(node, scm.ModuleUse) for node in scenario.nodes):
            return None
        try:
            self._flat = expansion(scenario)
        except Exception as error:  # any reason at all: the module rules say what is wrong
            self.flat_failure = str(error) or type(error).__name__
        return self._flat

    def flat_computed(self) -> bool:
        """Whether `flat` was asked for (or given by `reuse_flat`) in this run."""
        return self._flat_done

    def reuse_flat(self, flat: Expansion | None) -> None:
        """Take `flat` as the expansion of this run's model: one kept from an earlier run of
        the same model, patched for what changed since (sceml.validation.kept)."""
        self._flat, self._flat_done = flat, True

    def release(self) -> None:
        """End of the run: the expansion's copies stop being recorded in the model they name."""
        if self._flat is not None:
            self._flat.release()


def _resolve(use: scm.ModuleUse) -> scm.ModuleDefinition | None:
    try:
        definition = use.definition
        if isinstance(definition, EProxy):
            # The wrapped object, so that isinstance and identity work on what the proxy stood for.
            definition = definition.force_resolve()
        return definition if isinstance(definition, scm.ModuleDefinition) else None
    except Exception:  # pyecore reports broken hrefs with assorted exception types
        return None

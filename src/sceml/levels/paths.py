"""Parameter paths: one readable name for every numeric parameter of a scenario, and its slot.

A path starts with the name of a node, an actor or a module use, followed by feature names down
the containment tree; list members are indexed as `name[i]`:

    Root.maxDuration                      a parameter of the root node
    Root.environment.fogVisualRange       inside the root's environment
    ego.initialSpeed                      an actor parameter
    ego.startPosition.s                   inside an actor's start position
    Accelerate_1.targetSpeed              a maneuver or condition parameter
    InLocationRadius_2.position.x         inside a node's position
    FollowTrajectory_1.waypoints[0].y     inside one waypoint
    CrossingManeuver_1.crossingSpeed      a parameter of a module use (its override)

A node path may also be written with its reference actor in front, as in
`ego.Accelerate_1.targetSpeed`; `resolve` maps that to the canonical `Accelerate_1.targetSpeed`.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from pyecore.ecore import EObject, EReference

import scemlmodel as scm

from .. import catalog, params
from ..copying import copy_tree
from ..errors import ArgumentError, SceMLError
from ..modules.resolve import resolved_definition

_SEGMENT = re.compile(r"^(?P<name>[^.\[\]]+)(?:\[(?P<index>\d+)\])?$")


class LevelError(SceMLError):
    """A scenario cannot be moved to another abstraction level as asked."""


class LevelArgumentError(LevelError, ArgumentError):
    """A level operation was given a value it cannot use (a sample count, an assignment)."""


class UnknownPathError(LevelArgumentError):
    """A parameter path names nothing in the scenario; `valid` lists the paths that exist."""

    def __init__(self, path: str, valid: Sequence[str]) -> None:
        listing = "\n  ".join(valid) if valid else "(the scenario has no numeric parameters)"
        super().__init__(f"unknown parameter path {path!r}; valid paths:\n  {listing}")
        self.path = path
        self.valid = tuple(valid)


@dataclass(frozen=True, eq=False)
class Slot:
    """Where one numeric parameter lives: `owner.feature`, or a module use's parameter."""

    path: str
    owner: EObject
    feature: str
    unit: str
    default: float | None
    #: Unset has a meaning of its own (a lane or road position's h: the lane's direction).
    optional: bool = False

    @property
    def is_module_parameter(self) -> bool:
        """Whether the slot is a parameter of a module use, set through an override."""
        return isinstance(self.owner, scm.ModuleUse)

    def held(self) -> scm.ParameterValue | None:
        """What the slot holds; for a module parameter its override, else the module's default."""
        if not self.is_module_parameter:
            return self.owner.eGet(self.feature)
        override = _override(self.owner, self.feature)
        if override is not None:
            return override.value
        parameter = _module_parameter(self.owner, self.feature)
        return parameter.default if parameter is not None else None

    def put(self, value: scm.ParameterValue) -> None:
        """Place `value` in the slot (a module parameter gets an override)."""
        if not self.is_module_parameter:
            self.owner.eSet(self.feature, value)
            return
        override = _override(self.owner, self.feature)
        if override is None:
            override = scm.ParameterOverride(parameter=self.feature)
            self.owner.overrides.append(override)
        override.value = value


def _override(use: scm.ModuleUse, name: str) -> scm.ParameterOverride | None:
    return next((o for o in use.overrides if o.parameter == name), None)


def _module_parameter(use: scm.ModuleUse, name: str) -> scm.ModuleParameter | None:
    definition = resolved_definition(use)
    return next((p for p in definition.parameters if p.name == name), None)


def slots(scenario: scm.Scenario) -> dict[str, Slot]:
    """Every numeric parameter of the scenario by canonical path, set or not, in model order."""
    found: dict[str, Slot] = {}
    for prefix, owner in _named_owners(scenario):
        for slot in _slots_below(owner, prefix):
            if slot.path in found:
                raise LevelError(
                    f"two elements give the parameter path {slot.path!r}; rename one of them"
                )
            found[slot.path] = slot
    return found


def _named_owners(scenario: scm.Scenario) -> Iterator[tuple[str, EObject]]:
    for node in scenario.nodes:
        yield str(node.name), node
        if isinstance(node, scm.RootNode):
            for actor in node.actors:
                yield str(actor.name), actor


def _slots_below(owner: EObject, prefix: str) -> Iterator[Slot]:
    if isinstance(owner, scm.ModuleUse):
        for parameter in resolved_definition(owner).parameters:
            yield Slot(
                f"{prefix}.{parameter.name}",
                owner,
                str(parameter.name),
                parameter.unit or "",
                _default_of(parameter),
            )
        return
    for spec in catalog.parameters(owner):
        default = spec.default
        if spec.per_actor_default:
            default = catalog.actor_dimensions(owner).get(spec.name)
        yield Slot(f"{prefix}.{spec.name}", owner, spec.name, spec.unit, default, spec.optional)
    for reference in owner.eClass.eAllReferences():
        if not _is_nested_record(reference):
            continue
        held = owner.eGet(reference)
        if reference.many:
            for index, child in enumerate(held):
                yield from _slots_below(child, f"{prefix}.{reference.name}[{index}]")
        elif held is not None:
            yield from _slots_below(held, f"{prefix}.{reference.name}")


def _default_of(parameter: scm.ModuleParameter) -> float | None:
    held = parameter.default
    return float(held.value) if isinstance(held, scm.Value) else None


def _is_nested_record(reference: EReference) -> bool:
    """Positions and the environment hold parameters of their own; actors are reached by name."""
    if not reference.containment or reference.name == "actors":
        return False
    kind = catalog.class_name(reference.eType)
    return catalog.is_kind_of(kind, "Position") or kind == "Environment"


def resolve(scenario: scm.Scenario, path: str, known: dict[str, Slot] | None = None) -> Slot:
    """The slot a path names; UnknownPathError lists the valid paths when it names none."""
    known = slots(scenario) if known is None else known
    if path in known:
        return known[path]
    canonical = _without_actor(scenario, path)
    if canonical is not None and canonical in known:
        return known[canonical]
    raise UnknownPathError(path, list(known))


def _without_actor(scenario: scm.Scenario, path: str) -> str | None:
    """`ego.Accelerate_1.targetSpeed` -> `Accelerate_1.targetSpeed` when ego is its reference actor."""
    actor_name, _, rest = path.partition(".")
    node_name = rest.partition(".")[0]
    node = next((n for n in scenario.nodes if n.name == node_name), None)
    actor = getattr(node, "referenceActor", None)
    if actor is None or actor.name != actor_name:
        return None
    return rest


def find_feature(scenario: scm.Scenario, path: str) -> tuple[EObject, EReference]:
    """The object and containment feature a path names, e.g. `ego.startPosition`; for promote."""
    segments = path.split(".")
    owners = dict(_named_owners(scenario))
    if len(segments) < 2 or segments[0] not in owners:
        raise UnknownPathError(path, sorted(owners))
    owner = owners[segments[0]]
    for segment in segments[1:-1]:
        owner = _step(owner, segment, path)
    feature = owner.eClass.findEStructuralFeature(segments[-1])
    if not isinstance(feature, EReference) or not feature.containment or feature.many:
        names = [r.name for r in owner.eClass.eAllReferences() if r.containment and not r.many]
        raise UnknownPathError(path, [f"{'.'.join(segments[:-1])}.{n}" for n in names])
    return owner, feature


def _step(owner: EObject, segment: str, path: str) -> EObject:
    match = _SEGMENT.match(segment)
    feature = owner.eClass.findEStructuralFeature(match["name"]) if match else None
    if match is None or not isinstance(feature, EReference) or not feature.containment:
        raise UnknownPathError(path, [])
    held = owner.eGet(feature)
    if feature.many:
        index = int(match["index"] or -1)
        if not 0 <= index < len(held):
            raise UnknownPathError(path, [])
        held = held[index]
    if held is None:
        raise UnknownPathError(path, [])
    return held


def unresolved(scenario: scm.Scenario, known: dict[str, Slot] | None = None) -> list[str]:
    """Paths that keep a scenario from being concrete: ranges, distributions, required but unset."""
    known = slots(scenario) if known is None else known
    missing = []
    for path, slot in known.items():
        held = slot.held()
        unset_required = held is None and slot.default is None and not slot.optional
        if unset_required or not params.is_single_value(held):
            missing.append(path)
    return missing


def place_value(slot: Slot, number: float) -> None:
    """Set a slot to a single Value, reusing a Value already there."""
    held = slot.owner.eGet(slot.feature) if not slot.is_module_parameter else None
    if isinstance(held, scm.Value):
        held.value = float(number)
        return
    slot.put(scm.Value(value=float(number)))


def place(slot: Slot, value: scm.ParameterValue) -> None:
    """Set a slot to a copy of `value` (so one value can fill several slots)."""
    slot.put(copy_tree(value) if value.eContainer() is not None else value)

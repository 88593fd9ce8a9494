"""Turn a logical scenario and one sample's values into a concrete scenario.

`apply` is the reference: copy the logical scenario, set each sampled path to a Value, mark it
concrete. `FlatTemplate` is the fast equivalent for batch export: it flattens the logical
scenario once and then only rewrites numbers in place, so that for every sample

    template.fill(values)  equals  flatten(apply(logical, values))

Where a sampled value lands after flattening is read from flatten's provenance: each varied
slot gets a Value, and the template's targets are the values of the flat scenario that were
copied from it. Flatten itself decides where each module-use override goes (one module
parameter may fill several slots, e.g. a destination used by a maneuver and a condition), so
the mapping cannot drift from flatten's rules.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

from pyecore.ecore import EObject

import scemlmodel as scm

from ..model.copying import Copier
from ..model.graph import root_node
from ..model.locating import model_path
from ..modules.flatten import expand
from .paths import LevelError, place_value, resolve, slots, unresolved


def copy_scenario(scenario: scm.Scenario) -> scm.Scenario:
    """A deep copy of a scenario; references into libraries keep their targets."""
    copier = Copier()
    duplicate = copier.copy(scenario)
    copier.copy_references()
    return duplicate


def set_level(scenario: scm.Scenario, level: str) -> None:
    """Set the abstraction level on the scenario's root node."""
    root = root_node(scenario)
    if root is None:
        raise LevelError("the scenario has no root node")
    root.level = scm.AbstractionLevel.getEEnumLiteral(level)


def apply(logical: scm.Scenario, values: Mapping[str, float]) -> scm.Scenario:
    """A concrete copy of `logical` with each path in `values` set to its number.

    Raises LevelError when a parameter is still a range or distribution afterwards, and
    UnknownPathError for a path the scenario does not have.
    """
    concrete = copy_scenario(logical)
    known = slots(concrete)
    for path, number in values.items():
        place_value(resolve(concrete, path, known), number)
    left = unresolved(concrete, known)
    varied = [path for path in left if known[path].held() is not None]
    if varied:
        raise LevelError(f"no value given for {', '.join(varied)}")
    set_level(concrete, "concrete")
    return concrete


class FlatTemplate:
    """A flattened concrete copy of a logical scenario whose varied numbers are set in place."""

    def __init__(self, logical: scm.Scenario, paths: Sequence[str]) -> None:
        self.paths = tuple(paths)
        tagged = copy_scenario(logical)
        known = slots(tagged)
        placed: dict[EObject, list[int]] = {}
        for k, path in enumerate(self.paths):
            slot = resolve(tagged, path, known)
            place_value(slot, 0.0)
            placed.setdefault(slot.held(), []).append(k)
        flattened = expand(tagged)
        self.scenario = flattened.scenario
        set_level(self.scenario, "concrete")
        self.targets: list[list[scm.Value]] = [[] for _ in self.paths]
        for obj in self.scenario.eAllContents():
            origin = flattened.origin(obj)
            if isinstance(obj, scm.Value) and origin is not None and origin.element in placed:
                for k in placed[origin.element]:
                    self.targets[k].append(obj)
            elif isinstance(obj, scm.ParameterValue) and not isinstance(obj, scm.Value):
                raise LevelError(
                    f"{obj.eClass.name} is not among the sampled parameters; inside a module "
                    "definition, make it a module parameter so that a path reaches it",
                    element=model_path(obj),
                )

    def fill(self, values: Sequence[float]) -> scm.Scenario:
        """Write one sample's values (in path order) into the template and return it."""
        for targets, number in zip(self.targets, values, strict=True):
            number = float(number)
            for target in targets:
                target.value = number
        return self.scenario

    def slots_of(self, index: int) -> list[scm.Value]:
        """The Value objects of the flattened scenario that path `index` fills."""
        return list(self.targets[index])

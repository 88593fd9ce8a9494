"""Raise a scenario to the concrete level with explicit values for its parameter paths."""

from __future__ import annotations

from collections.abc import Mapping

import scemlmodel as scm

from ..model import params
from .apply import copy_scenario, set_level
from .paths import LevelArgumentError, LevelError, Slot, place_value, resolve, slots, unresolved


def concretize(scenario: scm.Scenario, assignments: Mapping[str, float]) -> scm.Scenario:
    """A concrete copy of `scenario` with every path in `assignments` set to its value.

    Every range and distribution must get a value, and every required parameter without a
    language default must be set. UnknownPathError (listing the valid paths) for a path the
    scenario does not have; LevelError naming what is still open otherwise.
    """
    concrete = copy_scenario(scenario)
    known = slots(concrete)
    for path, number in assignments.items():
        place_value(resolve(concrete, path, known), number)
    left = unresolved(concrete, known)
    if left:
        raise LevelError(
            "still not concrete; give a value (--set PATH=VALUE) for: "
            + "; ".join(_open(known[path]) for path in left)
        )
    set_level(concrete, "concrete")
    return concrete


def _open(slot: Slot) -> str:
    held = slot.held()
    what = "unset, no default" if held is None else params.describe(held, slot.unit)
    return f"{slot.path} ({what})"


def parse_assignment(text: str) -> tuple[str, float]:
    """`path=value` as (path, number); LevelArgumentError when it is not of that form."""
    path, sep, raw = text.partition("=")
    try:
        number = float(raw)
    except ValueError:
        number = float("nan")
    if not sep or not path.strip() or number != number:
        raise LevelArgumentError(f"expected PATH=NUMBER (a number in SI units), got {text!r}")
    return path.strip(), number

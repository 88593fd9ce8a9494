"""Controllers: what a player needs to run an assigned controller, an override or an activation."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator

import scemlmodel as scm

from ..diagnostics import Severity
from .context import Context
from .reads import SELF, Reads
from .registry import Finding, constraint

#: Inputs OpenSCENARIO gives as a fraction of their travel (0: released pedal, 1: pressed fully).
PEDALS = ("throttle", "brake", "clutch", "parkingBrake")


@constraint(
    "SCEML-K001",
    Severity.ERROR,
    ("Actor", "AssignController"),
    "a controller (an actor's or an assignment's) has a name, by which players pick it, and "
    "each of its properties a name",
    source="SPEC §2",
    # the node's or actor's own controller, activation and overrides (contents)
    reads=Reads(SELF),
)
def controller_is_named(
    owner: scm.Actor | scm.AssignController, context: Context
) -> Iterator[Finding]:
    held = owner.controller
    if held is None:
        if isinstance(owner, scm.AssignController):
            yield owner, f"{owner.name!r} assigns no controller; give it one with a name"
        return
    if not held.name:
        yield owner, f"the controller of {owner.name!r} has no name; players pick it by its name"
    for unnamed in (p for p in held.properties if not p.name):
        yield (
            owner,
            f"a property of {owner.name!r}'s controller has no name (value {unnamed.value!r})",
        )


@constraint(
    "SCEML-K002",
    Severity.ERROR,
    "OverrideController",
    "an OverrideController overrides at least one input, each at most once (OpenSCENARIO has one "
    "element per input)",
    source="SPEC §2",
    # the node's or actor's own controller, activation and overrides (contents)
    reads=Reads(SELF),
)
def override_inputs_once(node: scm.OverrideController, context: Context) -> Iterator[Finding]:
    kinds = Counter(str(o.kind.name) for o in node.overrides)
    if not kinds:
        yield node, f"{node.name!r} overrides no input"
    for kind, count in sorted(kinds.items()):
        if count > 1:
            yield node, f"{node.name!r} overrides {kind} {count} times; once is all a player reads"


@constraint(
    "SCEML-K003",
    Severity.ERROR,
    "OverrideController",
    "an active pedal override (throttle, brake, clutch, parking brake) is between 0 and 1",
    source="SPEC §2",
    # the node's or actor's own controller, activation and overrides (contents)
    reads=Reads(SELF),
)
def pedal_within_travel(node: scm.OverrideController, context: Context) -> Iterator[Finding]:
    for held in node.overrides:
        kind = str(held.kind.name)
        if held.active and kind in PEDALS and not 0.0 <= float(held.value or 0.0) <= 1.0:
            yield node, f"{node.name!r}: {kind} {held.value:g} is outside 0..1 (its travel)"


@constraint(
    "SCEML-K004",
    Severity.WARNING,
    "ActivateController",
    "an ActivateController switches at least one domain on or off",
    source="SPEC §2",
    # the node's or actor's own controller, activation and overrides (contents)
    reads=Reads(SELF),
)
def activation_switches_something(
    node: scm.ActivateController, context: Context
) -> Iterator[Finding]:
    domains = (node.lateral, node.longitudinal, node.lighting, node.animation)
    if all(domain is None for domain in domains):
        yield node, f"{node.name!r} switches no domain: it does nothing"

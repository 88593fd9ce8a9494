"""The preview player: a concrete scenario executed with SPEC §3 semantics by kinematic actors.

    >>> from sceml.model.loading import load_scenario
    >>> from sceml.simulate import simulate
    >>> run = simulate(load_scenario("examples/uis1-concrete.xmi").root, "examples/uis1-concrete.xmi")
    >>> run.end_reason, run.node("InVehicleRadius_1").finished  # doctest: +SKIP

What it models and what it does not: docs/simulate.md. It is a preview, not a vehicle-dynamics
simulator: no tyres, no steering limits, no collisions avoided or reacted to.
"""

from __future__ import annotations

from .preview import DEFAULT_STEP, simulate
from .run import END_NODE, MAX_DURATION, ActorInfo, NodeRecord, PairMetrics, Run
from .world import SimulationError

__all__ = [
    "DEFAULT_STEP",
    "END_NODE",
    "MAX_DURATION",
    "ActorInfo",
    "NodeRecord",
    "PairMetrics",
    "Run",
    "SimulationError",
    "simulate",
]

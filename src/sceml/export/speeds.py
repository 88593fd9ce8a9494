"""SpeedAction dynamics per profile, including CARLA's lack of rate-based speed changes.

scenario_runner (srunner/tools/openscenario_parser.py) reads a SpeedActionDynamics value as a
distance when dynamicsDimension is `distance` and as a duration otherwise, so a `rate` would be
taken for seconds. For the carla profile the rate is therefore turned into a duration,
|target - speed before| / rate, where the speed before is the last speed the graph sets for the
actor on the path back to the root (first predecessor at each step), or its initial speed.
"""

from __future__ import annotations

import scemlmodel as scm

from ..model import params
from ..model.graph import predecessors
from ..model.speed_shapes import PEAK_FACTORS
from .context import Context
from .values import number

_DEFAULT_RATE_FEATURE = "rate"


def speed_dynamics(ctx: Context, node: scm.ActionNode) -> dict[str, str]:
    """shape/dimension/value of the SpeedActionDynamics of Accelerate, Decelerate and Stop. A
    step is written as a zero time (players change the speed at once whatever the dimension)."""
    shape = node.shape.name
    if shape == "step":
        return {"shape": "step", "dimension": "time", "value": "0.0"}
    if ctx.profile != "carla":
        return {"shape": shape, "dimension": "rate", "value": ctx.values.text(node, "rate")}
    target = 0.0 if isinstance(node, scm.Stop) else params.concrete(node, "targetSpeed")
    rate = params.concrete(node, _DEFAULT_RATE_FEATURE)
    before = speed_before(node)
    # The rate of a cubic or sinusoidal change is its peak: the change lasts longer.
    seconds = PEAK_FACTORS[shape] * abs(target - before) / rate
    return {"shape": shape, "dimension": "time", "value": number(round(seconds, 6))}


def speed_before(node: scm.ActionNode) -> float:
    """The speed the graph last set for the node's actor before `node`, else its initial speed."""
    actor = node.referenceActor
    seen: set[int] = set()
    current = next(iter(predecessors(node)), None)
    while current is not None and id(current) not in seen:
        seen.add(id(current))
        if getattr(current, "referenceActor", None) is actor:
            speed = _speed_set_by(current)
            if speed is not None:
                return speed
        current = next(iter(predecessors(current)), None)
    return params.concrete(actor, "initialSpeed") if actor is not None else 0.0


def _speed_set_by(node: scm.GraphElement) -> float | None:
    if isinstance(node, scm.Stop):
        return 0.0
    if isinstance(node, scm.Accelerate | scm.Decelerate):
        return params.concrete(node, "targetSpeed")
    if isinstance(node, scm.DriveDistance | scm.Overtake):
        return params.concrete(node, "speed")
    return None

"""What a SpeedShape means, as OpenSCENARIO players read a speed change (esmini 3.6's
TransitionDynamics): how long it lasts at a given rate and the speed at each moment of it.

A cubic or sinusoidal change's rate is its peak rate, so it lasts longer than a linear change of
the same rate: `PEAK_FACTORS[shape] * |target - start| / rate` seconds.
"""

from __future__ import annotations

import math

#: Peak rate over mean rate of each gradual shape (a step has no duration).
PEAK_FACTORS = {"linear": 1.0, "cubic": 1.5, "sinusoidal": math.pi / 2}


def duration(shape: str, start: float, target: float, rate: float) -> float:
    """Seconds a change from `start` to `target` m/s takes at a (peak) `rate` in m/s²."""
    if shape == "step" or start == target:
        return 0.0
    return PEAK_FACTORS[shape] * abs(target - start) / rate


def fraction(shape: str, progress: float) -> float:
    """The share of the speed change made at `progress` (0 to 1) of its duration."""
    p = min(max(progress, 0.0), 1.0)
    if shape == "step":
        return 1.0
    if shape == "cubic":
        return p * p * (3 - 2 * p)
    if shape == "sinusoidal":
        return (1 - math.cos(math.pi * p)) / 2
    return p

"""Criticality search: the concrete scenarios of a logical one whose runs come closest to a crash.

    explore(logical, "uis1-logical.xmi", metric="collision", budget=500, seed=0) -> Exploration

`search` draws and refines the parameter values; `workers` runs the preview (`sceml.simulate`)
for each batch of them on an executor (`sceml.executors`); `objective` says what "critical"
means per metric; `outputs` writes the CSV of every run, the most critical concrete scenarios
(.xmi and .xosc) and the plots (docs/simulate.md).
"""

from __future__ import annotations

from .objective import METRICS, NO_CONFLICT
from .search import Evaluation, Exploration, ExploreError, explore

__all__ = ["METRICS", "NO_CONFLICT", "Evaluation", "Exploration", "ExploreError", "explore"]

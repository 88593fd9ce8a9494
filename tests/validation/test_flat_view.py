"""The validator's flat view traces each expanded node by flatten's provenance, not by its name."""

from __future__ import annotations

from pathlib import Path

import scemlmodel as scm
from sceml import io
from sceml.validation.context import Context
from sceml.validation.limits import Limits

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_nodes_nested_three_deep_trace_to_the_outermost_use() -> None:
    scenario = io.load(EXAMPLES / "overtaking-concrete.xmi").root
    flat = Context(scenario, None, Limits()).flat()
    assert flat is not None
    use = next(n for n in scenario.nodes if isinstance(n, scm.ModuleUse))
    inner = next(n for n in flat.nodes if str(n.name).endswith("TimeToCollision_1"))
    assert flat.from_module(inner) and flat.origin(inner) is use


def test_plain_nodes_sharing_a_name_each_trace_to_themselves() -> None:
    scenario = io.load(EXAMPLES / "uis2-concrete.xmi").root
    first, second = [n for n in scenario.nodes if isinstance(n, scm.InLocationRadius)]
    second.name = first.name
    # A name that looks like an expanded node's is still a plain node of the scenario.
    plain = next(n for n in scenario.nodes if n.name == "DriveDistance_1")
    plain.name = "CrossingManeuver_1.Waiting"
    flat = Context(scenario, None, Limits()).flat()
    assert flat is not None
    copies = {flat.origin(n): n for n in flat.nodes if not flat.from_module(n)}
    assert first in copies and second in copies and plain in copies
    assert copies[second] is not copies[first]

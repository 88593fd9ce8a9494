"""Speed change shapes and the 1.1 comparison rules (issue 24): files/speed-shapes.xosc imports
its cubic, sinusoidal, linear and step SpeedActions as Accelerate, Decelerate and Stop with their
shape (a time turned into the peak rate players read), its greaterOrEqual and lessOrEqual
SpeedConditions as written; the export writes them back at 1.1 to 1.3 (XSD-valid) and imports
again to the same scenario, and refuses the rules for 1.0 (SCEML-E008). The preview follows the
shapes; its values are worked out by hand below (esmini 3.6's log of the file, read by hand:
SpeedUp 0.05 s to 3.00 s, SpeedUpMore 3.05 s to 7.75 s, Halt at 7.80 s, LeadHalts at 3.05 s;
the preview finishes a step later, as it acts in the step a maneuver starts)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from sceml.export import ExportError, export_to_file
from sceml.importer import import_file, import_to_file
from sceml.model import graph
from sceml.model.loading import load
from sceml.simulate import simulate
from sceml.xosc import schema

SHAPES = Path(__file__).parent / "files" / "speed-shapes.xosc"


def speed_changes(path: Path) -> list[tuple[str, str, str, str]]:
    """(shape, dimension, value, target) of every SpeedAction outside Init, in order."""
    found = []
    for action in etree.parse(str(path)).iterfind("Storyboard/Story//SpeedAction"):
        dynamics = action.find("SpeedActionDynamics")
        target = action.find("SpeedActionTarget/AbsoluteTargetSpeed")
        found.append(
            (
                dynamics.get("dynamicsShape"),
                dynamics.get("dynamicsDimension"),
                f"{float(dynamics.get('value')):g}",
                f"{float(target.get('value')):g}",
            )
        )
    return found


def speed_rules(path: Path) -> list[tuple[str, str]]:
    """(rule, value) of every SpeedCondition, sorted."""
    return sorted(
        (str(c.get("rule")), f"{float(c.get('value')):g}")
        for c in etree.parse(str(path)).iter("SpeedCondition")
    )


def test_shapes_and_rules_import_as_written() -> None:
    imported = import_file(SHAPES)
    assert imported.report.counts()["opaque"] == 0
    nodes = {n.name: n for n in imported.scenario.nodes}
    changes = {
        name: (nodes[name].eClass.name, nodes[name].shape.name, nodes[name].rate)
        for name in ("SpeedUp", "SpeedUpMore", "Halt", "LeadSlows", "LeadHalts")
    }
    rates = {name: None if rate is None else rate.value for name, (_, _, rate) in changes.items()}
    # cubic over 3 s from 10 to 19 m/s: peak rate 1.5 * 9 / 3; the rest as written; a step
    # has no rate (the language default, unused).
    assert rates == {
        "SpeedUp": 4.5,
        "SpeedUpMore": 2.0,
        "Halt": None,
        "LeadSlows": 3.0,
        "LeadHalts": None,
    }
    assert {name: kind_shape[:2] for name, kind_shape in changes.items()} == {
        "SpeedUp": ("Accelerate", "cubic"),
        "SpeedUpMore": ("Accelerate", "sinusoidal"),
        "Halt": ("Stop", "step"),
        "LeadSlows": ("Decelerate", "linear"),
        "LeadHalts": ("Stop", "step"),
    }
    rules = sorted(
        (n.rule.name, n.speed.value) for n in nodes.values() if n.eClass.name == "SpeedCondition"
    )
    assert rules == [("greaterOrEqual", 19.0), ("greaterOrEqual", 25.0), ("lessOrEqual", 16.0)]


@pytest.mark.parametrize("version", ("1.1", "1.2", "1.3"))
def test_shapes_and_rules_export_as_they_were_read(version: str, tmp_path: Path, same) -> None:
    model = tmp_path / "shapes.xmi"
    import_to_file(SHAPES, model)
    exported = tmp_path / "shapes.xosc"
    export_to_file(load(model).root, exported, version=version, source_path=model)
    assert schema.validate_file(exported, version) == []
    # The cubic's 3 s are written as its peak rate, which players read back as 3 s.
    assert speed_changes(exported) == [
        ("cubic", "rate", "4.5", "19"),
        ("sinusoidal", "rate", "2", "25"),
        ("step", "time", "0", "0"),
        ("linear", "rate", "3", "16"),
        ("step", "time", "0", "0"),
    ]
    assert speed_rules(exported) == speed_rules(SHAPES)
    first, again = import_file(SHAPES), import_file(exported)
    for scenario in (first.scenario, again.scenario):
        graph.root_node(scenario).environment = None  # the export writes the default one
    same(first.scenario, again.scenario)


def test_openscenario_1_0_refuses_the_inclusive_rules(tmp_path: Path) -> None:
    model = tmp_path / "shapes.xmi"
    import_to_file(SHAPES, model)
    with pytest.raises(ExportError) as refused:
        export_to_file(load(model).root, tmp_path / "shapes.xosc", version="1.0")
    said = [(d.code, d.message) for d in refused.value.diagnostics]
    assert (
        "SCEML-E008",
        "'LeadHaltsStart' cannot be exported to OpenSCENARIO 1.0: the rule "
        "lessOrEqual needs OpenSCENARIO 1.1 or later (1.0 compares strictly)",
    ) in said
    assert not (tmp_path / "shapes.xosc").exists()


def test_the_preview_follows_each_shape() -> None:
    run = simulate(import_file(SHAPES).scenario, SHAPES)
    ego = run.actor_index("Ego")

    def speed_at(t: float) -> float:
        return float(run.states[ego, int(np.argmin(abs(run.times - t))), 3])

    # Cubic from 0.05 s for 3 s: v = 10 + 9 * p² (3 - 2p); p = 0.25 at 0.8 s gives 0.15625
    # (a linear change would be at 12.25), p = 0.5 at 1.55 s gives 0.5.
    assert speed_at(0.8) == pytest.approx(11.40625)
    assert speed_at(1.55) == pytest.approx(14.5)
    assert (run.node("SpeedUp").started, run.node("SpeedUp").finished) == (0.05, 3.05)
    # SpeedUpMore's `>= 19` holds at 3.05 s, as SpeedUp reaches 19 m/s; it starts then, as in
    # esmini (release 1.5: both may overlap as far as the graph tells, so both interrupt and
    # neither waits for the other; before, SpeedUpMore waited for SpeedUp and started at 3.1 s).
    # Sinusoid from 3.05 s at a peak 2 m/s² over 6 m/s: pi/2 * 6 / 2 = 4.712 s, so it ends in
    # the step of 7.762 s (7.80 s); at 5.4 s p = 2.35 / 4.712 and v = 19 + 6 (1 - cos pi p) / 2.
    progress = 2.35 / (math.pi * 1.5)
    assert speed_at(5.4) == pytest.approx(19 + 6 * (1 - math.cos(math.pi * progress)) / 2)
    assert speed_at(5.4) == pytest.approx(21.988, abs=1e-3)
    assert (run.node("SpeedUpMore").started, run.node("SpeedUpMore").finished) == (3.05, 7.8)
    # The steps: `>= 25` holds at 7.80 s and starts the Stop then (its trigger); the lead's
    # `<= 16` holds on its linear change's end, 16 exactly. A node started by a trigger in a
    # step acts from the next (the step's motion came first): 25 m/s is recorded at 7.80 s and
    # 0 at 7.85 s, with no ramp between.
    assert run.node("Halt").started == 7.8
    assert (speed_at(7.8), speed_at(7.85)) == (25.0, 0.0)
    assert run.node("LeadHalts").started == 3.1

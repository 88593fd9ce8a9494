"""Which rules a change makes stale on which objects (`reads.stale`), for an edit and for a
sample, which changes numbers alone."""

from __future__ import annotations

from pathlib import Path

from sceml.model.loading import load_scenario
from sceml.validation.edits import Change, Impact
from sceml.validation.reads import ACTOR_VALUES, ACTORS, SELF, VALUE, Reads, stale

UIS2 = Path(__file__).resolve().parents[2] / "examples" / "uis2-logical.xmi"


def test_a_value_an_actor_holds_reaches_its_nodes_only_for_rules_reading_actor_values() -> None:
    scenario = load_scenario(UIS2).root
    ego = next(a for a in scenario.nodes[0].actors if a.name == "ego")
    accelerate = next(n for n in scenario.nodes if n.name == "Accelerate_1")
    drive = next(n for n in scenario.nodes if n.name == "DriveDistance_1")  # the car's
    assert accelerate.referenceActor is ego and drive.referenceActor is not ego
    impact = Impact([Change(ego.initialSpeed, "value")], alone=False)
    names = Reads(VALUE)  # e.g. SCEML-P007: the node's actor names its parameter paths
    limits = Reads(VALUE | ACTOR_VALUES)  # e.g. SCEML-L001: the actor's own limits judge speeds
    # An edit may have renamed ego: both rules on ego's node are stale, none on the car's.
    assert stale(names, accelerate, impact) and stale(limits, accelerate, impact)
    assert not stale(names, drive, impact) and not stale(limits, drive, impact)
    # A sample set a number: ego's name, kind and declaration are as they were.
    assert not stale(names, accelerate, impact, values_only=True)
    assert stale(limits, accelerate, impact, values_only=True)
    assert not stale(limits, drive, impact, values_only=True)
    # On the value and what holds it, every rule reading them is stale either way; one reading
    # only actor names is not, after a sample.
    assert stale(Reads(SELF), ego, impact, values_only=True)
    assert stale(Reads(SELF), ego.initialSpeed, impact, values_only=True)
    assert stale(Reads(ACTORS), ego.initialSpeed, impact)
    assert not stale(Reads(ACTORS), ego.initialSpeed, impact, values_only=True)
    assert stale(None, drive, impact, values_only=True)  # a rule declaring nothing: everywhere

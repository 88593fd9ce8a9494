"""A sampled actor's own top speed (release 1.4's Actor.maxSpeed) moves the limit that the
actor's speeds are held to: per sample, a speed above the sample's own limit is skipped, wherever
that speed is (on the actor or on a node it performs), and no other sample is."""

from __future__ import annotations

from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.diagnostics import Severity
from sceml.levels.space import parameter_space
from sceml.levels.to_folder import (
    SampleRequest,
    blocking_problems,
    load_logical,
    plan_sampling,
    sample_to_folder,
)
from sceml.model.loading import load, load_scenario
from sceml.model.saving import save
from sceml.validation import validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
UIS2 = EXAMPLES / "uis2-logical.xmi"
ALLOW = (EXAMPLES, EXAMPLES.parent / "maps")
#: A car's own limit counts where it is above the kind's, 70 m/s (sceml.validation.limits).
CAR_LIMIT = 70.0


def _logical(folder: Path, where: str) -> Path:
    """UIS2 with ego's own maxSpeed sampled over [60, 100] m/s and one speed of 75 m/s that it
    holds (on the actor) or that a node it performs holds."""
    document = load_scenario(UIS2)
    ego = next(a for a in document.root.nodes[0].actors if a.name == "ego")
    ego.maxSpeed = scm.Range(min=60.0, max=100.0)
    if where == "actor":
        ego.initialSpeed = scm.Value(value=75.0)
    else:
        accelerate = next(n for n in document.root.nodes if n.name == "Accelerate_1")
        assert accelerate.referenceActor is ego
        accelerate.targetSpeed = scm.Value(value=75.0)
    path = folder / "own-logical.xmi"
    save(document.root, path, origin=UIS2)
    return path


@pytest.mark.parametrize("where", ["actor", "node"])
def test_a_speed_above_the_samples_own_limit_is_skipped(tmp_path: Path, where: str) -> None:
    logical = _logical(tmp_path, where)
    document = load_logical(logical, ALLOW)
    assert blocking_problems(document) == []  # 75 m/s is within the range's top, 100
    out = tmp_path / "out"
    request = SampleRequest(logical, "random", 40, 3, out, "xmi", allow=ALLOW)
    outcome = sample_to_folder(plan_sampling(document, request), executor="local")
    column = parameter_space(document.root).paths.index("ego.maxSpeed")
    expected = {r.index: r.values[column] >= 75.0 for r in outcome.records}
    # Worked out by hand: above 70 the own limit counts, and 75 m/s needs one of at least 75.
    assert {r.index: r.status == "written" for r in outcome.records} == expected
    assert 5 < sum(expected.values()) < 35  # both outcomes are drawn
    for record in outcome.records:
        if record.status == "skipped":
            # The reason names the speed that broke the sample's own limit.
            held = "ego.initialSpeed" if where == "actor" else "Accelerate_1.targetSpeed"
            assert record.reason == f"validation: SCEML-L001 at {held}", record.reason
            continue
        (name,) = record.files
        written = load(out / name, allow=list(ALLOW))
        errors = [
            d for d in validate(written.root, document=written) if d.severity >= Severity.ERROR
        ]
        assert errors == [], [str(e) for e in errors]

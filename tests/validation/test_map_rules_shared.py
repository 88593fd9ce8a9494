"""What the map rules share through the validation context's memo (issue 31) changes no finding:
each map rule run alone, in a context of its own with nothing computed before it, reports what
it reports beside every other rule in one context; and the lanes a map keeps are those it would
compute again."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from validation.test_edge_lanes import _with_edge_lane

from sceml.diagnostics import Diagnostic
from sceml.errors import LoadError
from sceml.maps import PositionError, RoadMap, load_map
from sceml.model.build import ScenarioBuilder, lane
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.validation.engine import validate
from sceml.validation.registry import REGISTRY

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "benchmarks"))
from scale_scenarios import write  # noqa: E402
from seeded_faults import write_faulty  # noqa: E402

#: The map rules that share grounds (R004, R009), a departure (R006, R007) or kept lanes.
SHARING = ("SCEML-R003", "SCEML-R004", "SCEML-R005", "SCEML-R006", "SCEML-R007", "SCEML-R009")
ON_THE_MAP = sorted(
    path
    for path in [*(REPO / "examples").rglob("*.xmi"), *(REPO / "tests").rglob("*.xmi")]
    if "intersection.xodr" in path.read_text(errors="replace")
)


def _said(found: list[Diagnostic]) -> list[tuple[object, ...]]:
    return [(d.severity, d.code, d.message, d.fragment, d.path, d.line) for d in found]


def _alone_and_together(path: Path) -> tuple[list[tuple[object, ...]], list[tuple[object, ...]]]:
    document = load(path)
    together = validate(document.root, document=document)
    alone = []
    for code in SHARING:
        alone += validate(document.root, document=document, registry=REGISTRY.subset(codes=[code]))
    key = sorted(_said([d for d in together if d.code in SHARING]), key=repr)
    return key, sorted(_said(alone), key=repr)


@pytest.fixture(scope="module")
def generated(tmp_path_factory: pytest.TempPathFactory) -> list[Path]:
    """A valid scale scenario and the same with faults seeded throughout."""
    folder = tmp_path_factory.mktemp("scale")
    return [write(700, folder), write_faulty(700, folder)]


def test_the_generated_scenarios_get_the_same_map_findings(generated: list[Path]) -> None:
    valid, faulty = generated
    assert _alone_and_together(valid) == ([], [])
    together, alone = _alone_and_together(faulty)
    assert together == alone
    # The seeded faults must reach the rules that share: destinations off the map.
    assert {said[1] for said in together} >= {"SCEML-R004"}


def test_the_corpus_on_the_map_gets_the_same_map_findings() -> None:
    codes: set[object] = set()
    checked = 0
    for path in ON_THE_MAP:
        try:
            together, alone = _alone_and_together(path)
        except LoadError:
            continue  # the hostile corpus: files that are not read at all
        checked += 1
        assert together == alone, path
        codes |= {said[1] for said in together}
    assert checked > 50
    assert codes >= {"SCEML-R004", "SCEML-R006", "SCEML-R007"}


def test_a_car_on_a_shoulder_gets_the_same_findings(tmp_path: Path) -> None:
    """R009 and R004 read the same grounds: a car parked on a shoulder, a truck on a sidewalk."""
    _with_edge_lane(tmp_path, "shoulder")
    b = ScenarioBuilder("Edge", map="edge.xodr", level="concrete")
    b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0))
    parked = b.actor("Car", "parked", start=lane(1, -2, 30.0))
    truck = b.actor("Truck", "truck", start=lane(2, 2, 20.0))
    b.chain(b.root, b.add("KeepVelocity", parked, duration=1.0), b.end)
    b.chain(b.root, b.add("KeepVelocity", truck, duration=1.0), b.end)
    save(b.scenario, tmp_path / "edge.xmi")
    (tmp_path / ".sceml-root").touch()
    together, alone = _alone_and_together(tmp_path / "edge.xmi")
    assert together == alone
    assert {said[1] for said in together} == {"SCEML-R004", "SCEML-R009"}


@pytest.fixture(scope="module")
def intersection() -> RoadMap:
    return load_map(REPO / "maps" / "intersection.xodr")


@settings(max_examples=300, deadline=None)
@given(
    road=st.sampled_from(["1", "2", "3", "4", "5", "9", "100", "x"]),
    lane=st.integers(-4, 4),
    s=st.one_of(
        st.floats(-5.0, 120.0, allow_nan=False),
        st.sampled_from([0.0, -0.0, 20.0, math.nan, math.inf]),
    ),
)
def test_a_kept_lane_is_the_lane_found_again(
    intersection: RoadMap, road: str, lane: int, s: float
) -> None:
    """`band` keeps its answers; asked twice, it answers as the search does, errors included."""
    for _ in range(2):
        try:
            kept = intersection.band(road, lane, s)
        except PositionError as error:
            with pytest.raises(PositionError) as again:
                intersection._band(road, lane, s)
            assert str(again.value) == str(error)
        else:
            assert kept == intersection._band(road, lane, s)

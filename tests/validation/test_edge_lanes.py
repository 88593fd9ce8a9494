"""A vehicle on a shoulder, stop or parking lane: it may stand there (a warning asks whether it
is meant), but a sidewalk stays an error (SCEML-R004, R009)."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.model.build import ScenarioBuilder, lane
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.validation import validate

MAP = Path(__file__).resolve().parents[2] / "maps" / "intersection.xodr"


def _with_edge_lane(folder: Path, lane_type: str) -> Path:
    """Our map with road 1's lane -2 (a sidewalk) turned into `lane_type`."""
    text = MAP.read_text(encoding="utf-8")
    first = text.index('<lane id="-2" type="sidewalk"')  # road 1 comes first in the file
    text = text[:first] + text[first:].replace('type="sidewalk"', f'type="{lane_type}"', 1)
    path = folder / "edge.xodr"
    path.write_text(text, encoding="utf-8")
    return path


def _codes(folder: Path, kind: str) -> dict[str, str]:
    b = ScenarioBuilder("Edge", map="edge.xodr", level="concrete")
    b.actor("Car", "ego", ego=True, start=lane(1, -1, 10.0))
    parked = b.actor(kind, "parked", start=lane(1, -2, 30.0))
    b.chain(b.root, b.add("KeepVelocity", parked, duration=1.0), b.end)
    save(b.scenario, folder / "edge.xmi")
    (folder / ".sceml-root").touch()
    document = load(folder / "edge.xmi")
    return {d.code: d.message for d in validate(document.root, document=document)}


@pytest.mark.parametrize("lane_type", ["shoulder", "stop", "parking"])
def test_a_car_on_an_edge_lane_is_a_warning_not_an_error(tmp_path: Path, lane_type: str) -> None:
    _with_edge_lane(tmp_path, lane_type)
    found = _codes(tmp_path, "Car")
    assert "SCEML-R004" not in found
    assert found["SCEML-R009"] == (
        f"start of actor 'parked': lane -2 of road 1 is a {lane_type} lane, not a driving lane; "
        "a car may stand there, but does it drive there?"
    )


def test_a_car_on_a_sidewalk_is_still_an_error(tmp_path: Path) -> None:
    _with_edge_lane(tmp_path, "sidewalk")
    found = _codes(tmp_path, "Car")
    assert "SCEML-R009" not in found
    assert "is a sidewalk lane; a car needs a driving lane" in found["SCEML-R004"]


def test_a_pedestrian_on_a_shoulder_gets_no_vehicle_warning(tmp_path: Path) -> None:
    _with_edge_lane(tmp_path, "shoulder")
    found = _codes(tmp_path, "Pedestrian")
    assert "SCEML-R009" not in found and "SCEML-R004" not in found

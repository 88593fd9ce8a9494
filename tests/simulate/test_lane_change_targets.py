"""The preview changes lanes to the lane the node names: on tests/importer/files/highway.xodr
(lanes 3.5 m wide, centres at y = -1.75, -5.25 and -8.75 along x), the target cuts into the
ego's lane 0.5 m left of its centre, then into lane -3 at its centre."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from sceml.importer import import_to_file
from sceml.model.loading import load
from sceml.simulate import simulate

FILES = Path(__file__).parents[1] / "importer" / "files"


def test_lane_changes_end_in_the_named_lanes_at_their_offsets(tmp_path: Path) -> None:
    shutil.copy(FILES / "highway.xodr", tmp_path)
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    shutil.copy(FILES / "lane-changes.xosc", tmp_path)
    model = tmp_path / "lane-changes.xmi"
    import_to_file(tmp_path / "lane-changes.xosc", model)
    run = simulate(load(model).root, model)
    cut_in, onward = run.node("CutInEvent"), run.node("OnwardEvent")
    assert cut_in.finished is not None and onward.finished is not None
    target = run.actor_index("Target")

    def y_at(t: float) -> float:
        return float(run.states[target, round(t / 0.05), 1])

    # Between the two changes: in the ego's lane (-5.25), 0.5 m to the left.
    assert y_at(cut_in.finished + 0.05) == pytest.approx(-4.75, abs=1e-6)
    # After the second: at the centre of lane -3 (its targetLaneOffset is 0).
    assert y_at(onward.finished + 0.05) == pytest.approx(-8.75, abs=1e-6)
    assert "CutInEvent: a cubic lane change is previewed as sinusoidal" in run.notes

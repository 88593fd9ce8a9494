"""esmini's recordings of UIS1 and UIS2 (esmini 3.6.0 `--csv_logger`, 0.1 s steps, from the
exports of the concrete examples) extract to the examples' maneuvers and waits, replay closely
in the preview, and the result renders and exports."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import REPO

from sceml import io
from sceml.cli import cli
from sceml.editor.session import EditorSession
from sceml.extract import extract, read_recording
from sceml.extract.closedloop import allowed_error
from sceml.maps import load_map

DATA = Path(__file__).resolve().parent / "data"

EXPECTED = {
    "uis1": (
        {"ego": ["Accelerate", "TurnRight"], "bike": ["Accelerate", "Cross"]},
        {("bike", "Accelerate_2", "InVehicleRadius", "bike", "ego")},
    ),
    "uis2": (
        {
            "ego": ["Accelerate", "TurnLeft"],
            # The car's speed jumps (the example's DriveDistance): a step, as recorded.
            "car": ["DriveDistance"],
            "pedestrian": ["Accelerate", "Cross"],
        },
        {
            ("car", "DriveDistance_1", "InLocationRadius", "ego", None),
            ("pedestrian", "Accelerate_2", "InVehicleRadius", "pedestrian", "car"),
        },
    ),
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_an_esmini_recording_extracts_to_the_examples_graph(name: str) -> None:
    found = extract(
        read_recording(DATA / f"{name}-esmini.csv"),
        load_map(REPO / "maps" / "intersection.xodr"),
        map_reference="../maps/intersection.xodr",
    )
    maneuvers, waits = EXPECTED[name]
    assert {a.name: [e.kind for e in a.maneuvers] for a in found.actors} == maneuvers
    assert {
        (i.actor, i.maneuver, i.explanation.kind, i.explanation.actor, i.explanation.target)
        for i in found.inferred
    } == waits
    assert found.replay is not None
    for fit in found.replay.actors:
        assert fit.largest < allowed_error(found, fit.name), fit


def test_the_extracted_scenario_renders_exports_and_opens_in_the_editor(tmp_path: Path) -> None:
    (tmp_path / "maps").mkdir()
    shutil.copyfile(REPO / "maps" / "intersection.xodr", tmp_path / "maps" / "intersection.xodr")
    # The scenario beside the map's folder, so that the map is among the files it may read.
    found = extract(
        read_recording(DATA / "uis2-esmini.csv"),
        load_map(REPO / "maps" / "intersection.xodr"),
        map_reference="maps/intersection.xodr",
    )
    saved = io.save(found.scenario, tmp_path / "uis2.xmi")
    runner = CliRunner()
    drawn = runner.invoke(cli, ["render", str(saved), "-o", str(tmp_path / "uis2.svg")])
    assert drawn.exit_code == 0, drawn.output
    assert "InVehicleRadius" in (tmp_path / "uis2.svg").read_text(encoding="utf-8")
    for version in ("1.0", "1.3"):
        target = tmp_path / f"uis2-{version}.xosc"
        exported = runner.invoke(
            cli, ["export", str(saved), "-o", str(target), "--osc-version", version]
        )
        assert exported.exit_code == 0, exported.output
        assert "RelativeDistanceCondition" in target.read_text(encoding="utf-8")
    session = EditorSession()
    session.open(saved)
    view = session.view()
    # Root, end, 5 maneuvers, 2 inferred conditions and 2 arrival checks; no error on any.
    assert len(view["nodes"]) == 11
    assert not [d for d in session.diagnostics() if d.severity.name == "ERROR"]

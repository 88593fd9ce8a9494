"""`sceml extract` through click's CliRunner: the scenario written, the report, usage errors."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from click.testing import CliRunner
from conftest import EXAMPLES, REPO

from sceml.cli import cli
from sceml.model.loading import load_scenario
from sceml.simulate import simulate
from sceml.simulate.outputs import trajectories_csv

DATA = Path(__file__).resolve().parent / "data"


def uis1_csv(tmp_path: Path) -> Path:
    """The preview's recording of UIS1, as `sceml simulate --csv` writes it."""
    path = EXAMPLES / "uis1-concrete.xmi"
    run = simulate(load_scenario(path).root, path)
    recording = tmp_path / "uis1.csv"
    recording.write_text(trajectories_csv(run), encoding="utf-8")
    return recording


def map_copy(tmp_path: Path) -> Path:
    target = tmp_path / "maps" / "intersection.xodr"
    target.parent.mkdir()
    shutil.copyfile(REPO / "maps" / "intersection.xodr", target)
    return target


def test_extract_writes_a_clean_scenario_and_reports_why_the_bike_started(tmp_path: Path) -> None:
    out = tmp_path / "scenarios" / "uis1-extracted.xmi"
    arguments = [
        "extract",
        str(uis1_csv(tmp_path)),
        "-o",
        str(out),
        "--map",
        str(map_copy(tmp_path)),
    ]
    result = CliRunner().invoke(cli, [*arguments, "--actor", "bike=Bicycle", "--report"])
    assert result.exit_code == 0, result.output
    assert "InVehicleRadius(bike and ego; radius=12)" in result.output
    assert "inferred conditions; replay within" in result.output
    root = load_scenario(out).root
    assert root.nodes[0].map == "../maps/intersection.xodr"
    kinds = {str(a.name): a.eClass.name for a in root.nodes[0].actors}
    assert kinds == {"ego": "Car", "bike": "Bicycle"}


def test_the_json_report_lists_maneuvers_conditions_and_the_replay(tmp_path: Path) -> None:
    out = tmp_path / "x.xmi"
    arguments = [
        "extract",
        str(DATA / "uis2-esmini.csv"),
        "-o",
        str(out),
        "--map",
        str(map_copy(tmp_path)),
    ]
    result = CliRunner().invoke(cli, [*arguments, "--report", "--format", "json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["recording"]["format"] == "esmini"
    by_actor = {a["name"]: [m["kind"] for m in a["maneuvers"]] for a in report["actors"]}
    assert by_actor == {
        "ego": ["Accelerate", "TurnLeft"],
        "car": ["DriveDistance"],  # its speed jumps, as the original's DriveDistance
        "pedestrian": ["Accelerate", "Cross"],
    }
    waits = {(c["actor"], c["kind"], c["reference"], c["target"]) for c in report["conditions"]}
    assert waits == {
        ("car", "InLocationRadius", "ego", None),
        ("pedestrian", "InVehicleRadius", "pedestrian", "car"),
    }
    assert report["replay"]["actors"][0]["name"] == "ego"
    assert any("above the Car limit" in note for note in report["notes"])


def test_each_threshold_option_sets_its_threshold(tmp_path: Path, monkeypatch) -> None:
    import sceml.extract as extraction
    from sceml.extract import Thresholds

    seen: list[Thresholds] = []

    def stop_after_reading_the_thresholds(*args: object, thresholds: Thresholds, **kw: object):
        seen.append(thresholds)
        raise SystemExit(3)

    monkeypatch.setattr(extraction, "extract", stop_after_reading_the_thresholds)
    options = {
        "--smoothing": ("smoothing_window", 1.5),
        "--accel-threshold": ("accel_threshold", 0.7),
        "--turn-angle": ("turn_angle", 0.6),
        "--vehicle-radius": ("vehicle_radius", 15.0),
        "--tolerance": ("arrival_tolerance", 3.0),
        "--sharp-bend": ("sharp_bend", 0.8),
        "--start-rate": ("start_rate", 1.5),
        "--start-significance": ("start_significance", 6.0),
    }
    arguments = ["extract", str(DATA / "uis1-esmini.csv"), "-o", str(tmp_path / "x.xmi")]
    arguments += ["--map", str(map_copy(tmp_path))]
    for option, (_, value) in options.items():
        arguments += [option, str(value)]
    result = CliRunner().invoke(cli, arguments)
    assert result.exit_code == 3, result.output
    assert len(seen) == 1
    for field, value in options.values():
        assert getattr(seen[0], field) == value != getattr(Thresholds(), field)


def test_a_broken_recording_is_a_usage_error_naming_its_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("time,actor,x,y\n0,ego,1,2\n0.1,ego,one,2\n", encoding="utf-8")
    out = tmp_path / "x.xmi"
    result = CliRunner().invoke(
        cli, ["extract", str(bad), "-o", str(out), "--map", str(map_copy(tmp_path))]
    )
    assert result.exit_code == 2
    assert f"{bad}:3: x is not a number" in result.output
    assert not out.exists()


def test_an_actor_option_that_names_no_kind_is_refused(tmp_path: Path) -> None:
    arguments = ["extract", str(DATA / "uis1-esmini.csv"), "-o", str(tmp_path / "x.xmi")]
    result = CliRunner().invoke(
        cli, [*arguments, "--map", str(map_copy(tmp_path)), "--actor", "bike=Unicycle"]
    )
    assert result.exit_code == 2 and "unknown actor kind 'Unicycle'" in result.output
    result = CliRunner().invoke(
        cli,
        [
            *arguments,
            "--map",
            str(tmp_path / "maps" / "intersection.xodr"),
            "--actor",
            "nobody=Car",
        ],
    )
    assert result.exit_code == 2 and "no actor nobody in the recording" in result.output

"""Reading recordings: SceML's preview CSV, esmini's --csv_logger, OSC-Generator's CSV, and the
errors for files that cannot be used (file and line named)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from sceml.errors import LoadError
from sceml.extract import read_recording

DATA = Path(__file__).resolve().parent / "data"


def write(tmp_path: Path, text: str, name: str = "run.csv") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_the_preview_csv_gives_one_track_per_actor_and_the_ego_by_name(tmp_path: Path) -> None:
    path = write(
        tmp_path,
        "time,actor,x,y,heading,speed\n"
        "0.000,ego,1.0,2.0,0.5,3.0\n0.000,bike,5.0,6.0,1.0,0.0\n"
        "0.050,ego,1.1,2.0,0.5,3.0\n0.050,bike,5.0,6.0,1.0,0.0\n",
    )
    recording = read_recording(path)
    assert recording.format == "sceml"
    ego, bike = recording.tracks
    assert (ego.name, ego.ego, bike.ego) == ("ego", True, False)
    assert list(ego.x) == [1.0, 1.1] and list(bike.y) == [6.0, 6.0]
    assert list(ego.times) == [0.0, 0.05] and ego.heading is not None


def test_esmini_csv_logger_output_gives_names_boxes_and_positions() -> None:
    # Recorded with esmini 3.6.0 from the export of examples/uis1-concrete.xmi (0.1 s steps).
    recording = read_recording(DATA / "uis1-esmini.csv")
    assert recording.format == "esmini"
    ego, bike = recording.tracks
    assert (ego.name, bike.name) == ("ego", "bike") and ego.ego and not bike.ego
    assert (ego.length, ego.width) == (4.5, 1.8) and (bike.length, bike.width) == (1.8, 0.6)
    # The start positions of the scenario (lane 1 of road 1 at s = 30, and the bike lane).
    assert (ego.x[0], ego.y[0]) == (1.75, -39.0) and (bike.x[0], bike.y[0]) == (4.5, -24.0)
    assert ego.times[1] == pytest.approx(0.1)


def test_osc_generator_csv_places_objects_relative_to_the_ego(tmp_path: Path) -> None:
    # Ego heading 0° = north (OSC-Generator: degrees clockwise from north), so an object 10 m
    # ahead and 2 m to the left is at x = -2, y = 10 in the map's frame (x east, y north).
    # Class 3 is a pedestrian in OSC-Generator 0.2.0 (man_helpers.label_maneuvers).
    ten_metres = math.degrees(10.0 / 6378137.0)
    path = write(
        tmp_path,
        "timestamp,lat,long,heading,speed,pos_x_1,pos_y_1,speed_x_1,speed_y_1,class_1\n"
        "0.0,0.0,0.0,0.0,10.0,10.0,2.0,0.0,0.0,3\n"
        f"0.1,{ten_metres!r},0.0,90.0,10.0,,,,,\n",
    )
    recording = read_recording(path)
    ego, walker = recording.tracks
    assert (ego.x[0], ego.y[0]) == (0.0, 0.0)
    assert ego.y[1] == pytest.approx(10.0, abs=1e-6) and ego.x[1] == pytest.approx(0.0)
    assert ego.heading is not None and ego.heading[0] == pytest.approx(math.pi / 2)
    assert ego.heading[1] == pytest.approx(0.0)  # 90° = east
    assert (walker.x[0], walker.y[0]) == (pytest.approx(-2.0), pytest.approx(10.0))
    assert len(walker.times) == 1 and walker.kind == "Pedestrian"


@pytest.mark.parametrize(
    ("text", "line", "words"),
    [
        ("time,actor,x,y\n0,ego,1,2\n0.1,ego,abc,2\n", 3, "x is not a number"),
        ("time,actor,x,y\n0.1,ego,1,2\n0.0,ego,1,2\n", 3, "does not follow"),
        ("time,actor,x,y\n0,ego,1,inf\n", 2, "not finite"),
        ("time,actor,x\n0,ego,1\n", 1, "missing column(s) y"),
        ("when,who\n1,2\n", 1, "cannot tell the recording's format"),
    ],
)
def test_a_recording_that_cannot_be_used_is_refused_with_its_line(
    tmp_path: Path, text: str, line: int, words: str
) -> None:
    path = write(tmp_path, text)
    with pytest.raises(LoadError) as caught:
        read_recording(path)
    assert caught.value.line == line and caught.value.file == str(path)
    assert words in caught.value.message


def test_a_missing_file_is_a_load_error(tmp_path: Path) -> None:
    with pytest.raises(LoadError, match="cannot read"):
        read_recording(tmp_path / "nothing.csv")

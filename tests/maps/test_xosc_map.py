"""check-xosc checks an OpenSCENARIO file's positions against the map its LogicFile names."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.xosc.check import check_file
from sceml.xosc.mapcheck import MAP_CODE, MAP_SKIPPED_CODE

REPO = Path(__file__).resolve().parents[2]
GOLDEN = REPO / "tests" / "export" / "golden"
MAP = REPO / "maps" / "intersection.xodr"


def changed_copy(tmp_path: Path, old: str, new: str, name: str = "uis1-1.3-generic.xosc") -> Path:
    """A golden export with one change, in a folder whose LogicFile still reaches the map."""
    text = (GOLDEN / name).read_text(encoding="utf-8")
    assert old in text, old
    folder = tmp_path / "a" / "b" / "c"  # the golden LogicFile is ../../../maps/intersection.xodr
    folder.mkdir(parents=True)
    (tmp_path / "maps").mkdir()
    # The map lies above the file's folder: the marker makes tmp_path the project root, from
    # which the reading rule lets check-xosc read it.
    (tmp_path / ".sceml-root").touch()
    (tmp_path / "maps" / "intersection.xodr").write_bytes(MAP.read_bytes())
    target = folder / name
    target.write_text(text.replace(old, new, 1), encoding="utf-8")
    return target


def codes(path: Path) -> list[tuple[str, int | None, str]]:
    report = check_file(path, quality=False)
    assert report.unreadable is None, report.unreadable
    return [(d.code, d.line, d.message) for d in report.diagnostics]


# The carla goldens are exported with --town Town03: see test_a_town_is_not_checked_and_says_so.
@pytest.mark.parametrize("golden", sorted(p.name for p in GOLDEN.glob("*-generic.xosc")))
def test_every_golden_export_lies_on_its_map(golden: str) -> None:
    assert codes(GOLDEN / golden) == []


def test_an_unknown_road_is_an_error_at_its_line(tmp_path: Path) -> None:
    path = changed_copy(tmp_path, 'roadId="3"', 'roadId="99"')
    found = codes(path)
    assert len(found) == 1, found
    code, line, message = found[0]
    assert code == MAP_CODE and "no road '99'" in message
    lines = path.read_text(encoding="utf-8").splitlines()
    assert line is not None and 'roadId="99"' in lines[line - 1]


def test_an_offset_outside_the_lane_and_an_s_beyond_the_road(tmp_path: Path) -> None:
    path = changed_copy(tmp_path, 's="30.0" offset="0.0"', 's="130.0" offset="0.0"')
    assert [m for _, _, m in codes(path)] == [
        "lane position: s=130 m is outside road '3', which is 100 m long"
    ]


def test_a_world_position_off_every_lane(tmp_path: Path) -> None:
    path = changed_copy(tmp_path, 'x="34.0" y="-1.75"', 'x="34.0" y="-30.0"')
    found = codes(path)
    assert [(c, m) for c, _, m in found] == [
        (MAP_CODE, "world position (34, -30) is on no lane of the map")
    ]


def test_a_town_is_not_checked_and_says_so(tmp_path: Path) -> None:
    found = codes(GOLDEN / "uis1-1.0-carla.xosc")
    assert [(c, m) for c, _, m in found] == [
        (
            MAP_SKIPPED_CODE,
            "positions are not checked against a map: LogicFile 'Town03' is a simulator town",
        )
    ]


def test_a_missing_map_is_an_error(tmp_path: Path) -> None:
    path = changed_copy(tmp_path, "maps/intersection.xodr", "maps/missing.xodr")
    ((code, _, message),) = codes(path)
    assert code == MAP_CODE and "does not exist" in message


def test_a_parameter_reference_is_resolved(tmp_path: Path) -> None:
    path = changed_copy(
        tmp_path,
        "<ParameterDeclarations/>",
        '<ParameterDeclarations><ParameterDeclaration name="S" parameterType="double" value="130"/></ParameterDeclarations>',
    )
    text = path.read_text(encoding="utf-8").replace(
        's="30.0" offset="0.0"', 's="$S" offset="0.0"', 1
    )
    path.write_text(text, encoding="utf-8")
    assert [m for _, _, m in codes(path)] == [
        "lane position: s=130 m is outside road '3', which is 100 m long"
    ]

"""`sceml import` on the command line, the report, and the imported file in validate and the editor."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

from click.testing import CliRunner

from sceml.cli import cli
from sceml.editor import EditorSession, SessionOptions
from sceml.editor.palette import node_groups
from sceml.importer import import_file

FILES = Path(__file__).resolve().parent / "files"


def test_import_writes_the_scenario_and_prints_the_report(tmp_path: Path) -> None:
    output = tmp_path / "cut-in.xmi"
    result = CliRunner().invoke(
        cli, ["import", str(FILES / "cut-in.xosc"), "-o", str(output), "--report"]
    )
    assert result.exit_code == 0, result.output
    # The change into the ego's lane is exact now (LaneChange's target actor), not a guess,
    # and so is its 3 s (release 1.5's duration, no longer metres at a guessed speed).
    # 14 mapped: the wait of a step a `SimulationTime > 0` stands for is one of them, and so
    # are the vehicle catalog entries Ego and OverTaker were read from (release 1.5).
    assert "OpenSCENARIO 1.1; 14 mapped, 1 opaque, 1 guessed, 0 not represented" in result.output
    assert (
        "line 99: CutInStartCondition: <Condition TimeHeadwayCondition entityRef=Target "
        "value=0.4 freespace=false alongRoute=true rule=greaterThan> kept verbatim" in result.output
    )
    assert "catalog entries used: VehicleCatalog/car_white" in result.output
    assert f"{output}: 8 nodes from" in result.output
    checked = CliRunner().invoke(cli, ["validate", str(output), "--allow", str(FILES)])
    assert checked.exit_code == 0, checked.output


def test_map_option_replaces_the_logic_file(tmp_path: Path) -> None:
    shutil.copy(FILES / "cut-in.xosc", tmp_path / "cut-in.xosc")
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    output = tmp_path / "out" / "cut-in.xmi"
    (tmp_path / "out").mkdir()
    result = CliRunner().invoke(
        cli,
        [
            "import",
            str(tmp_path / "cut-in.xosc"),
            "-o",
            str(output),
            "--map",
            str(FILES / "highway.xodr"),
        ],
    )
    assert result.exit_code == 0, result.output
    text = output.read_text()
    # The map is written relative to the output, and found from there.
    relative = Path(os.path.relpath(FILES / "highway.xodr", output.parent)).as_posix()
    assert f'map="{relative}"' in text


def test_without_a_readable_map_the_report_says_how_turns_are_read(tmp_path: Path) -> None:
    shutil.copy(FILES / "cut-in.xosc", tmp_path / "cut-in.xosc")
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    imported = import_file(tmp_path / "cut-in.xosc")
    guessed = [entry.message for entry in imported.report.section("guessed")]
    assert any("cannot be read" in message and "headings" in message for message in guessed)


def test_opaque_nodes_open_in_the_editor_and_are_not_in_the_palette(tmp_path: Path) -> None:
    # Copied beside the output with its map and catalogs: the editor reads the map it names
    # from the model's own folder.
    shutil.copy(FILES / "highway.xodr", tmp_path / "highway.xodr")
    shutil.copytree(FILES / "catalogs", tmp_path / "catalogs")
    # Its lane offset (which SceML maps) becomes a visibility change, which SceML has no kind for.
    text = (FILES / "alks-lane-keeping.xosc").read_text()
    start, end = text.index("<LateralAction>"), text.index("</LateralAction>")
    hidden = '<VisibilityAction graphics="false" traffic="true" sensors="true"/>'
    (tmp_path / "alks-lane-keeping.xosc").write_text(
        text[:start] + hidden + text[end + len("</LateralAction>") :]
    )
    output = tmp_path / "alks.xmi"
    assert (
        CliRunner()
        .invoke(cli, ["import", str(tmp_path / "alks-lane-keeping.xosc"), "-o", str(output)])
        .exit_code
        == 0
    )
    session = EditorSession(SessionOptions())
    session.open(output)
    view = session.view()
    opaque = [node for node in view["nodes"] if node["kind"] == "OpaqueAction"]
    # The VisibilityAction; its TraveledDistanceCondition maps to TraveledDistance. The box
    # says what it is: its type and key values, as the file has them, and where it came from.
    assert [node["look"] for node in opaque] == ["opaque"]
    assert opaque[0]["lines"] == [
        "SideVehicle",
        "Action VisibilityAction",
        "graphics=false traffic=true sensors=true",
        "OpenSCENARIO 1.3, line 81",
    ]
    assert view["style"]["looks"]["opaque"]["dashed"] is True
    assert view["summary"]["errors"] == 0
    offered = {item["kind"] for group in node_groups() for item in group["items"]}
    assert "OpaqueAction" not in offered
    assert "Accelerate" in offered
    session.save()
    assert "OpaqueAction" in output.read_text()


def test_exporting_an_opaque_node_to_another_version_warns(tmp_path: Path) -> None:
    output = tmp_path / "cut-in.xmi"
    CliRunner().invoke(cli, ["import", str(FILES / "cut-in.xosc"), "-o", str(output)])
    result = CliRunner().invoke(cli, ["validate", str(output), "--osc-version", "1.3"])
    assert "warning[SCEML-E007]" in result.output
    assert "read from OpenSCENARIO 1.1" in result.output

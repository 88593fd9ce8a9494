"""`sceml module list|show|extract` and `sceml flatten`: output, files and exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli.flatten import flatten
from sceml.cli.module import module
from sceml.model.loading import load
from sceml.model.saving import save
from sceml.validation import validate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
LIBRARY = EXAMPLES / "library" / "sceml-library.xmi"


def run(command, *args: object):
    return CliRunner().invoke(command, [str(a) for a in args])


def test_list_shows_each_definition() -> None:
    result = run(module, "list", LIBRARY)
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0] == f"{LIBRARY}: 5 modules"
    assert "  roles: crosser (TwoWheeler|Pedestrian), trigger (FourWheeler)" in lines
    assert "  size: 4 nodes, 5 flows, 0 uses, depth 1" in lines
    assert "  size: 4 nodes, 6 flows, 1 use, depth 3" in lines
    assert "destinationX [m] (no default)" in result.output
    assert "triggerRadius = 10 m" in result.output


def test_list_as_json() -> None:
    result = run(module, "list", LIBRARY, "--json")
    assert result.exit_code == 0
    data = json.loads(result.output)
    assert [d["name"] for d in data][-1] == "Overtaking"
    assert data[-1]["size"]["depth"] == 3


def test_show_prints_nodes_flows_and_uses() -> None:
    result = run(module, "show", LIBRARY, "PassVehicle")
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert lines[0] == f"PassVehicle ({LIBRARY})"
    nodes = lines[lines.index("nodes (in flow order):") + 1 : lines.index("flows:")]
    assert [line.split()[0] for line in nodes] == [
        "In",
        "ChangeLaneLeft_1",
        "Accelerate_1",
        "ChangeLaneRight_1",
        "Out",
    ]
    assert "[overtaker]  targetSpeed=$passingSpeed" in nodes[2]
    assert "  ChangeLaneRight_1: ChangeLaneRight [driver=overtaker]" in lines
    assert "    holdTime = $passingTime" in lines


def test_show_unknown_name_exits_2_listing_the_names() -> None:
    result = run(module, "show", LIBRARY, "Nope")
    assert result.exit_code == 2
    assert "no module 'Nope' (it has: CrossingManeuver, ChangeLaneLeft," in result.output
    assert "Traceback" not in result.output


def test_list_of_a_scenario_is_a_usage_error() -> None:
    result = run(module, "list", EXAMPLES / "uis1-concrete.xmi")
    assert result.exit_code == 2
    assert "expected a module library, found a scenario" in result.output


def test_flatten_writes_a_file_without_uses(tmp_path: Path) -> None:
    out = tmp_path / "flat.xmi"
    result = run(flatten, EXAMPLES / "overtaking-concrete.xmi", "-o", out)
    assert result.exit_code == 0, result.output
    assert result.output.startswith(f"{out}: 11 nodes; 4 module uses expanded (Overtaking_1, ")
    names = {n.name for n in load(out).root.nodes}
    assert "Overtaking_1.PassVehicle_1.ChangeLaneLeft_1.LaneChange_1" in names


def test_flatten_into_another_folder_keeps_the_map_reachable(tmp_path: Path) -> None:
    out = tmp_path / "deeper" / "still" / "flat.xmi"
    out.parent.mkdir(parents=True)
    result = run(flatten, EXAMPLES / "uis2-concrete.xmi", "-o", out)
    assert result.exit_code == 0, result.output
    root = next(n for n in load(out).root.nodes if n.eClass.name == "RootNode")
    assert (out.parent / root.map).resolve() == (EXAMPLES.parent / "maps/intersection.xodr")
    document = load(out, allow=[EXAMPLES.parent / "maps"])  # reachable, and allowed
    found = validate(document.root, document=document)
    assert not [d for d in found if d.code.startswith("SCEML-R")], found


def test_flatten_of_a_broken_reference_exits_1_without_writing(
    examples_copy: Path, tmp_path: Path
) -> None:
    path = examples_copy / "uis2-concrete.xmi"
    path.write_text(path.read_text().replace("sceml-library.xmi", "gone.xmi"))
    out = tmp_path / "flat.xmi"
    result = run(flatten, path, "-o", out)
    assert result.exit_code == 1
    assert f"{path}:" in result.output
    assert f"{examples_copy / 'library' / 'gone.xmi'}: no such file" in result.output
    assert not out.exists()


def test_flatten_library_outside_the_folder_needs_allow(
    examples_copy: Path, tmp_path: Path
) -> None:
    (examples_copy.parent / ".sceml-root").unlink()  # no project: only the file's folder
    scenario = examples_copy / "uis2-concrete.xmi"
    moved = examples_copy / "sub" / "uis2-concrete.xmi"
    save(load(scenario).root, moved)  # refers to ../library/ now
    denied = run(flatten, moved, "-o", tmp_path / "a.xmi")
    assert denied.exit_code == 1
    assert "reference leaves the allowed folders" in denied.output
    allowed = run(flatten, moved, "-o", tmp_path / "b.xmi", "--allow", examples_copy / "library")
    assert allowed.exit_code == 0, allowed.output


def test_flatten_of_a_missing_file_exits_2(tmp_path: Path) -> None:
    result = run(flatten, tmp_path / "none.xmi", "-o", tmp_path / "out.xmi")
    assert result.exit_code == 2


def test_extract_then_flatten(examples_copy: Path, tmp_path: Path) -> None:
    scenario, library = examples_copy / "uis1-concrete.xmi", examples_copy / "library" / "bikes.xmi"
    result = run(
        module,
        "extract",
        scenario,
        "--nodes",
        "InVehicleRadius_1,Accelerate_2,Cross_1,InLocationRadius_2",
        "--name",
        "BikeCrossing",
        "--into",
        library,
        "--role",
        "bike=crosser:TwoWheeler|Pedestrian",
        "--role",
        "ego=trigger",
    )
    assert result.exit_code == 0, result.output
    assert result.output.splitlines() == [
        f"module 'BikeCrossing' created {library}",
        "  roles: crosser=bike, trigger=ego; parameters: 0",
        f"scenario {scenario}: nodes InVehicleRadius_1, Accelerate_2, Cross_1, "
        "InLocationRadius_2 replaced by BikeCrossing_1",
    ]
    listed = run(module, "list", library)
    assert "  roles: crosser (TwoWheeler|Pedestrian), trigger (Car)" in listed.output
    flat = run(flatten, scenario, "-o", tmp_path / "flat.xmi")
    assert flat.exit_code == 0, flat.output


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--nodes", "Accelerate_1,Accelerate_2", "--name", "M"], "entered from exactly one node"),
        (["--nodes", "Cross_1", "--name", "CrossingManeuver"], "already has a module"),
        (["--nodes", "Cross_1", "--name", "M", "--role", "bike"], "not of the form"),
        (["--nodes", "Cross_1", "--name", "M", "--role", "bike=b:Horse"], "unknown actor kind"),
    ],
)
def test_extract_refusals_exit_2_and_change_nothing(
    examples_copy: Path, args: list[str], message: str
) -> None:
    scenario, library = (
        examples_copy / "uis1-concrete.xmi",
        examples_copy / "library" / "sceml-library.xmi",
    )
    before = (scenario.read_bytes(), library.read_bytes())
    result = run(module, "extract", scenario, "--into", library, *args)
    assert result.exit_code == 2, result.output
    assert message in result.output
    assert "Traceback" not in result.output
    assert (scenario.read_bytes(), library.read_bytes()) == before


@pytest.mark.parametrize(
    ("command", "args"),
    [(module, ["--help"]), (module, ["list", "--help"]), (module, ["show", "--help"]),
     (module, ["extract", "--help"]), (flatten, ["--help"])],
)  # fmt: skip
def test_help_explains_every_option(command, args: list[str]) -> None:
    result = run(command, *args)
    assert result.exit_code == 0
    assert "Usage:" in result.output
    for option in ("--nodes", "--into", "--role", "--parametrize", "--allow", "--output"):
        if f"{option} " in result.output.split("Options:")[-1]:
            line = next(x for x in result.output.splitlines() if option in x)
            assert len(line.split(option)[-1].strip()) > 5, line

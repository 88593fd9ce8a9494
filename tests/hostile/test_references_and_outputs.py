"""References that lead nowhere useful, and output sets that must be whole (docs/security.md):
a hand-edited cross-file referenceActor, a nameless module parameter, a module use of `#//`;
explore's and simulate's outputs all or none; concretize's warning about what its file names."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli
from sceml.errors import SaveError
from sceml.explore import to_folder as explore_to_folder

from .confined import sceml

ACTOR_REFERENCE = 'referenceActor="//@nodes.0/@actors.0"'  # Accelerate_1, line 22 of uis1

#: Every command that meets the reference, and its exit code (docs/security.md).
COMMANDS = {
    "info": (["info"], 1),
    "render": (["render", "-o", "out.svg"], 1),
    "flatten": (["flatten", "-o", "flat.xmi"], 1),
    "export": (["export", "-o", "out.xosc"], 1),
    "simulate": (["simulate", "-o", "run.html"], 2),
}


@pytest.fixture
def outside(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("outside")
    examples = Path(__file__).resolve().parents[2] / "examples"
    (folder / "other.xmi").write_bytes((examples / "uis1-concrete.xmi").read_bytes())
    return folder


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize("where", ["http", "outside", "missing"])
def test_a_cross_file_reference_actor_is_a_located_error(
    examples_copy: Path, outside: Path, command: str, where: str
) -> None:
    href = {
        "http": "http://example.com/x.xmi#//@nodes.0/@actors.0",
        "outside": f"{outside / 'other.xmi'}#//@nodes.0/@actors.0",
        "missing": "missing.xmi#//@nodes.0/@actors.0",
    }[where]
    scenario = examples_copy / "uis1-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    assert ACTOR_REFERENCE in text
    scenario.write_text(text.replace(ACTOR_REFERENCE, f'referenceActor="{href}"', 1))
    out = examples_copy / "out"
    out.mkdir()
    arguments, code = COMMANDS[command]
    run = sceml(arguments[0], scenario, *arguments[1:], cwd=out)
    assert "Traceback" not in run.output
    assert run.code == code, run.output
    said = "uis1-concrete.xmi:22: " if command != "export" else "uis1-concrete.xmi:22: error"
    assert said in run.output and "referenceActor" in run.output
    assert run.opened_under(outside) == []
    assert [p.name for p in out.iterdir()] == []  # nothing written


def nameless_parameter(examples: Path) -> Path:
    library = examples / "library" / "sceml-library.xmi"
    text = library.read_text(encoding="utf-8")
    named = '<parameters xsi:type="scemlmodel:ModuleParameter" name="triggerRadius" unit="m">'
    assert text.splitlines()[35].strip() == named
    library.write_text(text.replace(' name="triggerRadius"', "", 1), encoding="utf-8")
    return library


def test_a_module_parameter_without_a_name_is_a_validation_error(examples_copy: Path) -> None:
    library = nameless_parameter(examples_copy)
    run = sceml("validate", library, cwd=examples_copy)
    assert run.code == 1, run.output
    assert "sceml-library.xmi:36: error[SCEML-M016]" in run.output
    assert "without a name" in run.output


@pytest.mark.parametrize("command", ["flatten", "export", "simulate"])
def test_a_module_parameter_without_a_name_stops_expansion_at_its_line(
    examples_copy: Path, command: str
) -> None:
    nameless_parameter(examples_copy)
    arguments, _ = COMMANDS[command]
    run = sceml(
        arguments[0], examples_copy / "uis2-concrete.xmi", *arguments[1:], cwd=examples_copy
    )
    assert "Traceback" not in run.output
    assert run.code == 1, run.output
    assert "sceml-library.xmi:36: module 'CrossingManeuver' has a parameter without a name" in (
        run.output
    )


@pytest.mark.parametrize("href", ["#//", "#", "#//@nodes.0"])
def test_info_on_a_use_of_an_element_that_is_no_module(examples_copy: Path, href: str) -> None:
    scenario = examples_copy / "uis2-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    old = 'href="library/sceml-library.xmi#CrossingManeuver"'
    assert old in text
    scenario.write_text(text.replace(old, f'href="{href}"', 1), encoding="utf-8")
    run = sceml("info", scenario, cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 1, run.output
    kind = "RootNode" if href == "#//@nodes.0" else "Scenario"
    assert f"uis2-concrete.xmi:64: cannot resolve '{href}': it names a {kind}, not a " in (
        run.output
    )
    assert "(not a module definition" in run.output


# Output sets ---------------------------------------------------------------------------------


def explore(examples: Path, out: Path) -> tuple[int, str]:
    arguments = ["explore", str(examples / "uis1-logical.xmi"), "--budget", "4", "--top", "1"]
    result = CliRunner().invoke(cli, [*arguments, "-o", str(out)])
    return result.exit_code, result.output


def test_explore_writes_all_outputs_or_none(
    examples_copy: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = examples_copy / "explored"
    code, output = explore(examples_copy, out)
    assert code == 0, output
    written = sorted(p.name for p in out.iterdir())
    assert written == [
        "parameter-space.png",
        "runs.csv",
        "uis1_critical_01.xmi",
        "uis1_critical_01.xosc",
    ]
    before = {name: (out / name).read_bytes() for name in written}

    def fails(*args: object) -> None:
        raise SaveError("cannot write: disk full", file="parameter-space.png")

    monkeypatch.setattr(explore_to_folder, "plot_space", fails)
    code, output = explore(examples_copy, out)
    assert code == 1 and "disk full" in output, output
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before  # untouched, no staged file
    fresh = examples_copy / "fresh"
    code, output = explore(examples_copy, fresh)
    assert code == 1 and not fresh.exists(), output


def test_explore_interrupted_exits_130_and_writes_nothing(
    examples_copy: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def interrupted(*args: object, **kwargs: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(explore_to_folder, "explore", interrupted)
    out = examples_copy / "explored"
    code, output = explore(examples_copy, out)
    assert code == 130, output
    assert "Interrupted: no output was written." in output
    assert not out.exists()


def test_concretize_warns_when_its_file_names_what_readers_will_refuse(
    examples_copy: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    elsewhere = tmp_path_factory.mktemp("elsewhere")
    values = [
        "ego.initialSpeed=5",
        "Accelerate_1.targetSpeed=7",
        "InLocationRadius_2.radius=4",
        "DriveDistance_1.speed=10",
        "CrossingManeuver_1.triggerRadius=10",
        "CrossingManeuver_1.crossingSpeed=1.5",
    ]
    settings = [item for value in values for item in ("--set", value)]
    logical = examples_copy / "uis2-logical.xmi"
    beside = examples_copy / "c.xmi"
    inside = CliRunner().invoke(cli, ["concretize", str(logical), *settings, "-o", str(beside)])
    assert inside.exit_code == 0 and "Warning" not in inside.output, inside.output
    target = elsewhere / "c.xmi"
    result = CliRunner().invoke(cli, ["concretize", str(logical), *settings, "-o", str(target)])
    assert result.exit_code == 0, result.output
    library = examples_copy / "library"
    maps = examples_copy.parent / "maps"
    for folder, name in ((library, "sceml-library.xmi"), (maps, "intersection.xodr")):
        assert (
            f"Warning: {target} names {folder / name}, outside its folder and project root: "
            f"commands that read it will refuse it unless given --allow {folder}"
        ) in result.output
    export = ["export", str(target), "-o", str(elsewhere / "c.xosc")]
    assert CliRunner().invoke(cli, export).exit_code != 0
    allowed = CliRunner().invoke(cli, [*export, "--allow", str(library), "--allow", str(maps)])
    assert allowed.exit_code == 0, allowed.output

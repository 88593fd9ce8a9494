"""The reading rule and the writing rule (docs/security.md): FIFOs and links as inputs and
outputs, files outside the allowed folders, and the byte limit counted while reading.

Special files are made in a temporary folder (a FIFO, links to it); no test touches /dev or /etc.
"""

from __future__ import annotations

import os
import shutil
import stat
from pathlib import Path

import pytest

from sceml.errors import LoadError, SaveError
from sceml.files import safefiles
from sceml.files.writing import write_atomically, write_staged
from sceml.model.loading import load
from sceml.modules.store import save_together

from .confined import sceml

MAP_TEXT = 'map="../maps/intersection.xodr"'


@pytest.fixture
def outside(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder outside the examples' project, holding a good copy of the map."""
    folder = tmp_path_factory.mktemp("outside")
    repo = Path(__file__).resolve().parents[2]
    shutil.copy(repo / "maps" / "intersection.xodr", folder / "secret.xodr")
    return folder


def fifo(path: Path) -> Path:
    os.mkfifo(path)
    return path


def with_map(examples: Path, text: str, name: str = "mapped.xmi") -> Path:
    source = (examples / "uis1-concrete.xmi").read_text(encoding="utf-8")
    assert MAP_TEXT in source
    target = examples / name
    target.write_text(source.replace(MAP_TEXT, f'map="{text}"', 1), encoding="utf-8")
    return target


def no_traceback(output: str) -> None:
    assert "Traceback" not in output, output


# Reading -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "arguments"),
    [
        ("model.xmi", ["info"]),
        ("model.xmi", ["validate"]),
        ("scenario.xosc", ["check-xosc", "--no-quality-checker"]),
    ],
)
def test_a_fifo_named_on_the_command_line_is_refused_without_blocking(
    tmp_path: Path, name: str, arguments: list[str]
) -> None:
    path = fifo(tmp_path / name)
    run = sceml(*arguments, path, cwd=tmp_path)
    no_traceback(run.output)
    assert run.code == 2, run.output
    assert f"{path}" in run.output and "FIFO" in run.output


@pytest.mark.parametrize("option", ["limits", "ranges"])
def test_a_fifo_as_a_configuration_file_is_refused(
    examples_copy: Path, tmp_path: Path, option: str
) -> None:
    config = fifo(tmp_path / "config.yaml")
    if option == "limits":
        arguments = ["validate", "--limits", config, examples_copy / "uis1-concrete.xmi"]
    else:
        model = examples_copy / "uis1-functional.xmi"
        arguments = ["promote", model, "--ranges", config, "-o", tmp_path / "p.xmi"]
    run = sceml(*arguments, cwd=tmp_path)
    no_traceback(run.output)
    assert run.code == 2 and "FIFO" in run.output, run.output
    assert not (tmp_path / "p.xmi").exists()


def test_a_fifo_as_a_library_is_reported_at_the_use(examples_copy: Path) -> None:
    library = examples_copy / "library" / "sceml-library.xmi"
    library.unlink()
    fifo(library)
    run = sceml("info", examples_copy / "uis2-concrete.xmi", cwd=examples_copy)
    no_traceback(run.output)
    assert run.code == 1, run.output
    assert "uis2-concrete.xmi:64:" in run.output and "FIFO" in run.output


@pytest.mark.parametrize("kind", ["fifo", "link to a fifo"])
def test_a_fifo_as_a_map_is_a_located_map_error(examples_copy: Path, kind: str) -> None:
    pipe = fifo(examples_copy / "pipe.xodr")
    name = "pipe.xodr"
    if kind == "link to a fifo":
        (examples_copy / "link.xodr").symlink_to(pipe)
        name = "link.xodr"
    scenario = with_map(examples_copy, name)
    run = sceml("validate", scenario, cwd=examples_copy)
    no_traceback(run.output)
    assert run.code == 1, run.output
    assert "mapped.xmi:3: error[SCEML-R001]" in run.output and "FIFO" in run.output


def test_a_map_outside_the_allowed_folders_is_not_opened(
    examples_copy: Path, outside: Path
) -> None:
    secret = outside / "secret.xodr"
    scenario = with_map(examples_copy, str(secret))
    run = sceml("validate", scenario, cwd=examples_copy)
    no_traceback(run.output)
    assert run.code == 1 and "outside the allowed folders" in run.output, run.output
    assert f"--allow {outside}" in run.output
    assert run.opened_under(outside) == []
    allowed = sceml("validate", scenario, "--allow", outside, cwd=examples_copy)
    assert allowed.code == 0, allowed.output
    assert allowed.opened_under(outside) == [str(secret)]  # the audit does see such a read


def test_a_library_outside_the_allowed_folders_is_not_opened(
    examples_copy: Path, outside: Path
) -> None:
    library = examples_copy / "library" / "sceml-library.xmi"
    shutil.copy(library, outside / "library.xmi")
    scenario = examples_copy / "uis2-concrete.xmi"
    text = scenario.read_text(encoding="utf-8")
    old = 'href="library/sceml-library.xmi#CrossingManeuver"'
    assert old in text
    scenario.write_text(text.replace(old, f'href="{outside / "library.xmi"}#CrossingManeuver"'))
    run = sceml("flatten", scenario, "-o", examples_copy / "flat.xmi", cwd=examples_copy)
    assert "Traceback" not in run.output
    assert run.code == 1 and "leaves the allowed folders" in run.output, run.output
    assert run.opened_under(outside) == []
    assert not (examples_copy / "flat.xmi").exists()


def test_a_logic_file_outside_the_allowed_folders_is_not_opened(
    tmp_path: Path, outside: Path
) -> None:
    golden = Path(__file__).resolve().parents[1] / "export" / "golden" / "uis1-1.3-generic.xosc"
    text = golden.read_text(encoding="utf-8")
    logic = 'LogicFile filepath="../../../maps/intersection.xodr"'
    assert logic in text
    xosc = tmp_path / "a.xosc"
    xosc.write_text(text.replace(logic, f'LogicFile filepath="{outside / "secret.xodr"}"'))
    run = sceml("check-xosc", "--no-quality-checker", xosc, cwd=tmp_path)
    no_traceback(run.output)
    assert run.code == 1 and "XOSC-MAP" in run.output and "outside" in run.output, run.output
    assert run.opened_under(outside) == []
    allowed = sceml("check-xosc", "--no-quality-checker", xosc, "--allow", outside, cwd=tmp_path)
    assert allowed.code == 0, allowed.output


def test_the_byte_limit_is_counted_while_reading_not_taken_from_the_size_reported(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A device reports a size of 0 (/dev/zero) and then never ends; a regular file whose fstat
    # says 0 stands for it here.
    path = tmp_path / "grows.xmi"
    path.write_bytes(b"x" * 5000)
    real_fstat = os.fstat

    def says_empty(handle: int) -> os.stat_result:
        status = list(real_fstat(handle))
        status[stat.ST_SIZE] = 0
        return os.stat_result(status)

    monkeypatch.setattr(safefiles.os, "fstat", says_empty)
    with pytest.raises(LoadError, match="holds more than the 1000-byte limit"):
        safefiles.read_input(path, max_bytes=1000)
    assert safefiles.read_input(path, max_bytes=5000) == b"x" * 5000


def test_read_input_refuses_outside_roots_before_opening(tmp_path: Path, outside: Path) -> None:
    with pytest.raises(LoadError, match="outside the allowed folders"):
        safefiles.read_input(outside / "secret.xodr", roots=[tmp_path])
    link = tmp_path / "inside-looking.xodr"
    link.symlink_to(outside / "secret.xodr")  # a link is judged by where it leads
    with pytest.raises(LoadError, match="outside the allowed folders"):
        safefiles.read_input(link, roots=[tmp_path])


# Writing -------------------------------------------------------------------------------------


def test_export_to_a_fifo_refuses_and_leaves_it_a_fifo(examples_copy: Path, tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    target = fifo(out / "out.xosc")
    run = sceml("export", examples_copy / "uis1-concrete.xmi", "-o", target, cwd=out)
    no_traceback(run.output)
    assert run.code == 1 and "FIFO" in run.output, run.output
    assert stat.S_ISFIFO(os.lstat(target).st_mode)
    assert sorted(p.name for p in out.iterdir()) == ["out.xosc"]  # no temporary left


def test_a_link_to_a_regular_file_is_followed_and_stays_a_link(
    examples_copy: Path, tmp_path: Path
) -> None:
    real = tmp_path / "real.xosc"
    real.write_text("old")
    link = tmp_path / "link.xosc"
    link.symlink_to(real)
    run = sceml("export", examples_copy / "uis1-concrete.xmi", "-o", link, cwd=tmp_path)
    assert run.code == 0, run.output
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert real.read_text().startswith("<?xml") and "OpenSCENARIO" in real.read_text()


@pytest.mark.parametrize("points_to", ["fifo", "nothing"])
def test_a_link_to_a_fifo_or_to_nothing_is_refused_and_left_alone(
    examples_copy: Path, tmp_path: Path, points_to: str
) -> None:
    target = fifo(tmp_path / "pipe") if points_to == "fifo" else tmp_path / "missing.xosc"
    link = tmp_path / "link.xosc"
    link.symlink_to(target)
    run = sceml("export", examples_copy / "uis1-concrete.xmi", "-o", link, cwd=tmp_path)
    no_traceback(run.output)
    assert run.code == 1, run.output
    assert link.is_symlink() and os.readlink(link) == str(target)
    if points_to == "fifo":
        assert stat.S_ISFIFO(os.lstat(target).st_mode)
    else:
        assert not target.exists() and "missing file" in run.output


def test_every_writer_follows_the_rule(tmp_path: Path) -> None:
    target = fifo(tmp_path / "out.xmi")
    staging = tmp_path / "staging"
    staging.mkdir()
    with pytest.raises(SaveError, match="FIFO"):
        write_atomically(target, b"data")
    with pytest.raises(SaveError, match="FIFO"):
        write_staged(target, b"data", staging)
    examples = Path(__file__).resolve().parents[2] / "examples"
    model = load(examples / "uis1-concrete.xmi").root
    with pytest.raises(SaveError, match="FIFO"):
        save_together([(model, target)])
    assert stat.S_ISFIFO(os.lstat(target).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.xmi", "staging"]
    assert list(staging.iterdir()) == []


def test_simulate_writes_no_page_when_its_csv_cannot_be_written(
    examples_copy: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    csv = fifo(out / "run.csv")
    page = out / "run.html"
    run = sceml("simulate", examples_copy / "uis1-concrete.xmi", "-o", page, "--csv", csv, cwd=out)
    no_traceback(run.output)
    assert run.code == 1 and "FIFO" in run.output, run.output
    assert not page.exists()
    assert sorted(p.name for p in out.iterdir()) == ["run.csv"]

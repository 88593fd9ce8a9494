"""git diff and git merge through sceml, in a real git repository made in the test."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")

#: The sceml program of this environment, which git runs as the drivers.
SCEML = Path(sys.executable).with_name("sceml")


def git(repo: Path, *arguments: str, check: bool = True) -> subprocess.CompletedProcess[str]:
    environment = {
        **os.environ,
        "GIT_CONFIG_GLOBAL": str(repo.parent / "gitconfig"),
        "GIT_CONFIG_NOSYSTEM": "1",
        "GIT_PAGER": "cat",
    }
    return subprocess.run(
        ["git", *arguments], cwd=repo, capture_output=True, text=True, check=check, env=environment
    )


def replace(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert text.count(old) == 1, old
    path.write_text(text.replace(old, new))


@pytest.fixture
def repo(examples_copy: Path) -> Path:
    """A repository holding UIS2 and its library, set up with `sceml git-setup`."""
    folder = examples_copy.parent / "repo"
    folder.mkdir()
    shutil.copytree(examples_copy / "library", folder / "library")
    shutil.copy(examples_copy / "uis2-logical.xmi", folder / "uis2.xmi")
    git(folder, "init", "-q", "-b", "main")
    git(folder, "config", "user.email", "test@example.org")
    git(folder, "config", "user.name", "Test")
    done = subprocess.run(
        [str(SCEML), "git-setup", "--program", str(SCEML)],
        cwd=folder, capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert ".gitattributes: *.xmi diff=sceml merge=sceml" in done.stdout
    git(folder, "add", "-A")
    git(folder, "commit", "-qm", "base")
    return folder


DISTANCE = '<distance xsi:type="scemlmodel:Value" value="60.0"/>'
TOLERANCE = '<tolerance xsi:type="scemlmodel:Value" value="3.0"/>'


def test_setup_twice_writes_one_attributes_line(repo: Path) -> None:
    subprocess.run(
        [str(SCEML), "git-setup", "--program", str(SCEML)],
        cwd=repo,
        check=True,
        capture_output=True,
    )
    assert (repo / ".gitattributes").read_text() == "*.xmi diff=sceml merge=sceml\n"
    assert (
        git(repo, "config", "merge.sceml.driver").stdout.strip()
        == f"{SCEML} merge %O %A %B -o %A --name %P"
    )


def test_git_diff_shows_the_change_in_the_model_s_terms(repo: Path) -> None:
    replace(repo / "uis2.xmi", DISTANCE, DISTANCE.replace("60.0", "75.0"))
    shown = git(repo, "diff").stdout
    assert "a/uis2.xmi -> b/uis2.xmi: 1 change\n" in shown
    assert "~ DriveDistance_1.distance: 60 -> 75 m" in shown
    assert "<distance" not in shown


def test_git_merge_joins_edits_to_different_things(repo: Path) -> None:
    scenario = repo / "uis2.xmi"
    git(repo, "checkout", "-qb", "theirs")
    replace(scenario, TOLERANCE, TOLERANCE.replace("3.0", "5.0"))
    git(repo, "commit", "-qam", "wider turn")
    git(repo, "checkout", "-q", "main")
    replace(scenario, DISTANCE, DISTANCE.replace("60.0", "75.0"))
    git(repo, "commit", "-qam", "longer drive")
    merged = git(repo, "merge", "theirs", "-m", "merge")
    assert merged.returncode == 0
    shown = git(repo, "diff", "HEAD~2", "HEAD", "--", "uis2.xmi").stdout
    assert "~ TurnLeft_1.tolerance: 3 -> 5 m" in shown
    assert "~ DriveDistance_1.distance: 60 -> 75 m" in shown


def test_a_conflicting_merge_leaves_ours_and_lists_the_conflict(repo: Path) -> None:
    scenario = repo / "uis2.xmi"
    git(repo, "checkout", "-qb", "theirs")
    replace(scenario, DISTANCE, DISTANCE.replace("60.0", "80.0"))
    git(repo, "commit", "-qam", "80 m")
    git(repo, "checkout", "-q", "main")
    replace(scenario, DISTANCE, DISTANCE.replace("60.0", "75.0"))
    git(repo, "commit", "-qam", "75 m")
    ours = scenario.read_bytes()
    merged = git(repo, "merge", "theirs", "-m", "merge", check=False)
    assert merged.returncode != 0
    output = merged.stdout + merged.stderr
    assert (
        "uis2.xmi: conflict: DriveDistance_1.distance: changed differently (ours: 75 m; theirs: 80 m)"
        in output
    )
    assert "CONFLICT" in output
    assert scenario.read_bytes() == ours
    assert "UU uis2.xmi" in git(repo, "status", "--short").stdout


def test_an_added_file_lists_everything_as_added(repo: Path) -> None:
    shutil.copy(repo / "uis2.xmi", repo / "copy.xmi")
    git(repo, "add", "copy.xmi")
    git(repo, "commit", "-qm", "a copy")
    shown = git(repo, "show", "--ext-diff", "HEAD").stdout
    assert "a/copy.xmi -> b/copy.xmi: 20 changes\n" in shown
    assert "  + ego (Car) added\n" in shown and "  - " not in shown


def test_global_setup_writes_the_user_s_config_and_attributes(tmp_path: Path) -> None:
    home = tmp_path / "home"
    home.mkdir()
    environment = {**os.environ, "HOME": str(home), "GIT_CONFIG_NOSYSTEM": "1"}
    environment.pop("GIT_CONFIG_GLOBAL", None)
    subprocess.run(
        [str(SCEML), "git-setup", "--global", "--program", "sceml"],
        cwd=tmp_path, env=environment, check=True, capture_output=True,
    )  # fmt: skip
    config = (home / ".gitconfig").read_text()
    assert "command = sceml diff --git" in config
    assert "driver = sceml merge %O %A %B -o %A --name %P" in config
    attributes = home / ".config" / "git" / "attributes"
    assert f"attributesFile = {attributes}" in config
    assert attributes.read_text() == "*.xmi diff=sceml merge=sceml\n"

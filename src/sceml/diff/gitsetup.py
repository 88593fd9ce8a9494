"""git's diff and merge drivers for scenario files: the attributes line and the config they need.

git reads `*.xmi diff=sceml merge=sceml` from .gitattributes, then runs
`diff.sceml.command` (with the seven arguments of GIT_EXTERNAL_DIFF) for `git diff`, and
`merge.sceml.driver` for a three-way merge (%O base, %A ours, %B theirs; the result is written
into %A; a non-zero exit leaves %A as it was and marks the file conflicted).
"""

from __future__ import annotations

import shlex
import subprocess
from dataclasses import dataclass
from pathlib import Path

from ..errors import SceMLError
from ..files.writing import write_atomically

DRIVER = "sceml"

#: The line .gitattributes needs.
ATTRIBUTES_LINE = f"*.xmi diff={DRIVER} merge={DRIVER}"


class GitSetupError(SceMLError):
    """git is missing, or the folder is not in a git repository."""


@dataclass(frozen=True)
class GitSetup:
    """What was configured: the attributes file and the config entries, for the CLI to say."""

    attributes: Path
    scope: str
    settings: dict[str, str]


def settings(program: str) -> dict[str, str]:
    """The git config entries for a `sceml` program (a name on PATH or an absolute path)."""
    run = shlex.quote(program)
    return {
        f"diff.{DRIVER}.command": f"{run} diff --git",
        f"merge.{DRIVER}.name": "SceML three-way merge of scenarios",
        f"merge.{DRIVER}.driver": f"{run} merge %O %A %B -o %A --name %P",
    }


def configure(folder: Path, program: str, *, global_: bool = False) -> GitSetup:
    """Write the attributes line and the config, for the repository at `folder` or for the user."""
    scope = "--global" if global_ else "--local"
    if global_:
        attributes = _global_attributes(folder)
    else:
        attributes = Path(_git(folder, "rev-parse", "--show-toplevel").strip()) / ".gitattributes"
    add_line(attributes, ATTRIBUTES_LINE)
    chosen = settings(program)
    for key, value in chosen.items():
        _git(folder, "config", scope, key, value)
    return GitSetup(attributes=attributes, scope=scope.lstrip("-"), settings=chosen)


def _global_attributes(folder: Path) -> Path:
    """The user's attributes file: core.attributesFile, else git's default place (set it then)."""
    try:
        configured = _git(folder, "config", "--global", "--get", "core.attributesFile").strip()
    except GitSetupError:
        configured = ""
    if configured:
        return Path(configured).expanduser()
    default = Path.home() / ".config" / "git" / "attributes"
    _git(folder, "config", "--global", "core.attributesFile", str(default))
    return default


def add_line(path: Path, line: str) -> bool:
    """Append `line` to a text file unless it is there already; whether the file changed."""
    text = path.read_text(encoding="utf-8") if path.exists() else ""
    if line in text.splitlines():
        return False
    if text and not text.endswith("\n"):
        text += "\n"
    path.parent.mkdir(parents=True, exist_ok=True)
    write_atomically(path, (text + line + "\n").encode("utf-8"))
    return True


def _git(folder: Path, *arguments: str) -> str:
    try:
        done = subprocess.run(
            ["git", *arguments], cwd=folder, capture_output=True, text=True, check=False
        )
    except FileNotFoundError:
        raise GitSetupError("git is not installed") from None
    if done.returncode != 0:
        message = done.stderr.strip() or f"git {' '.join(arguments)} failed"
        raise GitSetupError(message, file=folder)
    return done.stdout

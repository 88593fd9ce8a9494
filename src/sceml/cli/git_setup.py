"""`sceml git-setup`: make `git diff` and `git merge` use sceml for scenario files."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import click

from ..diff.gitsetup import configure
from .common import SceMLCommand


def _this_program() -> str:
    """`sceml` when that is what PATH finds, else the absolute path of the running program."""
    running = Path(sys.argv[0]).resolve()
    found = shutil.which("sceml")
    if found is not None and Path(found).resolve() == running:
        return "sceml"
    return str(running) if running.name == "sceml" else "sceml"


@click.command(cls=SceMLCommand)
@click.option(
    "--global",
    "global_",
    is_flag=True,
    help="Configure git for every repository of this user (git config --global and the user's "
    "attributes file) instead of the repository in the current folder.",
)
@click.option(
    "--program",
    default=None,
    metavar="PATH",
    help="The sceml program git should run (default: `sceml` if PATH finds this one, else its "
    "absolute path).",
)
def git_setup(global_: bool, program: str | None) -> None:
    """Configure git so that `git diff` shows `sceml diff` and `git merge` uses `sceml merge`
    for *.xmi files.

    Adds `*.xmi diff=sceml merge=sceml` to .gitattributes (at the repository's top; with
    --global, to the user's attributes file) and sets diff.sceml.command and
    merge.sceml.driver. A conflicting merge leaves the file as it was on the current branch,
    marks it conflicted, and lists the conflicts in git's output. Running it again changes
    nothing.
    """
    done = configure(Path.cwd(), program or _this_program(), global_=global_)
    click.echo(f"{done.attributes}: *.xmi diff=sceml merge=sceml")
    for key, value in done.settings.items():
        click.echo(f"git config --{done.scope} {key} {value!r}")

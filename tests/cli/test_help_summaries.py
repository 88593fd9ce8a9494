"""`sceml --help` lists the commands from their summaries, without importing them; what it shows
must be what the commands themselves would show."""

from __future__ import annotations

import subprocess
import sys

import click
import pytest

from sceml.cli import COMMANDS, commands
from sceml.cli.summaries import summaries

SUMMARIES = summaries(COMMANDS)


@pytest.mark.parametrize("name", list(COMMANDS))
def test_the_summary_is_the_commands_own(name: str) -> None:
    command = commands()[name]
    assert not command.short_help and not command.hidden and not command.deprecated
    own = " ".join((command.help or "").split("\n\n")[0].split())
    assert SUMMARIES.get(name) == own, (
        f"the summary read from the source of {name!r} is not {own!r}"
    )
    for limit in range(10, 160):  # the terminal's width decides the limit
        shown = click.Command(name, help=SUMMARIES[name]).get_short_help_str(limit)
        assert shown == command.get_short_help_str(limit)


def test_help_lists_every_command_without_importing_one() -> None:
    script = (
        "import sys; from sceml.cli import cli\n"
        "try:\n    cli(['--help'])\nexcept SystemExit:\n    pass\n"
        "print(sorted(m for m in sys.modules if m.startswith('sceml.cli.')))"
    )
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    *listing, imported = ran.stdout.splitlines()
    assert imported == "['sceml.cli.common', 'sceml.cli.summaries']"
    shown = [line.split()[0] for line in listing[listing.index("Commands:") + 1 :] if line]
    assert shown == list(COMMANDS)

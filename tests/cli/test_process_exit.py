"""`sceml` ends its process without freeing the model, and nothing a user sees changes by it.

The command's status, its output and the exit handlers are what the ordinary exit gives; only
the collection of the objects left over is skipped.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from click.testing import CliRunner

from sceml.cli import cli

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def run_process(*arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sceml.cli", *arguments], capture_output=True, text=True
    )


@pytest.mark.parametrize(
    "arguments",
    [
        ["validate", str(EXAMPLES / "uis1-concrete.xmi")],  # 0: valid
        ["validate", "no-such-file.xmi"],  # 2: unreadable
        ["validate", "--no-such-option"],  # 2: usage error
        ["info", str(EXAMPLES / "uis2-logical.xmi")],
    ],
)
def test_status_and_output_are_those_of_the_command(arguments: list[str]) -> None:
    expected = CliRunner().invoke(cli, arguments, prog_name="python -m sceml.cli")
    ran = run_process(*arguments)
    assert (ran.returncode, ran.stdout, ran.stderr) == (
        expected.exit_code,
        expected.stdout,
        expected.stderr,
    )


def run_with_command(body: str, tmp_path: Path) -> subprocess.CompletedProcess[str]:
    """Run `main()` with one extra command, `probe`, whose body is `body`."""
    script = tmp_path / "probe.py"
    script.write_text(
        textwrap.dedent(
            """
            import atexit, sys, threading, time
            import click
            from sceml.cli import cli, main

            class Cycle:
                def __init__(self):
                    self.me = self
                def __del__(self):
                    print("freed", file=sys.stderr)

            @cli.command()
            def probe():
                {body}

            sys.argv = ["sceml", "probe"]
            main()
            """
        ).replace("{body}", body)
    )
    return subprocess.run([sys.executable, str(script)], capture_output=True, text=True)


def test_output_exit_handlers_and_status_survive_the_fast_end(tmp_path: Path) -> None:
    marker = tmp_path / "handler-ran"
    body = (
        f"atexit.register(lambda: open({str(marker)!r}, 'w').close()); "
        "globals()['kept'] = Cycle(); "
        "sys.stdout.write('x' * 1_000_000); "
        "sys.exit(3)"
    )
    ran = run_with_command(body, tmp_path)
    assert ran.returncode == 3
    assert ran.stdout == "x" * 1_000_000
    assert marker.exists()
    # The cycle left in a module global is not collected: the process ended before teardown.
    assert "freed" not in ran.stderr


def test_a_running_thread_gets_the_ordinary_exit(tmp_path: Path) -> None:
    marker = tmp_path / "thread-finished"
    body = (
        "globals()['kept'] = Cycle(); "
        "threading.Thread(target=lambda: (time.sleep(0.2), "
        f"open({str(marker)!r}, 'w').close())).start()"
    )
    ran = run_with_command(body, tmp_path)
    assert ran.returncode == 0
    assert marker.exists()  # the exit waited for the thread
    assert "freed" in ran.stderr  # and collected what was left, as Python's exit does

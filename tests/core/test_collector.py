"""The collector is left off after a command only in a process that ends with the command."""

from __future__ import annotations

import gc
import subprocess
import sys
import textwrap

from sceml.model.collector import collector_off_for_command


def test_in_process_the_collector_comes_back_on() -> None:
    assert gc.isenabled()
    with collector_off_for_command():
        assert not gc.isenabled()
    assert gc.isenabled()


def test_a_process_that_ends_with_its_command_leaves_it_off() -> None:
    script = textwrap.dedent(
        """
        import gc
        from sceml.model.collector import collector_off_for_command, ending_with_command
        ending_with_command()
        with collector_off_for_command():
            inside = gc.isenabled()
        print(inside, gc.isenabled())
        """
    )
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert ran.stdout.split() == ["False", "False"]

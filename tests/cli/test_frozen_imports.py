"""The console script puts what a command imported out of the cyclic collector's reach
(`gc.freeze`) before the command runs; a command called in-process leaves the collector alone."""

from __future__ import annotations

import gc
import subprocess
import sys
from pathlib import Path

from click.testing import CliRunner

from sceml.cli import cli

UIS1 = Path(__file__).resolve().parents[2] / "examples" / "uis1-concrete.xmi"

PROBE = """
import atexit, gc, sys
atexit.register(lambda: print("frozen", gc.get_freeze_count(), "scemlmodel" in sys.modules))
sys.argv[0] = "sceml"
from sceml.cli import main
main()
"""


def test_the_console_script_freezes_the_imported_objects(tmp_path: Path) -> None:
    ran = subprocess.run(
        [sys.executable, "-c", PROBE, "validate", str(UIS1)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert ran.returncode == 0, ran.stderr
    label, count, model_imported = ran.stdout.splitlines()[-1].split()
    assert label == "frozen" and model_imported == "True"
    assert int(count) > 20_000  # the modules, pyecore's metamodel, the generated classes


def test_a_command_run_in_process_freezes_nothing() -> None:
    before = gc.get_freeze_count()
    result = CliRunner().invoke(cli, ["validate", str(UIS1)])
    assert result.exit_code == 0, result.output
    assert gc.get_freeze_count() == before


COLLECTIONS = """
import atexit, gc, sys
before_freeze, in_main = [], []
gc.callbacks.append(
    lambda phase, info: phase == "start" and in_main and gc.get_freeze_count() == 0
    and before_freeze.append(info["generation"])
)
atexit.register(lambda: print("collections", len(before_freeze), gc.isenabled()))
sys.argv[0] = "sceml"
from sceml.cli import main
in_main.append(True)
main()
"""


def test_no_collection_runs_while_the_command_imports_and_it_is_back_on_after(
    tmp_path: Path,
) -> None:
    # Without the pause, 40-80 collections ran among a command's imports (6-11 ms of `sceml
    # validate`, `simulate` and `sample`), each walking objects that live to the end anyway.
    uis2 = UIS1.with_name("uis2-logical.xmi")
    arguments = ["sample", str(uis2), "--strategy", "random", "--n", "2", "-o", "out"]
    ran = subprocess.run(
        [sys.executable, "-c", COLLECTIONS, *arguments],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert ran.returncode == 0, ran.stderr
    label, count, enabled = ran.stdout.splitlines()[-1].split()
    assert label == "collections" and count == "0"
    assert enabled == "True"  # the command itself runs with the collector as usual

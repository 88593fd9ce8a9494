"""The console script asks numpy's OpenBLAS for one thread unless the user set a limit (issue 31:
its pool of spinning threads cost about 30 ms CPU of every command that reads a map)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from sceml.cli.blas_threads import THREAD_VARIABLES

SCRIPT = """
import os, sys
from sceml.cli.blas_threads import one_blas_thread
one_blas_thread()
import numpy
tasks = len(os.listdir("/proc/self/task")) if os.path.isdir("/proc/self/task") else -1
print(os.environ.get("OPENBLAS_NUM_THREADS"), tasks)
"""


def _run(**variables: str) -> list[str]:
    env = {k: v for k, v in os.environ.items() if k not in THREAD_VARIABLES}
    ran = subprocess.run(
        [sys.executable, "-c", SCRIPT], env={**env, **variables}, capture_output=True, text=True
    )
    assert ran.returncode == 0, ran.stderr
    return ran.stdout.split()


def test_one_thread_when_nothing_is_set() -> None:
    setting, tasks = _run()
    assert setting == "1"
    if tasks != "-1":
        assert tasks == "1"  # the interpreter's own thread, no pool


@pytest.mark.parametrize("variable", THREAD_VARIABLES)
def test_a_limit_the_user_set_is_kept(variable: str) -> None:
    setting, _ = _run(**{variable: "2"})
    assert setting == ("2" if variable == "OPENBLAS_NUM_THREADS" else "None")


def test_nothing_changes_once_numpy_is_imported(monkeypatch: pytest.MonkeyPatch) -> None:
    import numpy  # noqa: F401

    from sceml.cli.blas_threads import one_blas_thread

    for name in THREAD_VARIABLES:
        monkeypatch.delenv(name, raising=False)
    one_blas_thread()
    assert "OPENBLAS_NUM_THREADS" not in os.environ


def test_the_console_script_limits_the_threads(tmp_path: Path) -> None:
    code = (
        "import atexit, os, sys; sys.argv[0] = 'sceml'\n"
        "atexit.register(lambda: print(os.environ.get('OPENBLAS_NUM_THREADS'), file=sys.stderr))\n"
        "from sceml.cli import main; main()"
    )
    env = {k: v for k, v in os.environ.items() if k not in THREAD_VARIABLES}
    uis1 = Path(__file__).resolve().parents[2] / "examples" / "uis1-concrete.xmi"
    ran = subprocess.run(
        [sys.executable, "-c", code, "validate", str(uis1)],
        env=env,
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert ran.returncode == 0, ran.stderr
    assert ran.stderr.splitlines()[-1] == "1"

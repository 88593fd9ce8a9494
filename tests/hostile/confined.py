"""Run `sceml` in a fresh process held to 1 GB of address space and 10 s of CPU, and record
every file it opens (Python's `open` audit event), so a test can say what it did not touch.

Limits, not timings: a run that needs more is killed by the kernel (MemoryError or SIGXCPU)
and the test fails on its exit, whatever the machine's speed. The wall-clock timeout only
catches a process blocked on something (a FIFO), which uses no CPU.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

MEMORY_BYTES = 2**30
CPU_SECONDS = 10
HANG_SECONDS = 120  # far above CPU_SECONDS: only a process that waits without working gets here

# Runs in the child: the audit hook records each path opened (one per line, flushed, so a killed
# process leaves its log), then the CLI runs as `sceml` would.
_BOOT = """
import sys
log = open(sys.argv[1], "w", buffering=1, encoding="utf-8", errors="replace")

def audit(event, args):
    if event == "open" and isinstance(args[0], (str, bytes)):
        log.write(f"{args[0]!s}\\n" if isinstance(args[0], str) else f"{args[0]!r}\\n")

sys.addaudithook(audit)
sys.argv = ["sceml", *sys.argv[2:]]
from sceml.cli import cli
cli(prog_name="sceml")
"""


@dataclass
class Run:
    """How a confined run ended: exit code, its output, and every path it opened."""

    code: int
    stdout: str
    stderr: str
    opened: list[str]

    @property
    def output(self) -> str:
        return self.stdout + self.stderr

    def opened_under(self, folder: Path) -> list[str]:
        """The opened paths inside `folder` (links not resolved: as the program named them)."""
        prefix = str(folder)
        return [p for p in self.opened if p == prefix or p.startswith(prefix + os.sep)]


# BLAS libraries reserve address space per thread at import (tens of MB each on a many-core
# machine), which would count against the limit without being used.
_ENVIRONMENT = {
    "MPLBACKEND": "Agg",
    "PYTHONDONTWRITEBYTECODE": "1",
    "OPENBLAS_NUM_THREADS": "1",
    "OMP_NUM_THREADS": "1",
    "MKL_NUM_THREADS": "1",
}


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_SECONDS, CPU_SECONDS))


def sceml(*arguments: object, cwd: Path, log: Path | None = None) -> Run:
    """Run `sceml ARGUMENTS` confined, in `cwd`; the audit log goes to `log` (default in cwd)."""
    log = log or cwd / ".opened.log"
    done = subprocess.run(
        [sys.executable, "-c", _BOOT, str(log), *(str(a) for a in arguments)],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=HANG_SECONDS,
        preexec_fn=_limit,
        env={**os.environ, **_ENVIRONMENT},
        check=False,
    )
    opened = log.read_text(encoding="utf-8").splitlines() if log.exists() else []
    log.unlink(missing_ok=True)
    return Run(done.returncode, done.stdout, done.stderr, opened)

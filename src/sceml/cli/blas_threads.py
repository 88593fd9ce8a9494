"""One BLAS thread for the command line's numpy, unless the user chose otherwise.

numpy's OpenBLAS starts a pool of threads as numpy is imported, one per core, and they spin
waiting for work: about 30 ms CPU of every command that reads a map (`import numpy` 98 ms CPU
above a 24 ms `python -c pass`, 64 ms with one thread; benchmarks/startup.py). SceML's arrays
are small (a road's samples, a fit of a few columns), below the sizes OpenBLAS splits between
threads, so the pool never helps it. The limit must be in the environment before numpy is
imported; OpenBLAS reads OPENBLAS_NUM_THREADS, then GOTO_NUM_THREADS, then OMP_NUM_THREADS, and
a value the user set in any of them is kept.
"""

from __future__ import annotations

import os
import sys

#: The variables OpenBLAS reads for its thread count, in the order it reads them.
THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS")


def one_blas_thread() -> None:
    """Ask OpenBLAS for one thread, if numpy is not imported yet and no limit is set."""
    if "numpy" in sys.modules or any(name in os.environ for name in THREAD_VARIABLES):
        return
    os.environ["OPENBLAS_NUM_THREADS"] = "1"

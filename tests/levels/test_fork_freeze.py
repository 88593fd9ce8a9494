"""A forking pool freezes the caller's heap for its workers and thaws it afterwards (issue 31).

A forked worker's collector would otherwise walk, and so copy page by page, every object it
inherited before its first file; frozen objects are not walked.
"""

from __future__ import annotations

import gc
import multiprocessing

import pytest

from sceml.executors import ProcessExecutor

pytestmark = pytest.mark.skipif(
    "fork" not in multiprocessing.get_all_start_methods(), reason="workers are forked only here"
)


def _setup(payload: int) -> int:
    return payload


def _frozen_in_worker(state: int, item: int) -> int:
    return gc.get_freeze_count()


def test_workers_start_with_the_callers_objects_frozen_and_the_caller_thaws() -> None:
    assert gc.get_freeze_count() == 0
    outcomes = list(ProcessExecutor(2).map_unordered(_setup, _frozen_in_worker, 0, [1, 2, 3]))
    assert len(outcomes) == 3
    assert all(o.error is None and o.result is not None and o.result > 0 for o in outcomes)
    assert gc.get_freeze_count() == 0


def test_a_heap_frozen_by_the_caller_stays_frozen() -> None:
    gc.freeze()
    try:
        before = gc.get_freeze_count()
        list(ProcessExecutor(1).map_unordered(_setup, _frozen_in_worker, 0, [1]))
        assert gc.get_freeze_count() >= before > 0
    finally:
        gc.unfreeze()

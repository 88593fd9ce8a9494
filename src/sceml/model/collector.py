"""Pausing CPython's cyclic garbage collector around passes that build or walk large models."""

from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def collector_paused() -> Iterator[None]:
    """Run the body with the cyclic collector off, restoring its previous state afterwards.

    Loading or validating a model allocates a few objects per element while millions are alive;
    the collector would rescan all of them again and again (a 10,000-node load takes 2.4 s with
    it and 0.85 s without). Nothing these passes create relies on it: reference counting frees
    what they drop, and cycles left over are collected at the next regular collection.
    """
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


#: Whether this process ends when its command returns (set by `sceml.cli.main`, which ends it
#: with `end_now`, without freeing anything); a test calling a command in-process leaves it off.
_ends_with_command = False


def ending_with_command() -> None:
    """Note that this process ends once its command returns (see `collector_off_for_command`)."""
    global _ends_with_command
    _ends_with_command = True


@contextmanager
def collector_off_for_command() -> Iterator[None]:
    """`collector_paused` for a one-shot command, which leaves the collector off for good when
    the process ends with the command.

    Turned back on after loading and validating a large model, the collector's next pass walks
    every object allocated while it was off (the whole model, about twenty containers per node)
    only to find them alive, and the process ends right after: 10-15 % of `sceml validate` at
    10,000 nodes. Elsewhere (tests, the editor) it is turned back on as usual.
    """
    if not _ends_with_command:
        with collector_paused():
            yield
        return
    gc.disable()
    yield

"""Editor fixtures: a session on a private copy of an example, and the bytes a model saves to."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from editor.servers import Server, kill_all

from sceml.editor import EditorSession, SessionOptions


@pytest.fixture
def open_example(examples_copy: Path):
    """Open a copied example by file name: `open_example("uis1-concrete.xmi")`."""

    def opener(name: str, **options: object) -> EditorSession:
        session = EditorSession(SessionOptions(**options))  # type: ignore[arg-type]
        session.open(examples_copy / name)
        return session

    return opener


@pytest.fixture
def uis1(open_example) -> EditorSession:
    """A session on a copy of UIS1 (concrete)."""
    return open_example("uis1-concrete.xmi")


@pytest.fixture
def uis2(open_example) -> EditorSession:
    """A session on a copy of UIS2 (concrete), which uses CrossingManeuver."""
    return open_example("uis2-concrete.xmi")


@pytest.fixture
def servers() -> Iterator[list[Server]]:
    """Real `sceml edit` processes a test starts with `start(servers, path)`; killed after it."""
    started: list[Server] = []
    yield started
    kill_all(started)

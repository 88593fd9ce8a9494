"""Fixtures of the migration tests."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from metamodel_releases import METAMODEL

from sceml.migrations import History


@pytest.fixture
def metamodel_copy(tmp_path: Path) -> Path:
    """metamodel/ as it is, with the current release kept in its history (as `sceml dev
    release` would), so that a test can make the next release on top of it."""
    folder = tmp_path / "metamodel"
    folder.mkdir()
    shutil.copyfile(METAMODEL / "scemlmodel.ecore", folder / "scemlmodel.ecore")
    shutil.copytree(METAMODEL / "history", folder / "history")
    shutil.copytree(METAMODEL / "migrations", folder / "migrations")
    current = History(folder).current.version
    kept = folder / "history" / current
    if not kept.exists():
        kept.mkdir()
        shutil.copyfile(folder / "scemlmodel.ecore", kept / "scemlmodel.ecore")
    return folder

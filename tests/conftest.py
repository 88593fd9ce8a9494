"""Shared fixtures: where the repository's examples are, and fresh copies of them per test."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
EXAMPLES = REPO / "examples"


@pytest.fixture
def examples_copy(tmp_path: Path) -> Path:
    """A private copy of examples/ (and the map it refers to) that a test may change freely."""
    target = tmp_path / "examples"
    shutil.copytree(EXAMPLES, target, ignore=shutil.ignore_patterns("*.py", "__pycache__"))
    shutil.copytree(REPO / "maps", tmp_path / "maps", ignore=shutil.ignore_patterns("*.py"))
    return target

"""Shared fixtures: where the repository's examples are, and fresh copies of them per test."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
EXAMPLES = REPO / "examples"


def pytest_addoption(parser: pytest.Parser) -> None:
    """--update-golden rewrites golden files (e.g. tests/export/golden) instead of comparing."""
    parser.addoption(
        "--update-golden",
        action="store_true",
        default=False,
        help="rewrite the golden files from the current code; review the diff before committing",
    )


@pytest.fixture
def examples_copy(tmp_path: Path) -> Path:
    """A private copy of examples/ (and the map it refers to) that a test may change freely.

    Like the repository, the copy is one project (tmp_path holds a `.sceml-root` marker), so the
    examples may read ../maps by the reading rule; a test of files outside a project removes it.
    """
    target = tmp_path / "examples"
    shutil.copytree(EXAMPLES, target, ignore=shutil.ignore_patterns("*.py", "__pycache__"))
    shutil.copytree(REPO / "maps", tmp_path / "maps", ignore=shutil.ignore_patterns("*.py"))
    (tmp_path / ".sceml-root").touch()
    return target

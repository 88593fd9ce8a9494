"""Fixtures of the export tests: whether to rewrite the golden files."""

from __future__ import annotations

import pytest


@pytest.fixture
def update_golden(request: pytest.FixtureRequest) -> bool:
    """Whether `--update-golden` was given (registered in tests/conftest.py)."""
    return bool(request.config.getoption("--update-golden"))

"""The player-check scenarios: committed files equal their builder's output, and export."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from sceml.export import build_xosc
from sceml.model.loading import load_scenario

HERE = Path(__file__).resolve().parent
SCENARIOS = HERE / "scenarios"


def _builder():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("build_scenarios", HERE / "build_scenarios.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_committed_scenarios_equal_the_builder_output(tmp_path: Path) -> None:
    written = _builder().build_all(tmp_path)
    assert written
    for path in written:
        committed = SCENARIOS / path.relative_to(tmp_path)
        assert committed.read_bytes() == path.read_bytes(), f"{committed} is stale"


@pytest.mark.parametrize("path", sorted(SCENARIOS.glob("*.xmi")), ids=lambda p: p.stem)
@pytest.mark.parametrize("version", ["1.0", "1.3"])
def test_every_scenario_exports(path: Path, version: str) -> None:
    document = build_xosc(load_scenario(path).root, version=version, source_path=path)
    assert document.events_of

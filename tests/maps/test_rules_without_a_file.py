"""A model built in Python has no file: its map is read only from an absolute path, never from
wherever the working directory happens to be."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.model.build import ScenarioBuilder, lane
from sceml.validation import validate

REPO = Path(__file__).resolve().parents[2]


def on_sidewalk(map_text: str) -> list[str]:
    """Codes for a car started on a sidewalk (SCEML-R004 whenever the map is read)."""
    b = ScenarioBuilder("Case", map=map_text, level="concrete", date="2026-01-01T00:00:00")
    ego = b.actor("Car", "ego", ego=True, start=lane(1, -2, 10.0), speed=5.0)
    b.chain(b.root, b.add("Accelerate", ego, targetSpeed=8.0), b.end)
    return [d.code for d in validate(b.scenario)]


def test_a_relative_map_is_not_read_from_the_working_directory(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.chdir(REPO)  # "maps/intersection.xodr" exists from here
    assert (REPO / "maps" / "intersection.xodr").is_file()
    assert not [c for c in on_sidewalk("maps/intersection.xodr") if c.startswith("SCEML-R")]


def test_an_absolute_map_is_read() -> None:
    assert "SCEML-R004" in on_sidewalk(str(REPO / "maps" / "intersection.xodr"))

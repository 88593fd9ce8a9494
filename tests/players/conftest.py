"""Recorded esmini runs (tests/players/data, gzip-compressed) and the scenarios they played."""

from __future__ import annotations

import gzip
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
SCENARIOS = HERE / "scenarios"
EXAMPLES = HERE.parent.parent / "examples"


def model(name: str) -> Path:
    """The scenario a recording played: an example (`*-concrete`) or a player-check scenario."""
    return EXAMPLES / f"{name}.xmi" if name.endswith("-concrete") else SCENARIOS / f"{name}.xmi"


@pytest.fixture
def recording(tmp_path: Path):  # type: ignore[no-untyped-def]
    """recording(stem) -> (log, csv): the recorded files, unpacked into tmp_path."""

    def unpack(stem: str) -> tuple[Path, Path]:
        paths = []
        for suffix in (".log.txt", ".csv"):
            target = tmp_path / f"{stem}{suffix}"
            plain = DATA / f"{stem}{suffix}"  # one log is kept plain for other tests to read
            data = plain.read_bytes() if plain.exists() else None
            if data is None:
                data = gzip.decompress((DATA / f"{stem}{suffix}.gz").read_bytes())
            target.write_bytes(data)
            paths.append(target)
        return paths[0], paths[1]

    return unpack

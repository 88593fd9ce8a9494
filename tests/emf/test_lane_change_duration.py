"""Eclipse EMF reads and writes back a lane change given in time (release 1.5's
LaneChange.duration), as `sceml import` writes it."""

from __future__ import annotations

from pathlib import Path

from sceml.importer import import_to_file
from sceml.model.compare import differences
from sceml.model.loading import load

from .conftest import ECORE, REPO, Harness

FILES = REPO / "tests" / "importer" / "files"


def test_emf_keeps_a_lane_change_duration(emf: Harness, tmp_path: Path) -> None:
    source, out = tmp_path / "in", tmp_path / "out"
    source.mkdir()
    out.mkdir()
    import_to_file(FILES / "lane-change-time.xosc", source / "timed.xmi")
    assert "<duration" in (source / "timed.xmi").read_text()
    result = emf.run("roundtrip", ECORE, source, out, Path("timed.xmi"))
    assert "DIAGNOSTIC" not in result.stdout and "ERROR" not in result.stdout
    original, from_emf = load(source / "timed.xmi"), load(out / "timed.xmi")
    assert differences(original.root, from_emf.root) == []
    changes = {n.name: n for n in from_emf.root.nodes if n.eClass.name == "LaneChange"}
    assert changes["CutInEvent"].duration.value == 3.0
    assert changes["OnwardEvent"].duration.value == 2.5
    assert changes["CutInEvent"].distance is None

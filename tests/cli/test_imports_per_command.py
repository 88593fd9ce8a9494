"""A command imports the libraries its own work needs and no others (issue 31: start-up).

Each command runs in a fresh interpreter, as `sceml` runs it, and reports which of the heavy
libraries it imported; their costs are in docs/performance.md. Not timed: an import that
creeps back fails here, whatever the machine's speed.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("matplotlib", "scipy", "jinja2", "graphviz", "yaml", "shapely", "numpy", "xmlschema")

SCRIPT = """
import json, sys
from sceml.cli import cli
try:
    cli(sys.argv[1:])
except SystemExit as done:
    if done.code not in (0, None):
        raise
print(json.dumps(sorted(m for m in {heavy!r} if m in sys.modules)))
"""


def _imported(tmp_path: Path, *arguments: str, watched: tuple[str, ...] = HEAVY) -> list[str]:
    ran = subprocess.run(
        [sys.executable, "-c", SCRIPT.format(heavy=watched), *arguments],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        check=True,
    )
    listed: list[str] = json.loads(ran.stdout.splitlines()[-1])
    return listed


def test_validate_reads_the_map_with_nothing_heavy(tmp_path: Path) -> None:
    # UIS1 names the intersection map: its clothoids are sampled and projected onto in plain
    # floats (sceml.maps.planview), without numpy.
    uis1 = ROOT / "examples" / "uis1-concrete.xmi"
    watched = (*HEAVY, "sceml.maps.roadmap")  # the map is read
    assert _imported(tmp_path, "validate", str(uis1), watched=watched) == ["sceml.maps.roadmap"]


def test_validate_expands_module_uses_without_extracting_or_the_library_listing(
    tmp_path: Path,
) -> None:
    # UIS2 uses a library module: validation expands it (sceml.modules.expansion) and needs
    # neither extraction, the library listing with the scenario builder, nor the store.
    watched = (
        "sceml.modules.expansion",
        "sceml.modules.extract",
        "sceml.modules.library",
        "sceml.modules.store",
        "sceml.model.build",
    )
    uis2 = ROOT / "examples" / "uis2-concrete.xmi"
    assert _imported(tmp_path, "validate", str(uis2), watched=watched) == [
        "sceml.modules.expansion"
    ]


@pytest.mark.parametrize("example", ["uis1-concrete.xmi", "uis2-concrete.xmi"])
def test_simulate_draws_its_page_without_matplotlib_or_graphviz(
    tmp_path: Path, example: str
) -> None:
    # The page is SVG written by hand from a Jinja template; numpy carries the run.
    imported = _imported(tmp_path, "simulate", str(ROOT / "examples" / example), "-o", "p.html")
    assert imported == ["jinja2", "numpy"]
    assert (tmp_path / "p.html").read_text().startswith("<!DOCTYPE html>")


def test_the_map_view_still_draws_with_matplotlib(tmp_path: Path) -> None:
    uis2 = ROOT / "examples" / "uis2-concrete.xmi"
    imported = _imported(tmp_path, "render", str(uis2), "--view", "map", "-o", "m.svg")
    assert "matplotlib" in imported
    assert (tmp_path / "m.svg").read_bytes().startswith(b"<?xml")

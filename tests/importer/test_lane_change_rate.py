"""A lane change given by its lateral rate (`dynamicsDimension="rate"`, the peak lateral speed)
is as long as players make it: `peak factor × lane width / rate` seconds (ALKS 4.4.x and 4.5.x,
whose cut-ins and cut-outs at 2 m/s were read as 2 s: 33 m instead of 45 m, 0.97 m off).

`files/lane-change-rate.xosc` is written by hand on lanes 3.5 m wide at 20 m/s; esmini 3.6
plays its changes from 2.0 s to 4.15 s and from 8.0 s to 8.95 s, and its re-export the same."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import scemlmodel as scm
from sceml.export import export_to_file
from sceml.importer import import_file
from sceml.model import params

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "lane-change-rate.xosc"


def distances(scenario: scm.Scenario) -> dict[str, float]:
    return {
        str(n.name): params.concrete(n, "distance")
        for n in scenario.nodes
        if isinstance(n, scm.LaneChange)
    }


def test_the_rate_gives_the_time_players_take_over_the_lane_width() -> None:
    # Sinusoidal: steepest at pi/2 of the mean slope; linear: the mean slope. As a distance at
    # 20 m/s, one step (0.05 s) shorter, as for a change given in time.
    assert distances(import_file(SOURCE).scenario) == pytest.approx(
        {"Left": 20 * (math.pi / 2 * 3.5 / 2.5 - 0.05), "Right": 20 * (3.5 / 3.5 - 0.05)}
    )


def test_the_export_imports_back_as_the_same_scenario(tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / SOURCE.name
    export_to_file(first, exported, version="1.1", source_path=SOURCE)
    # The file sets no environment; the export writes SceML's default one, which reads back.
    first.nodes[0].environment = scm.Environment()
    same(first, import_file(exported, allow=[FILES]).scenario)

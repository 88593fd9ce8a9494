"""A StopTrigger without a time limit: the original runs until it holds, however late, so the
import gives it a maximum duration of 1200 s and not SceML's default of 60 s (`acc-toggle`
ended at 60.05 s instead of 117.8 s, `cut-in_sloppy` at 60.05 s instead of 218.65 s).

`files/stop-without-time-limit.xosc` is written by hand; esmini 3.6 plays it to 97.0 s (Brake
runs from 90.0 s to 94.95 s, the stop holds 2 s later). Every expectation is read off the file.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

import scemlmodel as scm
from sceml.export import build_xosc, export_to_file
from sceml.importer import import_file
from sceml.importer.ending import UNLIMITED_RUN
from sceml.model import params
from sceml.simulate import simulate
from sceml.simulate.run import END_NODE

FILES = Path(__file__).parent / "files"
SOURCE = FILES / "stop-without-time-limit.xosc"


@pytest.fixture(scope="module")
def imported() -> scm.Scenario:
    return import_file(SOURCE).scenario


def stop_tests(document: etree._Element) -> list[list[str]]:
    """Each StopTrigger group as what it tests: `state:<element>+delay` or `time>v`."""
    read = []
    for group in document.iterfind("Storyboard/StopTrigger/ConditionGroup"):
        tests = []
        for condition in group.iterfind("Condition"):
            state = condition.find(".//StoryboardElementStateCondition")
            clock = condition.find(".//SimulationTimeCondition")
            if state is not None:
                delay = float(condition.get("delay"))
                tests.append(f"state:{state.get('storyboardElementRef')}+{delay:g}")
            elif clock is not None:
                tests.append(f"time>{float(clock.get('value')):g}")
        read.append(sorted(tests))
    return sorted(read)


def test_the_maximum_duration_is_no_limit_in_practice(imported: scm.Scenario) -> None:
    root = imported.nodes[0]
    assert params.concrete(root, "maxDuration") == 1200.0 == UNLIMITED_RUN
    report = import_file(SOURCE).report
    assert any("no SimulationTime limit" in e.message for e in report.entries)


def test_the_preview_ends_when_the_stop_holds_not_at_60_s(imported: scm.Scenario) -> None:
    run = simulate(imported, SOURCE)
    assert run.end_reason.startswith(END_NODE)
    # Brake 90 s to 95 s (5 m/s at 1 m/s²), then the stop's 2 s.
    assert run.end_time == pytest.approx(97.0, abs=0.1)


def test_the_export_stops_on_the_brake_and_only_then_on_the_limit(
    imported: scm.Scenario,
) -> None:
    document = build_xosc(imported, version="1.1", source_path=SOURCE).tree.getroot()
    assert stop_tests(document) == [["state:Brake+2"], ["time>1200"]]


def test_the_export_imports_back_as_the_same_scenario(tmp_path: Path, same) -> None:
    first = import_file(SOURCE).scenario
    exported = tmp_path / SOURCE.name
    export_to_file(first, exported, version="1.1", source_path=SOURCE)
    # The file sets no environment; the export writes SceML's default one, which reads back.
    first.nodes[0].environment = scm.Environment()
    same(first, import_file(exported, allow=[FILES]).scenario)

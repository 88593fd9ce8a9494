"""The preview beside recorded esmini runs: it agrees with today's, not with the old exports'."""

from __future__ import annotations

from pathlib import Path

import pytest

from sceml.model.loading import load_scenario
from sceml.players import esmini
from sceml.players.check import check_scenario_run
from sceml.players.compare import POSITION_AGREEMENT, START_AGREEMENT, compare
from sceml.simulate import simulate

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "examples"


def model(name: str) -> Path:
    if name.endswith("-concrete"):
        return EXAMPLES / f"{name}.xmi"
    return HERE / "scenarios" / f"{name}.xmi"


def comparison(stem: str, scenario: str, recording):  # type: ignore[no-untyped-def]
    log, trace = recording(stem)
    run = esmini.read(log, trace)
    path = model(scenario)
    report = check_scenario_run(path, run)
    return compare(simulate(load_scenario(path).root, path), report, run)


@pytest.mark.parametrize(
    "stem",
    [
        "overtaking-concrete-1.3",
        "uis2-concrete-1.0",
        "follow-in-turn-1.3",
        "turn-while-speeding-1.0",
        "longitudinal-1.0",
        "junction-1.3",
        "stop-on-arrival-1.3",
    ],
)
def test_the_preview_agrees_with_esmini(stem: str, recording) -> None:  # type: ignore[no-untyped-def]
    result = comparison(stem, stem.rsplit("-", 1)[0], recording)
    assert result.worst_start <= START_AGREEMENT + 1e-9, result
    assert result.worst_position <= POSITION_AGREEMENT, result
    assert result.same_end and result.agrees


def test_the_preview_disagrees_with_a_run_of_the_old_export(recording) -> None:  # type: ignore[no-untyped-def]
    # The old DriveDistance finished at once: the Stop came 2.5 s early, 20 m short.
    result = comparison("drive-after-moving-before-issue-25-1.3", "drive-after-moving", recording)
    assert not result.agrees
    assert result.worst_start == pytest.approx(2.5)
    assert result.worst_start_node == "Stop_1"

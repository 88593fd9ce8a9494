"""`explore` on every executor: the same seed gives the same files, whichever runs the batches.

One `distributed.LocalCluster` with two worker processes serves the module.
"""

from __future__ import annotations

import shutil
from collections.abc import Generator, Iterator, Sequence
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner
from conftest import EXAMPLES
from distributed import LocalCluster

from sceml.cli import cli
from sceml.executors import EXECUTORS, LocalExecutor, Outcome
from sceml.explore import explore
from sceml.explore.workers import make_search_payload, setup_search, simulate_chunk
from sceml.levels.space import parameter_space
from sceml.model.loading import load_scenario
from sceml.simulate import Run

UIS1 = EXAMPLES / "uis1-logical.xmi"


@pytest.fixture(scope="module")
def cluster() -> Iterator[LocalCluster]:
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as started:
        yield started


def _explore(out: Path, *extra: str) -> None:
    arguments = ["explore", str(UIS1), "--budget", "24", "--seed", "5", "--top", "2"]
    result = CliRunner().invoke(cli, [*arguments, "-o", str(out), *extra])
    assert result.exit_code == 0, result.output


def _files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_every_executor_writes_the_same_files_from_the_same_seed(
    tmp_path: Path, cluster: LocalCluster
) -> None:
    _explore(tmp_path / "local", "--executor", "local")
    _explore(tmp_path / "processes", "--executor", "processes", "--workers", "2")
    _explore(tmp_path / "dask", "--executor", "dask", "--scheduler", cluster.scheduler_address)
    local = _files(tmp_path / "local")
    assert {"runs.csv", "uis1_critical_02.xosc"} <= set(local)
    assert _files(tmp_path / "processes") == local
    assert _files(tmp_path / "dask") == local


class _Shuffled(LocalExecutor):
    """Runs in this process, reports the chunks last first and the second one as lost."""

    def map_unordered(
        self, setup: Any, task: Any, payload: Any, items: Sequence[Any]
    ) -> Generator[Outcome[Any], None, None]:
        done = list(super().map_unordered(setup, task, payload, items))
        for outcome in reversed(done):
            yield Outcome(1, error="KilledWorker") if outcome.item == 1 else outcome


def test_runs_keep_the_order_of_their_candidates_not_of_their_results() -> None:
    scenario = load_scenario(UIS1).root
    plain = explore(scenario, UIS1, metric="min-ttc", budget=20, seed=3)
    shuffled = explore(scenario, UIS1, metric="min-ttc", budget=20, seed=3, executor=_Shuffled())
    assert [e.index for e in shuffled.evaluations] == list(range(20))
    lost = [e for e in shuffled.evaluations if e.run is None]
    assert lost and all(e.error == "lost: KilledWorker" for e in lost)
    kept = [(e.values, e.score) for e in shuffled.evaluations[: lost[0].index]]
    assert kept == [(e.values, e.score) for e in plain.evaluations[: lost[0].index]]


def test_a_worker_needs_only_the_payload_not_the_callers_files(examples_copy: Path) -> None:
    logical = examples_copy / "uis1-logical.xmi"
    scenario = load_scenario(logical).root
    paths = parameter_space(scenario).paths
    payload = make_search_payload(scenario, logical, paths, step=0.05)
    shutil.rmtree(examples_copy)
    shutil.rmtree(examples_copy.parent / "maps")  # the map is shipped too
    state = setup_search(payload)
    [run] = simulate_chunk(state, ((5.0, 8.0, 12.0, 5.0),))
    assert isinstance(run, Run), run
    assert run.pair("ego", "bike").min_distance >= 0


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--executor", "threads"], "'threads' is not one of"),
        (["--scheduler", "tcp://127.0.0.1:1"], "needs the dask executor"),
    ],
)
def test_a_bad_executor_choice_is_a_usage_error_and_writes_nothing(
    tmp_path: Path, extra: list[str], message: str
) -> None:
    out = tmp_path / "out"
    result = CliRunner().invoke(
        cli, ["explore", str(UIS1), "--budget", "4", "-o", str(out), *extra]
    )
    assert result.exit_code == 2, result.output
    assert message in result.output
    assert not out.exists()


def test_the_executors_are_those_of_sample() -> None:
    result = CliRunner().invoke(cli, ["explore", "--help"])
    assert all(kind in result.output for kind in EXECUTORS)
    assert "[default: local]" in result.output

"""Workers that draw their own samples' values: the same values, files and records as the caller's.

`sceml sample` hands grid and random runs to the workers as indices (`sampling.IndexDraw`);
each worker draws the values of its chunk. These tests hold those values to the ones the caller
drew before (bit for bit), and to numpy's documented stream for a random sample.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from sceml.executors import open_executor
from sceml.levels import batch
from sceml.levels.batch import BatchConfig, run_batch
from sceml.levels.paths import LevelError
from sceml.levels.sampling import IndexDraw, Plan, design, index_draw, plan_for, values_at
from sceml.levels.space import ParameterSpace, parameter_space
from sceml.model.loading import load_scenario

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
UIS2 = EXAMPLES / "uis2-logical.xmi"


@pytest.fixture(scope="module")
def space() -> ParameterSpace:
    return parameter_space(load_scenario(UIS2).root)


def _files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir()) if p.is_file()}


def _by_index(records: list) -> dict[int, tuple]:  # type: ignore[type-arg]
    return {r.index: (r.status, r.values, r.files, r.reason) for r in records}


@pytest.mark.parametrize(("strategy", "n"), [("random", 300), ("grid", None)])
def test_chunks_drawn_apart_are_the_whole_design_bit_for_bit(
    space: ParameterSpace, strategy: str, n: int | None
) -> None:
    plan = plan_for(space, strategy, n, 9)  # type: ignore[arg-type]
    whole = design(space, plan)
    draw = IndexDraw(space, plan)
    pieces = [draw.rows(np.arange(start, min(start + 7, plan.n))) for start in range(0, plan.n, 7)]
    assert np.concatenate(pieces).tobytes() == whole.tobytes()
    # Out of order and one at a time too: a value depends on its index alone.
    assert draw.rows(np.array([plan.n - 1, 0])).tobytes() == whole[[plan.n - 1, 0]].tobytes()


def test_a_random_sample_is_numpys_spawned_seed_sequence(space: ParameterSpace) -> None:
    # Sample i's uniforms come from SeedSequence(seed).spawn(n)[i], as sampling.py documents;
    # UIS2's sixth parameter is uniform on [1, 2], so its value is 1 + u[5].
    column = 5
    dimension = space.dimensions[column]
    assert (dimension.kind, dimension.low, dimension.high) == ("uniform", 1.0, 2.0)
    seed, n = 42, 50
    children = np.random.SeedSequence(seed).spawn(n)
    expected = [
        1.0 + np.random.default_rng(c).random(len(space.dimensions))[column] for c in children
    ]
    drawn = IndexDraw(space, Plan("random", n, seed)).rows(np.arange(n))[:, column]
    assert drawn.tolist() == expected


def test_a_latin_hypercube_is_not_drawn_by_index(space: ParameterSpace) -> None:
    assert index_draw(space, Plan("lhs", 10, 0)) is None
    with pytest.raises(LevelError, match="as a whole"):
        IndexDraw(space, Plan("lhs", 10, 0))


def test_workers_that_draw_write_the_files_and_records_of_drawn_values(
    tmp_path: Path, space: ParameterSpace
) -> None:
    plan = Plan("random", 40, seed=3)
    indices = np.arange(40)

    def config(name: str) -> BatchConfig:
        return BatchConfig(UIS2, tmp_path / name, space.paths, ("xosc",), stem="uis2")

    given = run_batch(config("given"), indices, values_at(space, plan, indices), workers=2)
    with open_executor("processes", workers=2) as executor:
        drawn = run_batch(
            config("drawn"), indices, IndexDraw(space, plan), executor=executor, chunk_size=6
        )
    assert _files(tmp_path / "drawn") == _files(tmp_path / "given")
    assert _by_index(drawn.records) == _by_index(given.records)
    assert len(drawn.records) == 40


def test_a_lost_chunk_that_its_worker_would_have_drawn_lists_its_values(
    tmp_path: Path, space: ParameterSpace, monkeypatch: pytest.MonkeyPatch
) -> None:
    real = batch.produced_samples

    def lose_the_chunk_with_seven(state: batch.WorkerState, chunk: batch.Chunk) -> Iterator:  # type: ignore[type-arg]
        assert chunk[1] is None  # the chunk carries indices only
        if 7 in chunk[0]:
            raise MemoryError("worker ran out of memory")
        yield from real(state, chunk)

    monkeypatch.setattr(batch, "produced_samples", lose_the_chunk_with_seven)
    plan = Plan("random", 12, seed=5)
    config = BatchConfig(UIS2, tmp_path, space.paths, ("xosc",), stem="uis2")
    with open_executor("local") as executor:
        result = run_batch(
            config, np.arange(12), IndexDraw(space, plan), executor=executor, chunk_size=5
        )
    failed = {r.index: r.values for r in result.records if r.status == "failed"}
    assert sorted(failed) == [5, 6, 7, 8, 9]
    expected = values_at(space, plan, np.arange(5, 10))
    assert [failed[i] for i in range(5, 10)] == [tuple(row) for row in expected.tolist()]

"""Where the search's runs happen: one batch of candidates simulated on any executor.

Workers receive what `sceml sample`'s workers receive (`levels.batch.make_payload`: the bytes
of the logical file and of every module library it reaches, recreated by `setup_worker` under
their absolute paths in a private folder, where the scenario is loaded and flattened into a
`FlatTemplate` once), plus the bytes of the OpenDRIVE map, which the preview reads. A worker
loads the map from its own copy and hands it to the player, so it needs neither the caller's
file system nor a map named by a relative path.

The caller draws every candidate's values (the seed never leaves it) and cuts a batch into
chunks; each task simulates one chunk and returns, per candidate, its `Run` or why it has none.
Results come back in candidate order whatever order the chunks finish in, so every executor
gives the same runs.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path

import scemlmodel as scm

from ..errors import SceMLError
from ..executors import Executor
from ..files.safefiles import read_input, reading_roots
from ..levels.batch import (
    BatchConfig,
    BatchPayload,
    WorkerState,
    make_payload,
    mirrored,
    setup_worker,
)
from ..maps.reader import MapError
from ..maps.reference import map_reference
from ..model.graph import root_node
from ..simulate import Run, simulate

#: What became of one candidate: its run, or the message of the error that stopped it.
Result = Run | str
#: The values of the candidates one task simulates, in the space's path order.
Chunk = tuple[tuple[float, ...], ...]


@dataclass(frozen=True)
class SearchPayload:
    """What every worker receives: the batch payload (with the map's bytes among its inputs),
    where the map was on the caller, and the time step."""

    batch: BatchPayload
    map_file: str | None
    step: float


def make_search_payload(
    logical: scm.Scenario,
    logical_file: str | Path,
    paths: tuple[str, ...],
    *,
    step: float,
    allow: tuple[Path, ...] = (),
) -> SearchPayload:
    """The payload of a search: the logical file, its libraries and its map, as bytes."""
    file = Path(logical_file)
    config = BatchConfig(logical=file, out_dir=file.parent, paths=paths, formats=(), allow=allow)
    batch = make_payload(config)
    root = root_node(logical)
    roots = reading_roots(file, allow)
    reference = map_reference(root.map if root is not None else None, file, roots)
    if reference is None or reference.path is None or not reference.path.is_file():
        # No map, a simulator town, or a file that is not there: each run says so, as it would
        # here, because the worker resolves the name itself.
        return SearchPayload(batch, None, step)
    road = (
        str(reference.path),
        read_input(reference.path, roots=roots, what="map", error=MapError),
    )
    inputs = tuple(sorted({*batch.inputs, road}))
    return SearchPayload(replace(batch, inputs=inputs), road[0], step)


@dataclass(frozen=True)
class SearchState:
    """A worker's copy of the inputs (and its FlatTemplate), and where its copy of the map is."""

    inputs: WorkerState
    map_path: Path | None
    step: float


def setup_search(payload: SearchPayload) -> SearchState:
    """Recreate the payload's files in a private folder and build the template on them."""
    inputs = setup_worker(payload.batch)
    where = None if payload.map_file is None else mirrored(inputs.folder, Path(payload.map_file))
    return SearchState(inputs, where, payload.step)


def simulate_chunk(state: SearchState, chunk: Chunk) -> list[Result]:
    """Each candidate's run, or why it has none, in the chunk's order."""
    return [_simulate(state, values) for values in chunk]


def _simulate(state: SearchState, values: tuple[float, ...]) -> Result:
    from ..maps import load_map  # numpy and the clothoids, only where runs happen

    worker = state.inputs.worker
    try:
        road_map = None if state.map_path is None else load_map(state.map_path)
        return simulate(
            worker.template.fill(values), worker.config.logical, step=state.step, road_map=road_map
        )
    except SceMLError as error:
        return error.message


def run_candidates(
    executor: Executor,
    payload: SearchPayload,
    candidates: Sequence[tuple[float, ...]],
    progress: Callable[[int], None] | None = None,
) -> list[Result]:
    """Every candidate's result, in the candidates' order, simulated on `executor`.

    A chunk whose task failed (e.g. its worker was lost beyond the executor's retries) gives
    each of its candidates the message `lost: <why>`. Closing early (Ctrl-C) cancels the rest.
    """
    size = chunk_size(len(candidates), executor)
    chunks = [tuple(candidates[i : i + size]) for i in range(0, len(candidates), size)]
    done: list[list[Result]] = [[] for _ in chunks]
    outcomes = executor.map_unordered(setup_search, simulate_chunk, payload, chunks)
    try:
        for outcome in outcomes:
            chunk = chunks[outcome.item]
            if outcome.error is None and outcome.result is not None:
                done[outcome.item] = outcome.result
            else:
                done[outcome.item] = [f"lost: {outcome.error or 'no result'}"] * len(chunk)
            if progress is not None:
                progress(len(chunk))
    finally:
        outcomes.close()  # cancels what has not run yet
    return [result for results in done for result in results]


def chunk_size(count: int, executor: Executor) -> int:
    """Candidates per task: about four tasks per worker thread, for balance.

    A search's batches are small (a tenth of the budget) and a run takes milliseconds, about
    what a Dask task costs, so candidates travel in a few chunks rather than one by one.
    """
    return max(1, min(executor.max_chunk, math.ceil(count / (4 * executor.parallelism))))

"""The fast batch path: sample a logical scenario into many concrete files on any executor.

The caller cuts the samples into chunks and hands them to an executor (`sceml.executors`:
in-process, a process pool or a Dask cluster). A chunk carries its samples' values, computed
by the caller (a Latin hypercube is one joint design), or only their indices when each sample's
values come from its index alone (grid, random: `sampling.IndexDraw`); the worker then draws
them, so no worker waits for the whole run's values. Either way no value depends on which
worker makes the sample or when.

Workers need not share the caller's file system. Each one receives a `BatchPayload`: the run's
configuration and the bytes of every file the logical scenario reads (itself and its module
libraries; the map is not read, only named). It recreates those files under their absolute
paths inside a private temporary folder, so that every path relative to the output (the map's
LogicFile, library references of .xmi files) comes out as it would on the caller. Once per
worker: load the logical scenario, flatten it into a `FlatTemplate`, load the XSD and render
the export once with a placeholder for every sampled number (`SampleXosc`). Per sample: write
its numbers into the template in place (no model copy), run the value checks, fill the
placeholders and check the document against the XSD (in the template's tree, without parsing
the sample). Samples whose values break a rule are skipped with a reason. The first sample of
each worker is also exported in full and compared byte for byte; if they differ, that worker
exports every sample in full.

Who writes depends on the executor. Worker processes on the caller's machine
(`Executor.shares_files`) write their samples' files themselves, so that writing, which costs
about as much as producing a file, runs on every core: each new file is written unnamed in the
output folder and named once complete, and a file that exists already is written under its own
name into a staging folder inside the output folder and renamed into place (`write_staged`);
the task returns only the records. Otherwise (in-process, Dask) workers return file contents
and the caller writes each file atomically (`write_atomically`). Either way a sample's record
is kept only once all its files are written, and a sample the run did not finish (its chunk
lost, or Ctrl-C) has no files when the run returns: the caller removes the staging folder,
and the files that workers wrote for samples whose records never arrived. So the manifest lists
exactly the files the run leaves, and no half-written file is left.
"""

from __future__ import annotations

import shutil
import signal
import tempfile
import threading
import weakref
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import scemlmodel as scm

from ..errors import SaveError, SceMLError
from ..executors import Deferred, Executor, open_executor
from ..files.safefiles import read_input
from ..files.writing import (
    make_folder,
    open_folder,
    remove_folders,
    write_atomically,
    write_staged,
)
from ..model.documents import Document
from ..model.loading import load_scenario, unresolved_references
from ..model.saving import save
from ..xosc.profiles import DEFAULT_VERSION
from .apply import FlatTemplate, copy_scenario, set_level
from .checks import SampleChecker
from .manifest import SampleRecord
from .paths import place_value, resolve, slots
from .sampling import IndexDraw
from .space import parameter_space
from .xosc import SampleXosc, XoscWriter, prepare_export

FORMATS = ("xmi", "xosc")


@dataclass(frozen=True)
class BatchConfig:
    """Where a batch reads from and writes to, and in which formats."""

    logical: Path
    out_dir: Path
    paths: tuple[str, ...]
    formats: tuple[str, ...] = ("xosc",)
    osc_version: str = DEFAULT_VERSION
    stem: str = "sample"
    width: int = 5
    #: More folders the logical scenario's references may reach (see sceml.files.safefiles.reading_roots).
    allow: tuple[Path, ...] = ()

    def file_name(self, index: int, suffix: str) -> str:
        """The output file name of one sample, e.g. `uis2_00417.xosc`."""
        return f"{self.stem}_{index:0{self.width}d}.{suffix}"


@dataclass(frozen=True)
class Produced:
    """One sample's record and the contents of its files, by file name."""

    record: SampleRecord
    files: tuple[tuple[str, bytes], ...] = ()


class Worker:
    """Everything one worker needs to turn sample values into file contents, built once.

    Output paths are computed relative to `config.out_dir`, which also holds the .xmi files
    while they are serialised.
    """

    def __init__(self, config: BatchConfig) -> None:
        self.config = config
        logical = load_scenario(config.logical, allow=config.allow).root
        self.template = FlatTemplate(logical, config.paths)
        self.checker = SampleChecker(self.template)
        self.xosc = None
        self.fast: SampleXosc | None = None
        self.verified = False
        if "xosc" in config.formats:
            self.xosc = XoscWriter(config.logical, config.osc_version)
            # Rendered at the nominal values (midpoints, means): a row the export accepts.
            nominal = {d.path: d.nominal() for d in parameter_space(logical).dimensions}
            probe = [nominal.get(path, 0.0) for path in config.paths]
            self.fast = _fast_path(self.xosc, self.template, config.out_dir / "probe.xosc", probe)
        self.xmi_copy = None
        if "xmi" in config.formats:
            self.xmi_copy = _xmi_working_copy(logical, config.paths)

    def produce(self, index: int, values: Sequence[float]) -> Produced:
        """The files of one sample, or its record saying why it is skipped."""
        row = tuple(float(v) for v in values)
        flat = self.template.fill(row)
        problem = self.checker.problem(flat, row)
        if problem is not None:
            return Produced(SampleRecord(index, row, status="skipped", reason=problem))
        files = []
        if self.xosc is not None:
            name = self.config.file_name(index, "xosc")
            data, problem = self._xosc_bytes(flat, row, name)
            if data is None:
                return Produced(SampleRecord(index, row, status="skipped", reason=problem))
            files.append((name, data))
        if self.xmi_copy is not None:
            name = self.config.file_name(index, "xmi")
            self.xmi_copy.fill(row)
            files.append((name, self._xmi_bytes(self.config.out_dir / name)))
        record = SampleRecord(index, row, files=tuple(name for name, _ in files))
        return Produced(record, tuple(files))

    def run(self, index: int, values: Sequence[float]) -> SampleRecord:
        """Produce one sample and write its files into `config.out_dir`."""
        produced = self.produce(index, values)
        return write_sample(self.config.out_dir, produced)

    def _xosc_bytes(
        self, flat: scm.Scenario, row: Sequence[float], name: str
    ) -> tuple[bytes | None, str]:
        assert self.xosc is not None
        if self.fast is not None and not self.verified:
            # One full export per worker confirms that substitution reproduces it exactly.
            self.verified = True
            if not self.fast.matches(flat, row):
                self.fast = None
        if self.fast is not None and self.fast.covers(row):
            texts = self.fast.texts(row)
            problem = self.fast.schema_problem(row, texts)
            return (None, problem) if problem else (self.fast.render(row, texts), "")
        try:  # the full export, which needs the file's path (for paths relative to it)
            return self.xosc.document(flat, self.config.out_dir / name).data, ""
        except SceMLError as error:  # ExportError, or InvalidOutputError for an XSD failure
            return None, f"export: {error.message}"

    def _xmi_bytes(self, target: Path) -> bytes:
        assert self.xmi_copy is not None
        # save writes references relative to the file it saves, so it saves where the file
        # belongs (the worker's copy of the output folder) and the bytes are read back.
        save(self.xmi_copy.scenario, target, origin=self.config.logical)
        try:
            return target.read_bytes()
        finally:
            target.unlink()


def write_sample(
    folder: Path, produced: Produced, staging: Path | None = None, handle: int | None = None
) -> SampleRecord:
    """Write one sample's files atomically (through `staging`, if given, else each through a
    temporary file); if that is cut short, none of them stays. `handle`: an open descriptor of
    `folder` (`open_folder`), for the staged writes."""
    written: list[Path] = []
    try:
        for name, data in produced.files:
            path = folder / name
            if staging is None:
                write_atomically(path, data)
            else:
                write_staged(path, data, staging, handle)
            written.append(path)
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        raise
    return produced.record


def _fast_path(
    writer: XoscWriter, template: FlatTemplate, probe: Path, row: Sequence[float]
) -> SampleXosc | None:
    try:
        fast = SampleXosc(writer, template, probe, row)
    except SceMLError:
        return None  # the per-sample export will report why
    return fast if fast.usable else None


class _XmiCopy:
    """A concrete (unflattened) copy of the logical scenario whose sampled Values are rewritten."""

    def __init__(self, scenario: scm.Scenario, targets: list[scm.Value]) -> None:
        self.scenario = scenario
        self.targets = targets

    def fill(self, row: Sequence[float]) -> None:
        for target, number in zip(self.targets, row, strict=True):
            target.value = float(number)


def _xmi_working_copy(logical: scm.Scenario, paths: Sequence[str]) -> _XmiCopy:
    working = copy_scenario(logical)
    known = slots(working)
    targets = []
    for path in paths:
        slot = resolve(working, path, known)
        place_value(slot, 0.0)
        targets.append(slot.held())
    set_level(working, "concrete")
    return _XmiCopy(working, targets)


@dataclass(frozen=True)
class BatchPayload:
    """What a worker receives: the run's configuration, and the input files as bytes.

    Paths in `config` are absolute, as the caller resolved them; `inputs` maps each such path
    of a file the logical scenario reads to its contents. `staging` is set when the workers
    write the files themselves: the folder inside `config.out_dir` they stage them in. `draw`
    is set when each chunk carries indices only, and a worker draws their values.
    """

    config: BatchConfig
    inputs: tuple[tuple[str, bytes], ...]
    staging: Path | None = None
    #: Set when the workers draw their samples' values from the indices (chunks carry none).
    draw: IndexDraw | None = None


def make_payload(config: BatchConfig) -> BatchPayload:
    """The payload of a run: the logical scenario and every module library it reaches."""
    config = replace(
        config,
        logical=config.logical.resolve(),
        out_dir=config.out_dir.resolve(),
        allow=tuple(p.resolve() for p in config.allow),
    )
    document = load_scenario(config.logical, allow=config.allow)
    files: set[Path] = set()
    while (found := _loaded_files(document)) != files:  # a library may use another's modules
        files = found
        for resource in list(document.resource_set.resources.values()):
            for root in resource.contents:
                # Resolving is the point; a broken reference fails in the worker as it would here.
                list(unresolved_references(root))
    # Read again by the reading rule: the file may have been swapped for a FIFO since it loaded.
    inputs = tuple(sorted((str(path), read_input(path)) for path in files))
    return BatchPayload(config, inputs)


def _loaded_files(document: Document) -> set[Path]:
    found = set()
    for resource in document.resource_set.resources.values():
        path = Path(resource.uri.normalize()).resolve()
        if path.is_file():
            found.add(path)
    return found


def mirrored(root: Path, path: Path) -> Path:
    """Where a caller's absolute path lives inside a worker's private folder."""
    return root.joinpath(*path.parts[1:])


class WorkerState:
    """A worker's private copy of the inputs and the `Worker` built on it.

    The folder goes when the state does (when its run ends, or the worker process exits).
    """

    def __init__(self, worker: Worker, folder: Path, payload: BatchPayload | None = None) -> None:
        self.worker = worker
        self.folder = folder
        #: The payload it was made from: where the caller's output folder and staging are.
        self.payload = payload
        weakref.finalize(self, shutil.rmtree, folder, ignore_errors=True)


def setup_worker(payload: BatchPayload) -> WorkerState:
    """Recreate the payload's files in a private folder and build a Worker on them."""
    root = Path(tempfile.mkdtemp(prefix="sceml-worker-")).resolve()
    try:
        for name, data in payload.inputs:
            target = mirrored(root, Path(name))
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
        config = replace(
            payload.config,
            logical=mirrored(root, payload.config.logical),
            out_dir=mirrored(root, payload.config.out_dir),
            allow=(root,),
        )
        config.out_dir.mkdir(parents=True, exist_ok=True)
        return WorkerState(Worker(config), root, payload)
    except BaseException:
        shutil.rmtree(root, ignore_errors=True)
        raise


#: The indices of some samples and their values, or None when the worker draws them.
Chunk = tuple[NDArray[np.int64], NDArray[np.float64] | None]


def chunk_rows(payload: BatchPayload | None, chunk: Chunk) -> NDArray[np.float64]:
    """The values of a chunk's samples: those it carries, or drawn from its indices."""
    indices, rows = chunk
    if rows is not None:
        return rows
    assert payload is not None and payload.draw is not None  # set whenever chunks carry none
    return payload.draw.rows(indices)


def produce_chunk(state: WorkerState, chunk: Chunk) -> list[Produced]:
    """The files of every sample of a chunk."""
    return list(produced_samples(state, chunk))


def produced_samples(state: WorkerState, chunk: Chunk) -> Iterator[Produced]:
    """The files of each sample of a chunk, one sample at a time."""
    indices, rows = chunk[0], chunk_rows(state.payload, chunk)
    for index, row in zip(indices, rows, strict=True):
        yield state.worker.produce(int(index), row)


@dataclass(frozen=True)
class Written:
    """What a worker that writes returns for a chunk: the records of the samples it finished,
    and, if a file could not be written, that SaveError's message and file (it stopped there)."""

    records: tuple[SampleRecord, ...]
    error: tuple[str, str | None] | None = None


def write_chunk(state: WorkerState, chunk: Chunk) -> Written:
    """Produce every sample of a chunk and write its files into the caller's output folder.

    Each sample is written as soon as it is produced, not after the whole chunk (125 samples
    for 2,000 on two workers): the run's first file comes one sample after the workers start.
    If the chunk fails part-way, the caller removes the files of its samples (`_collect`).
    """
    assert state.payload is not None and state.payload.staging is not None
    folder, staging = state.payload.config.out_dir, state.payload.staging
    records = []
    with open_folder(folder) as handle:
        for produced in produced_samples(state, chunk):
            try:
                records.append(write_sample(folder, produced, staging, handle))
            except SaveError as error:  # sent back as data: the caller reports it as its own
                return Written(tuple(records), (error.message, error.file))
    return Written(tuple(records))


@dataclass
class BatchResult:
    """The records of a run, in the order samples finished, and whether Ctrl-C cut it short."""

    records: list[SampleRecord]
    interrupted: bool = False


#: Called with the number of samples just finished (written, skipped or failed).
Progress = Callable[[int], None]


#: The sample values, one row per index; or a function that computes them: the workers then
#: start (and set up) while the caller computes them; or how each worker draws the values of
#: its own samples (chunks then carry indices only).
Rows = NDArray[np.float64] | Callable[[], NDArray[np.float64]] | IndexDraw


def run_batch(
    config: BatchConfig,
    indices: NDArray[np.int64],
    rows: Rows,
    *,
    executor: Executor | None = None,
    workers: int | None = None,
    chunk_size: int | None = None,
    progress: Progress | None = None,
) -> BatchResult:
    """Produce every sample's files on `executor` (default: a local pool of `workers`
    processes) and write them into `config.out_dir`.

    A sample whose chunk was lost (its task failed, or its worker died beyond the executor's
    retries) is recorded as `failed` and has no files. Ctrl-C stops the run: the remaining
    tasks are cancelled and the result, marked interrupted, holds the samples written so far.
    A file that cannot be written is a SaveError naming it, whichever process wrote it.
    When the run fails, the output folder, if it made it, is removed again unless files were
    written.
    """
    created = make_folder(config.out_dir)
    try:
        payload = make_payload(config)
        if isinstance(rows, IndexDraw):
            payload = replace(payload, draw=rows)
        if executor is not None:
            return _run(payload, indices, rows, executor, chunk_size, progress)
        with open_executor("processes", workers=workers) as own:
            return _run(payload, indices, rows, own, chunk_size, progress)
    except BaseException:
        remove_folders(created)
        raise


def _run(
    payload: BatchPayload,
    indices: NDArray[np.int64],
    rows: Rows,
    executor: Executor,
    chunk_size: int | None,
    progress: Progress | None,
) -> BatchResult:
    if not executor.shares_files:
        return _collect(payload, indices, rows, executor, chunk_size, progress)
    staging = _staging_folder(payload.config.out_dir)
    try:
        return _collect(
            replace(payload, staging=staging), indices, rows, executor, chunk_size, progress
        )
    finally:
        with _interrupt_deferred():
            shutil.rmtree(staging, ignore_errors=True)  # empty, unless a worker died mid-file


def _staging_folder(out_dir: Path) -> Path:
    """A new staging folder inside the output folder (on its file system, for the renames)."""
    try:
        return Path(tempfile.mkdtemp(prefix=".sceml-staging-", dir=out_dir))
    except OSError as error:
        raise SaveError(f"cannot write: {error.strerror or error}", file=out_dir) from None


def _collect(
    payload: BatchPayload,
    indices: NDArray[np.int64],
    rows: Rows,
    executor: Executor,
    chunk_size: int | None,
    progress: Progress | None,
) -> BatchResult:
    """Run every chunk; write what comes back (unless the workers wrote it) and keep records."""
    size = chunk_size or _chunk_size(len(indices), executor)
    chunks: list[Chunk] = []

    def make() -> list[Chunk]:
        values = None if isinstance(rows, IndexDraw) else rows() if callable(rows) else rows
        chunks.extend(_chunks(indices, values, size))
        return chunks

    result = BatchResult([])
    unfinished = set(range(-(-len(indices) // size)))
    task: Callable[[WorkerState, Chunk], list[Produced] | Written] = (
        write_chunk if payload.staging is not None else produce_chunk
    )
    if executor.inherits_imports and "xosc" in payload.config.formats:
        prepare_export(payload.config.osc_version)  # once here instead of once per worker
    outcomes = executor.map_unordered(setup_worker, task, payload, Deferred(len(unfinished), make))
    try:
        for outcome in outcomes:
            done = outcome.result
            if outcome.error is not None or done is None:
                lost = chunks[outcome.item]
                result.records.extend(_failed(lost, payload, outcome.error or "no result"))
            elif isinstance(done, Written):
                result.records.extend(done.records)
                if done.error is not None:
                    raise SaveError(done.error[0], file=done.error[1])
                unfinished.discard(outcome.item)
            else:
                with _interrupt_deferred():
                    for produced in done:
                        result.records.append(write_sample(payload.config.out_dir, produced))
                unfinished.discard(outcome.item)
            if progress is not None:
                progress(len(chunks[outcome.item][0]))
    except KeyboardInterrupt:
        result.interrupted = True
    finally:
        outcomes.close()  # cancels what has not started, and waits for what has
    if payload.staging is not None:
        # Workers may have written files of samples whose records never came: those of a chunk
        # still running at Ctrl-C, or the part of a lost chunk done before its worker died.
        with _interrupt_deferred():
            for number in sorted(unfinished & set(range(len(chunks)))):
                _remove_files_of(payload.config, chunks[number][0])
    return result


def _remove_files_of(config: BatchConfig, indices: NDArray[np.int64]) -> None:
    for index in indices:
        for suffix in config.formats:
            (config.out_dir / config.file_name(int(index), suffix)).unlink(missing_ok=True)


@contextmanager
def _interrupt_deferred() -> Iterator[None]:
    """Hold Ctrl-C until the block is done, then raise it.

    A KeyboardInterrupt between creating a temporary file and renaming it would leave the
    temporary file behind; a chunk's files take milliseconds, so Ctrl-C waits for them. So does
    a second Ctrl-C for the clean-up after the first.
    Only the main thread receives signals; elsewhere this does nothing.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    received: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda number, _frame: received.append(number))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if received and callable(previous):
            previous(signal.SIGINT, None)  # Python's own handler raises KeyboardInterrupt


def _chunk_size(count: int, executor: Executor) -> int:
    return max(1, min(executor.max_chunk, count // (executor.parallelism * 8) or 1))


def _chunks(indices: NDArray[np.int64], rows: NDArray[np.float64] | None, size: int) -> list[Chunk]:
    return [
        (indices[i : i + size], None if rows is None else rows[i : i + size])
        for i in range(0, len(indices), size)
    ]


def _failed(chunk: Chunk, payload: BatchPayload, error: str) -> list[SampleRecord]:
    indices, rows = chunk[0], chunk_rows(payload, chunk)
    return [
        SampleRecord(int(i), tuple(float(v) for v in row), status="failed", reason=f"lost: {error}")
        for i, row in zip(indices, rows, strict=True)
    ]

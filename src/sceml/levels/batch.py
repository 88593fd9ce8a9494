"""The fast batch path: sample a logical scenario into many concrete files on every core.

Per worker process, once: load the logical scenario, flatten it into a `FlatTemplate`, load the
XSD, and render the export once with a placeholder for every sampled number (`SampleXosc`).
Per sample: write its numbers into the template in place (no model copy), run the value
checks, fill the placeholders to get the document text, parse it once, validate the tree
against the XSD and write the text atomically. Samples whose values break a rule are skipped
and reported, not written. The first sample of each worker is also exported in full and
compared byte for byte; if they differ, that worker exports every sample in full.

The parent process computes every sample's values (cheap arrays) and hands them out in
chunks, so workers never need the sampling state and LHS designs stay whole.
"""

from __future__ import annotations

import multiprocessing
import os
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import scemlmodel as scm

from .. import io
from ..errors import SceMLError
from .apply import FlatTemplate, copy_scenario, set_level
from .checks import SampleChecker
from .manifest import SampleRecord
from .paths import place_value, resolve, slots
from .xosc import SampleXosc, XoscWriter

FORMATS = ("xmi", "xosc")


@dataclass(frozen=True)
class BatchConfig:
    """Where a batch reads from and writes to, and in which formats."""

    logical: Path
    out_dir: Path
    paths: tuple[str, ...]
    formats: tuple[str, ...] = ("xosc",)
    osc_version: str = "1.3"
    stem: str = "sample"
    width: int = 5
    #: More folders the logical scenario's references may reach (see io.reading_roots).
    allow: tuple[Path, ...] = ()

    def file_name(self, index: int, suffix: str) -> str:
        """The output file name of one sample, e.g. `uis2_00417.xosc`."""
        return f"{self.stem}_{index:0{self.width}d}.{suffix}"


class Worker:
    """Everything one process needs to turn sample values into files, built once."""

    def __init__(self, config: BatchConfig) -> None:
        self.config = config
        logical = io.load_scenario(config.logical, allow=config.allow).root
        self.template = FlatTemplate(logical, config.paths)
        self.checker = SampleChecker(self.template)
        self.xosc = None
        self.fast: SampleXosc | None = None
        self.verified = False
        if "xosc" in config.formats:
            self.xosc = XoscWriter(config.logical, config.osc_version)
            self.fast = _fast_path(self.xosc, self.template, config.out_dir / "probe.xosc")
        self.xmi_copy = None
        if "xmi" in config.formats:
            self.xmi_copy = _xmi_working_copy(logical, config.paths)

    def run(self, index: int, values: Sequence[float]) -> SampleRecord:
        """Produce the files of one sample, or say why it is skipped."""
        row = tuple(float(v) for v in values)
        flat = self.template.fill(row)
        problem = self.checker.problem(flat, row)
        if problem is not None:
            return SampleRecord(index, row, status="skipped", reason=problem)
        files = []
        if self.xosc is not None:
            name = self.config.file_name(index, "xosc")
            problem = self._write_xosc(flat, row, self.config.out_dir / name)
            if problem is not None:
                return SampleRecord(index, row, status="skipped", reason=problem)
            files.append(name)
        if self.xmi_copy is not None:
            name = self.config.file_name(index, "xmi")
            self.xmi_copy.fill(row)
            io.save(self.xmi_copy.scenario, self.config.out_dir / name, origin=self.config.logical)
            files.append(name)
        return SampleRecord(index, row, files=tuple(files))

    def _write_xosc(self, flat: scm.Scenario, row: Sequence[float], target: Path) -> str | None:
        assert self.xosc is not None
        if self.fast is not None and not self.verified:
            # One full export per worker confirms that substitution reproduces it exactly.
            self.verified = True
            if not self.fast.matches(flat, row):
                self.fast = None
        if self.fast is not None:
            return self.fast.write(row, target)
        return self.xosc.write(flat, target)


def _fast_path(writer: XoscWriter, template: FlatTemplate, probe: Path) -> SampleXosc | None:
    try:
        fast = SampleXosc(writer, template, probe)
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


_WORKER: Worker | None = None


def _initialise(config: BatchConfig) -> None:
    global _WORKER
    _WORKER = Worker(config)


def _run_chunk(chunk: tuple[NDArray[np.int64], NDArray[np.float64]]) -> list[SampleRecord]:
    assert _WORKER is not None, "worker used before its initializer ran"
    indices, rows = chunk
    return [_WORKER.run(int(i), row) for i, row in zip(indices, rows, strict=True)]


def run_batch(
    config: BatchConfig,
    indices: NDArray[np.int64],
    rows: NDArray[np.float64],
    *,
    workers: int | None = None,
    chunk_size: int | None = None,
) -> Iterator[SampleRecord]:
    """Produce every sample's files; records come as samples finish (in no fixed order).

    When it fails, the output folder, if it made it, is removed again unless files were written.
    """
    created = io.make_folder(config.out_dir)
    try:
        yield from _records(config, indices, rows, workers, chunk_size)
    except BaseException:
        io.remove_folders(created)
        raise


def _records(
    config: BatchConfig,
    indices: NDArray[np.int64],
    rows: NDArray[np.float64],
    workers: int | None,
    chunk_size: int | None,
) -> Iterator[SampleRecord]:
    workers = max(1, min(workers or os.cpu_count() or 1, len(indices) or 1))
    if workers == 1:
        worker = Worker(config)
        for index, row in zip(indices, rows, strict=True):
            yield worker.run(int(index), row)
        return
    size = chunk_size or max(1, min(64, len(indices) // (workers * 8) or 1))
    chunks = [(indices[i : i + size], rows[i : i + size]) for i in range(0, len(indices), size)]
    # fork shares the parent's imported modules, so a worker starts in milliseconds.
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    context = multiprocessing.get_context(method)
    with context.Pool(workers, initializer=_initialise, initargs=(config,)) as pool:
        for records in pool.imap_unordered(_run_chunk, chunks):
            yield from records

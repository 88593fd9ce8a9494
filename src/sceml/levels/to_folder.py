"""Sampling a logical scenario into a folder: the workflow `sceml sample` runs.

    document = load_logical(path)                      # LevelError unless it is logical
    problems = blocking_problems(document)             # errors that stop every sample
    planned = plan_sampling(document, SampleRequest(path, "lhs", 100, 0, out_dir))
    outcome = sample_to_folder(planned, progress=bar.update)   # files, then the manifest

Each step returns what the next needs and what a caller shows; nothing here prints. The
imports are those `sceml sample` needs anyway (no exporter, scipy or Jinja2 until a worker
or a distribution needs them), so that the command starts as fast as before.
"""

from __future__ import annotations

import time
from collections import Counter
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..diagnostics import Diagnostic, Severity
from ..errors import ArgumentError, SceMLError
from ..executors import open_executor
from ..model.documents import Document
from ..model.graph import level_text
from ..model.loading import load_scenario
from ..validation import validate
from ..xosc.profiles import DEFAULT_VERSION
from .batch import BatchConfig, BatchResult, Rows, run_batch
from .counts import SAMPLE_MEMORY_BYTES, check_count
from .manifest import SampleRecord, write_manifest
from .paths import LevelError
from .sampling import Plan, index_draw, plan_for, values_at
from .space import ParameterSpace, parameter_space

#: What each `--format` writes.
FORMATS = {"xmi": ("xmi",), "xosc": ("xosc",), "both": ("xosc", "xmi")}

# scipy's Latin hypercube holds about four float64 arrays of the design's shape at once.
_LHS_ROW_BYTES = 32


@dataclass(frozen=True)
class SampleRequest:
    """What to sample and where: the options of `sceml sample`.

    With `index`, only that sample of the run the other fields describe is written (same seed,
    and for lhs the same `n`), and no manifest.
    """

    logical: Path
    strategy: str
    n: int | None
    seed: int
    out_dir: Path
    file_format: str = "xosc"
    osc_version: str = DEFAULT_VERSION
    index: int | None = None
    allow: tuple[Path, ...] = ()


@dataclass
class PlannedSampling:
    """A run ready to go: its parameter space, plan and the samples to write."""

    request: SampleRequest
    space: ParameterSpace
    plan: Plan
    indices: NDArray[np.int64]
    #: The samples' values, or how to draw them (by the workers, or while they start).
    rows: Rows
    config: BatchConfig


@dataclass
class SamplingOutcome:
    """What a run wrote: a record per sample, and whether Ctrl-C cut it short."""

    result: BatchResult
    #: Seconds the samples took (without loading and planning).
    elapsed: float
    #: With `SampleRequest.index`: each varied parameter's value in that sample, by path.
    values: dict[str, float] = field(default_factory=dict)

    @property
    def records(self) -> list[SampleRecord]:
        return self.result.records

    @property
    def written(self) -> int:
        return sum(1 for r in self.records if r.status == "written")

    @property
    def skipped(self) -> Counter[str]:
        """How many samples were skipped, by reason (a rule their values break)."""
        return Counter(r.reason for r in self.records if r.status == "skipped")

    @property
    def failed(self) -> list[int]:
        """The samples lost with their worker, by index."""
        return sorted(r.index for r in self.records if r.status == "failed")

    @property
    def files(self) -> int:
        return sum(len(r.files) for r in self.records)


def load_logical(logical: Path, allow: tuple[Path, ...] = ()) -> Document:
    """The logical scenario to sample; LevelError when it is of another level."""
    with _blamed_on(logical):
        document = load_scenario(logical, allow=allow)
    level = level_text(document.root)
    if level != "logical":
        raise LevelError(f"only logical scenarios are sampled; this one is {level}", file=logical)
    return document


def blocking_problems(document: Document) -> list[Diagnostic]:
    """The errors that would spoil every sample, checked once here: samples only change
    numbers, so rules about structure, actors and modules need not run for each."""
    found = validate(document.root, document=document)
    return [d for d in found if d.severity >= Severity.ERROR]


def plan_sampling(document: Document, request: SampleRequest) -> PlannedSampling:
    """The run's plan, refused (SceMLError naming the file) when this machine cannot hold it."""
    logical = request.logical
    with _blamed_on(logical):
        space = parameter_space(document.root)
        plan = plan_for(space, request.strategy, request.n, request.seed)  # type: ignore[arg-type]
        if request.index is None:
            _check_size(plan.n, len(space.dimensions), request)
        elif request.strategy == "lhs":  # one sample of a Latin hypercube needs the whole design
            check_count(
                plan.n,
                "rows of the Latin hypercube",
                memory_each=_LHS_ROW_BYTES * max(1, len(space.dimensions)),
                hint="one sample of it is reproduced by drawing them all; ask for fewer with --n",
            )
        indices = np.arange(plan.n) if request.index is None else np.array([request.index])
        rows: Rows
        if request.index is not None:
            rows = values_at(space, plan, indices)  # refuses an index out of range, here
        else:
            # Each worker draws its own samples' values (grid, random), or, for a Latin
            # hypercube, the caller draws the design while the workers start.
            rows = index_draw(space, plan) or partial(values_at, space, plan, indices)
    config = BatchConfig(
        logical=logical,
        out_dir=request.out_dir,
        paths=space.paths,
        formats=FORMATS[request.file_format],
        osc_version=request.osc_version,
        stem=logical.stem.removesuffix("-logical"),
        allow=request.allow,
        width=max(5, len(str(max(plan.n - 1, 0)))),
    )
    return PlannedSampling(request, space, plan, indices, rows, config)


def sample_to_folder(
    planned: PlannedSampling,
    *,
    executor: str = "processes",
    scheduler: str | None = None,
    workers: int | None = None,
    progress: Callable[[int], None] | None = None,
) -> SamplingOutcome:
    """Write the planned samples on `executor` (`sceml.executors`), then, for a whole run, the
    manifest (also after Ctrl-C: it lists what was written). `progress` hears of each sample
    done."""
    request = planned.request
    started = time.perf_counter()
    with open_executor(executor, workers=workers, scheduler=scheduler) as runner:
        result = run_batch(
            planned.config, planned.indices, planned.rows, executor=runner, progress=progress
        )
    outcome = SamplingOutcome(result, time.perf_counter() - started)
    if request.index is None:
        run: dict[str, object] = {
            "logical": str(request.logical),
            "strategy": request.strategy,
            "n": planned.plan.n,
            "seed": request.seed,
            "format": request.file_format,
            "osc_version": request.osc_version,
        }
        if result.interrupted:
            run["interrupted"] = True
        write_manifest(request.out_dir, planned.space.paths, result.records, run)
    else:
        assert isinstance(planned.rows, np.ndarray)  # one sample's values are drawn when planning
        row = planned.rows[0]
        outcome.values = {
            path: float(value) for path, value in zip(planned.space.paths, row, strict=True)
        }
    return outcome


@contextmanager
def _blamed_on(file: Path) -> Iterator[None]:
    """Errors without a file name `file`: e.g. a grid too large is the logical file's doing.
    Errors in the request itself (ArgumentError) are not the file's."""
    try:
        yield
    except SceMLError as error:
        if not isinstance(error, ArgumentError):
            error.file = error.file or str(file)
        raise


def _check_size(count: int, dimensions: int, request: SampleRequest) -> None:
    """Refuse a run whose samples this machine cannot hold, before anything is allocated."""
    # A sample file is about the size of the logical file it comes from (an .xosc about twice).
    per_file = 2 * request.logical.stat().st_size
    hint = (
        "ask for fewer with --n"
        if request.n is not None
        else "the grid has that many points; cap it with --n"
    )
    check_count(
        count,
        "samples",
        memory_each=SAMPLE_MEMORY_BYTES + 8 * dimensions,
        disk_each=per_file * len(FORMATS[request.file_format]),
        folder=request.out_dir,
        hint=hint,
    )

"""`sceml sample LOGICAL --strategy grid|random|lhs ... -o DIR`: many concrete scenarios at once."""

from __future__ import annotations

import atexit
import gc
import sys
import time
from collections import Counter
from functools import partial
from pathlib import Path

import click
import numpy as np

import scemlmodel as scm

from ..diagnostics import Severity
from ..errors import ArgumentError, SceMLError
from ..executors import check, open_executor
from ..levels.batch import BatchConfig, BatchResult, Rows, run_batch
from ..levels.counts import SAMPLE_MEMORY_BYTES, check_count, parse_count
from ..levels.manifest import SampleRecord, write_manifest
from ..levels.paths import LevelError
from ..levels.sampling import STRATEGIES, plan_for, values_at
from ..levels.space import parameter_space
from ..model.documents import Document
from ..model.graph import level_text
from ..model.loading import load_scenario
from ..validation import validate
from ..xosc.schema import SUPPORTED_VERSIONS
from .common import (
    Parsed,
    SceMLCommand,
    allow_option,
    echo_diagnostics,
    executor_options,
    input_file,
    output_folder,
    seed_option,
)

_FORMATS = {"xmi": ("xmi",), "xosc": ("xosc",), "both": ("xosc", "xmi")}

# scipy's Latin hypercube holds about four float64 arrays of the design's shape at once.
_LHS_ROW_BYTES = 32

# A run leaves a large heap (scipy, imported to draw from normal distributions, and the model),
# which the interpreter's last garbage collections walked for 0.1-0.2 s after the manifest was
# written. Frozen at exit, it is not walked; the memory goes back with the process.
atexit.register(gc.freeze)


@click.command(cls=SceMLCommand)
@input_file("logical")
@click.option(
    "--strategy",
    type=click.Choice(STRATEGIES),
    default="grid",
    show_default=True,
    help="grid: full factorial over ranges with steps and discrete sets (other parameters at "
    "their nominal value); random: Monte Carlo; lhs: Latin hypercube.",
)
@click.option(
    "--n",
    "n",
    type=Parsed("N", parse_count),
    help="Number of samples (required for random and lhs; caps the grid): 1000, 1e6 or 2^20. "
    "A count that this machine's free memory or the output's disk cannot hold is refused.",
)
@seed_option
@output_folder("Folder for the sampled files and manifest.csv / manifest.json.")
@click.option(
    "--format",
    "file_format",
    type=click.Choice(sorted(_FORMATS)),
    default="xosc",
    show_default=True,
    help="Write each sample as OpenSCENARIO (.xosc, XSD-checked), as SceML (.xmi), or both.",
)
@click.option(
    "--osc-version",
    type=click.Choice(SUPPORTED_VERSIONS),
    default=SUPPORTED_VERSIONS[-1],
    show_default=True,
    help="OpenSCENARIO version of the .xosc files.",
)
@click.option(
    "--workers",
    type=click.IntRange(min=1),
    default=None,
    help="Worker processes of the processes executor, or of the dask executor's LocalCluster "
    "[default: the number of CPUs].",
)
@click.option(
    "--index",
    type=click.IntRange(min=0),
    default=None,
    help="Write only sample INDEX of the run given by the other options (same seed, and for "
    "lhs the same --n); its values are printed and no manifest is written.",
)
@executor_options
@allow_option
def sample(
    logical: Path,
    strategy: str,
    n: int | None,
    seed: int,
    out_dir: Path,
    file_format: str,
    osc_version: str,
    workers: int | None,
    index: int | None,
    executor: str,
    scheduler: str | None,
    allow: tuple[Path, ...],
) -> None:
    """Sample the logical scenario LOGICAL into concrete scenarios in DIR.

    Every sample is reproducible from (seed, index) alone. Samples whose values break a rule
    (e.g. a negative speed drawn from a wide distribution) are skipped and counted. A manifest
    lists each sample's index, status, files and the value of every varied parameter.
    The files are the same whichever executor runs the samples.
    """
    check(executor, scheduler)
    try:
        document = load_scenario(logical, allow=allow)
        scenario = document.root
        _require_logical(scenario, logical)
        _require_valid(document, logical)
        space = parameter_space(scenario)
        if index is not None and strategy == "lhs" and n is None:
            raise click.UsageError("--index with --strategy lhs needs the --n of the run")
        plan = plan_for(space, strategy, n, seed)  # type: ignore[arg-type]
        if index is None:
            _check_size(plan.n, len(space.dimensions), _FORMATS[file_format], logical, out_dir, n)
        elif strategy == "lhs":  # one sample of a Latin hypercube needs the whole design drawn
            check_count(
                plan.n,
                "rows of the Latin hypercube",
                memory_each=_LHS_ROW_BYTES * max(1, len(space.dimensions)),
                hint="one sample of it is reproduced by drawing them all; ask for fewer with --n",
            )
        indices = np.arange(plan.n) if index is None else np.array([index])
        # A whole run's values are drawn while the workers start: drawing takes a while (scipy,
        # for a normal distribution, takes half a second to import), and so does their setup.
        rows: Rows = partial(values_at, space, plan, indices)
        if index is not None:
            rows = one = values_at(space, plan, indices)  # refuses an index out of range, here
    except SceMLError as error:
        if not isinstance(error, ArgumentError):  # e.g. a grid too large: the file is the cause
            error.file = error.file or str(logical)
        raise
    config = BatchConfig(
        logical=logical,
        out_dir=out_dir,
        paths=space.paths,
        formats=_FORMATS[file_format],
        osc_version=osc_version,
        stem=logical.stem.removesuffix("-logical"),
        allow=allow,
        width=max(5, len(str(max(plan.n - 1, 0)))),
    )
    started = time.perf_counter()
    result = _run(config, indices, rows, executor, scheduler, workers)
    records = result.records
    elapsed = time.perf_counter() - started
    if index is None:
        run = {
            "logical": str(logical),
            "strategy": strategy,
            "n": plan.n,
            "seed": seed,
            "format": file_format,
            "osc_version": osc_version,
        }
        if result.interrupted:
            run["interrupted"] = True
        write_manifest(out_dir, space.paths, records, run)
    else:
        for path, value in zip(space.paths, one[0], strict=True):
            click.echo(f"{path} = {float(value)!r}")
    click.echo(_summary(records, elapsed))
    _exit_status(result, len(indices))


def _check_size(
    count: int,
    dimensions: int,
    formats: tuple[str, ...],
    logical: Path,
    out_dir: Path,
    n: int | None,
) -> None:
    """Refuse a run whose samples this machine cannot hold, before anything is allocated."""
    # A sample file is about the size of the logical file it comes from (an .xosc about twice).
    per_file = 2 * logical.stat().st_size
    hint = (
        "ask for fewer with --n"
        if n is not None
        else "the grid has that many points; cap it with --n"
    )
    check_count(
        count,
        "samples",
        memory_each=SAMPLE_MEMORY_BYTES + 8 * dimensions,
        disk_each=per_file * len(formats),
        folder=out_dir,
        hint=hint,
    )


def _exit_status(result: BatchResult, planned: int) -> None:
    records = result.records
    if result.interrupted:
        click.echo(
            f"Interrupted: {len(records)} of {planned} samples done; the manifest lists what "
            "was written.",
            err=True,
        )
        raise click.exceptions.Exit(130)
    failed = sorted(r.index for r in records if r.status == "failed")
    if failed:
        click.echo(f"Error: samples lost with their worker: {_ranges(failed)}", err=True)
        raise click.exceptions.Exit(1)
    if records and all(r.status != "written" for r in records):
        raise click.exceptions.Exit(1)


def _ranges(indices: list[int]) -> str:
    """`3-5, 9` for [3, 4, 5, 9]."""
    spans: list[list[int]] = []
    for i in indices:
        if spans and spans[-1][1] == i - 1:
            spans[-1][1] = i
        else:
            spans.append([i, i])
    return ", ".join(f"{a}-{b}" if a != b else f"{a}" for a, b in spans)


def _require_logical(scenario: scm.Scenario, file: Path) -> None:
    level = level_text(scenario)
    if level != "logical":
        raise LevelError(f"only logical scenarios are sampled; this one is {level}", file=file)


def _require_valid(document: Document, file: Path) -> None:
    # Samples only change numbers: rules about structure, actors and modules are checked once here.
    found = validate(document.root, document=document)
    errors = [d for d in found if d.severity >= Severity.ERROR]
    echo_diagnostics(errors, document, file)
    if errors:
        raise click.exceptions.Exit(1)


def _run(
    config: BatchConfig,
    indices: np.ndarray,
    rows: Rows,
    executor: str,
    scheduler: str | None,
    workers: int | None,
) -> BatchResult:
    # The bar is for a person at a terminal; logs and pipes would only get a stray label.
    hidden = not sys.stderr.isatty()
    with (
        open_executor(executor, workers=workers, scheduler=scheduler) as runner,
        click.progressbar(
            length=len(indices), label="sampling", file=sys.stderr, hidden=hidden
        ) as bar,
    ):
        return run_batch(config, indices, rows, executor=runner, progress=bar.update)


def _summary(records: list[SampleRecord], elapsed: float) -> str:
    written = sum(1 for r in records if r.status == "written")
    failed = sum(1 for r in records if r.status == "failed")
    reasons = Counter(r.reason for r in records if r.status == "skipped")
    skipped = sum(reasons.values())
    why = (
        f" ({'; '.join(f'{reason}: {count}' for reason, count in reasons.most_common())})"
        if reasons
        else ""
    )
    files = sum(len(r.files) for r in records)
    rate = files / elapsed if elapsed > 0 else 0.0
    lost = f", {failed} failed" if failed else ""
    return f"{written} written, {skipped} skipped{why}{lost}, {elapsed:.2f} s, {rate:.0f} files/s"

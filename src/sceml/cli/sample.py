"""`sceml sample LOGICAL --strategy grid|random|lhs ... -o DIR`: many concrete scenarios at once."""

from __future__ import annotations

import atexit
import gc
import sys
from pathlib import Path

import click

from ..executors import check
from ..levels.counts import parse_count
from ..levels.sampling import STRATEGIES
from ..levels.to_folder import (
    FORMATS,
    SampleRequest,
    SamplingOutcome,
    blocking_problems,
    load_logical,
    plan_sampling,
    sample_to_folder,
)
from .common import (
    Parsed,
    SceMLCommand,
    allow_option,
    echo_diagnostics,
    executor_options,
    input_file,
    output_folder,
    seed_option,
    workers_option,
    written_version_option,
)

# A run leaves a large heap (numpy, the exporter, the model), which the interpreter's last
# garbage collections walked for 0.1-0.2 s after the manifest was written, when the process
# ends the ordinary way (`sceml.cli.end_now` skips that unless a thread or child is still
# running). Frozen at exit, it is not walked; the memory goes back with the process.
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
    type=click.Choice(sorted(FORMATS)),
    default="xosc",
    show_default=True,
    help="Write each sample as OpenSCENARIO (.xosc, XSD-checked), as SceML (.xmi), or both.",
)
@written_version_option("OpenSCENARIO version of the .xosc files.")
@workers_option
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
    document = load_logical(logical, allow)
    errors = blocking_problems(document)
    echo_diagnostics(errors, document, logical)
    if errors:
        raise click.exceptions.Exit(1)
    if index is not None and strategy == "lhs" and n is None:
        raise click.UsageError("--index with --strategy lhs needs the --n of the run")
    request = SampleRequest(
        logical, strategy, n, seed, out_dir, file_format, osc_version, index, allow
    )
    planned = plan_sampling(document, request)
    # The bar is for a person at a terminal; logs and pipes would only get a stray label.
    hidden = not sys.stderr.isatty()
    with click.progressbar(
        length=len(planned.indices), label="sampling", file=sys.stderr, hidden=hidden
    ) as bar:
        outcome = sample_to_folder(
            planned, executor=executor, scheduler=scheduler, workers=workers, progress=bar.update
        )
    for path, value in outcome.values.items():
        click.echo(f"{path} = {value!r}")
    click.echo(_summary(outcome))
    _exit_status(outcome, len(planned.indices))


def _exit_status(outcome: SamplingOutcome, planned: int) -> None:
    records = outcome.records
    if outcome.result.interrupted:
        click.echo(
            f"Interrupted: {len(records)} of {planned} samples done; the manifest lists what "
            "was written.",
            err=True,
        )
        raise click.exceptions.Exit(130)
    failed = outcome.failed
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


def _summary(outcome: SamplingOutcome) -> str:
    reasons = outcome.skipped
    why = (
        f" ({'; '.join(f'{reason}: {count}' for reason, count in reasons.most_common())})"
        if reasons
        else ""
    )
    elapsed = outcome.elapsed
    rate = outcome.files / elapsed if elapsed > 0 else 0.0
    lost = f", {len(outcome.failed)} failed" if outcome.failed else ""
    return (
        f"{outcome.written} written, {sum(reasons.values())} skipped{why}{lost}, "
        f"{elapsed:.2f} s, {rate:.0f} files/s"
    )
